// A memory-bandwidth probe for the roofline of `lbdem bench`.
#pragma once

#include <cstddef>

namespace lbdem::solver::lattice {

/// Best-of-`passes` bandwidth [GB/s] of an in-place read-modify-write a[i] = s a[i] + b[i]
/// over two arrays of `bytesPerArray` each (far larger than cache), counting 3 transfers per
/// element (read a, read b, write a), i.e. the same no-write-allocate traffic pattern as an
/// in-place lattice update. Uses the current OpenMP thread count.
double measureBandwidthGBs(std::size_t bytesPerArray = 256u << 20, int passes = 5);

} // namespace lbdem::solver::lattice
