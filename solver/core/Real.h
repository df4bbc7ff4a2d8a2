// The floating-point type of all solver state; change it here alone.
#pragma once

namespace lbdem::solver {

/// Precision of solver state and arithmetic (docs/design.md §5: double; float storage is a kernel
/// option).
using Real = double;

} // namespace lbdem::solver
