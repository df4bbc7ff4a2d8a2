// The plan as JSON (plan.json, `lbdem info --json`) and as a human-readable table.
#pragma once

#include "solver/scene/Plan.h"

#include <nlohmann/json.hpp>
#include <string>

namespace lbdem::io {

/// The plan with the stable keys nx, ny, h_m, dt_s, tau, mach, dem_dt_s, substeps, grains,
/// memory_bytes, steps and the rest of its fields.
nlohmann::json planToJson(const solver::Plan& plan);

/// The plan as aligned "name  value  unit" lines followed by its warnings.
std::string formatPlan(const solver::Plan& plan);

} // namespace lbdem::io
