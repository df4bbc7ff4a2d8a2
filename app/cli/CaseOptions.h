// Options shared by every command that reads a case: the path and `--set` overrides.
#pragma once

#include "solver/scene/CaseSpec.h"

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace lbdem::cli {

/// The case path and overrides given on the command line.
struct CaseOptions {
    std::string path;
    std::vector<std::string> overrides;

    /// Add the CASE positional and the repeatable --set option to command.
    void addTo(CLI::App& command, bool caseRequired = true);
    /// Load and validate the case (defaults when no path was given); throws InputError.
    solver::CaseSpec load() const;
};

} // namespace lbdem::cli
