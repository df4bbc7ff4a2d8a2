// summary.json of a run: what the run is, how far it got and its headline numbers.
#pragma once

#include "solver/scene/Simulation.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace lbdem::io {

/// The summary of simulation as it stands: case, scene, plan, steps, t/tau_c, wall time and
/// MLUPS over every process of the run, the last output's metrics ("final"), the column's
/// headline numbers (runout_final, packing_final, ke_peak, t_ke_peak_over_tc), seconds per stage
/// and, when stopReason is not empty, the stability guard's diagnosis.
nlohmann::json runSummary(const solver::Simulation& simulation, bool finished,
                          const std::string& stopReason = {});

/// Write runSummary() as DIR/summary.json (atomically, indented by two).
void writeRunSummary(const std::filesystem::path& dir, const solver::Simulation& simulation,
                     bool finished, const std::string& stopReason = {});

/// The numbers a run's summary.json holds beside the scene's metrics: those runSummary() puts
/// at its top level, and t_s and step, which the run adds to each output's metrics ("final").
std::vector<std::string> runSummaryNumbers(const solver::CaseSpec& spec);

} // namespace lbdem::io
