// Factory of the runner of the paper's column collapse, dry or submerged.
#pragma once

#include "solver/scene/SceneRunner.h"

namespace lbdem::solver {

/// The runner of a column_collapse case: grains always, lattice and coupling only when submerged.
std::unique_ptr<SceneRunner> makeColumnCollapseRunner(const CaseSpec& spec, const Plan& plan);

} // namespace lbdem::solver
