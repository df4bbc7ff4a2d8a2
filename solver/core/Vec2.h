// Two-component vectors for positions, velocities and forces.
#pragma once

#include "solver/core/Real.h"

#include <Eigen/Core>

namespace lbdem::solver {

/// A 2D vector in solver precision (x to the right / downslope, y up).
using Vec2 = Eigen::Matrix<Real, 2, 1>;

} // namespace lbdem::solver
