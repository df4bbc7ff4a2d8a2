// Factory of the runner for pure-fluid verification flows.
#pragma once

#include "solver/scene/SceneRunner.h"

namespace lbdem::solver {

/// The runner of a poiseuille, taylor_green, cavity or cylinder case.
std::unique_ptr<SceneRunner> makeFlowSceneRunner(const CaseSpec& spec, const Plan& plan);

} // namespace lbdem::solver
