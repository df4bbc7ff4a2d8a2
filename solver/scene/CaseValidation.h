// Checks that involve more than one key, after every key is within its own range.
#pragma once

#include "solver/scene/CaseSpec.h"

#include <string>
#include <vector>

namespace lbdem::solver {

/// A rule broken by a case: the key to blame and the reason as a sentence fragment.
struct CaseProblem {
    std::string path;
    std::string message;
};

/// Every cross-key problem of spec; empty when the case is consistent.
std::vector<CaseProblem> validateCase(const CaseSpec& spec);

} // namespace lbdem::solver
