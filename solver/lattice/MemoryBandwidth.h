// A memory-bandwidth probe for the roofline of `lbdem bench`.
#pragma once

#include <cstddef>
#include <vector>

namespace lbdem::solver::lattice {

/// Bandwidth [GB/s] of each of `passes` passes of the in-place read-modify-write a[i] = s a[i] + c
/// over an array of `bytes` (far larger than cache), counting 2 transfers per element (read a,
/// write a): the traffic pattern of the in-place (AA) lattice update, which reads each
/// population and writes it back to the same line. Uses the current OpenMP thread count.
std::vector<double> measureBandwidthPassesGBs(std::size_t bytes = 512u << 20, int passes = 5);

} // namespace lbdem::solver::lattice
