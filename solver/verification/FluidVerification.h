// Verification cases of the lattice-Boltzmann fluid solver.
#pragma once

#include "solver/scene/CaseSpec.h"
#include "solver/verification/Verification.h"

#include <string>
#include <vector>

namespace lbdem::solver {

/// The case of sample_cases/verification/<file>.toml for scene `scene` (poiseuille,
/// taylor_green, cavity or cylinder), with the resolution and collision model replaced.
CaseSpec fluidCase(SceneKind scene, int nodes, lattice::CollisionModel collision);

} // namespace lbdem::solver
