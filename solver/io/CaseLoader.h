// Reading case files and command-line overrides into a validated CaseSpec.
#pragma once

#include "solver/scene/CaseSpec.h"

#include <string>
#include <vector>

namespace lbdem::io {

/// Parse the TOML case at path, apply "section.key=value" overrides, validate; throws InputError.
solver::CaseSpec loadCase(const std::string& path, const std::vector<std::string>& overrides = {});

/// Parse TOML text (source names it in messages) with overrides; throws InputError.
solver::CaseSpec parseCase(const std::string& text, const std::string& source,
                           const std::vector<std::string>& overrides = {});

/// Apply one "section.key=value" override to spec; throws InputError naming the override.
void applyOverride(solver::CaseSpec& spec, const std::string& assignment);

} // namespace lbdem::io
