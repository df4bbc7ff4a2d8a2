// Shared case options.
#include "app/cli/CaseOptions.h"

#include "solver/io/CaseLoader.h"

#include <CLI/CLI.hpp>

namespace lbdem::cli {

void CaseOptions::addTo(CLI::App& command, bool caseRequired) {
    auto* option = command.add_option("case", path, "Case file (TOML)");
    if (caseRequired) option->required();
    command.add_option("--set", overrides, "Override a case key: section.key=value (repeatable)")
        ->take_all()
        ->allow_extra_args(false);
}

solver::CaseSpec CaseOptions::load() const {
    if (path.empty()) {
        solver::CaseSpec spec = solver::defaultCase();
        for (const auto& assignment : overrides)
            io::applyOverride(spec, assignment);
        return spec;
    }
    return io::loadCase(path, overrides);
}

} // namespace lbdem::cli
