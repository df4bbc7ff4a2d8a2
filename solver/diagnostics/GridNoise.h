// The grid-scale share of a lattice's vorticity: how much of the flow is node-to-node noise.
#pragma once

#include <cstdint>

namespace lbdem::solver {

/// A velocity field on nx x ny nodes (x fastest, lattice units) and which nodes are solid.
struct GridNoiseField {
    int nx = 0, ny = 0;
    const double* ux = nullptr;
    const double* uy = nullptr;
    const std::uint8_t* solid = nullptr; ///< non-zero: a solid node (grain, obstacle, wall)
    bool periodic_x = false;             ///< wrap across x; otherwise beyond the edge is solid
    bool periodic_y = false;
};

/// Result of gridNoise().
struct GridNoise {
    double share = 0;    ///< rms(omega - its 3 x 3 box mean) / rms(omega); NaN without nodes
    long long nodes = 0; ///< fluid nodes at least kGridNoiseSolidDistance from any solid node
};

/// Nodes measured lie at least this many nodes (Euclidean, equivalently no solid node in the 5 x 5
/// block around them) from every solid node: then the 3 x 3 box mean of the central-difference
/// vorticity reads fluid velocities only.
inline constexpr int kGridNoiseSolidDistance = 3;

/// The grid-scale share of vorticity: omega = (uy[i+1] - uy[i-1]) / 2 - (ux[j+1] - ux[j-1]) / 2,
/// box = mean of omega over the 3 x 3 nodes around, share = sqrt(sum (omega - box)^2 /
/// sum omega^2) over the nodes kGridNoiseSolidDistance or more from any solid node. 0 for a field
/// without vorticity, (2/3)(1 - cos k) for one smooth Fourier mode of wavenumber k along an axis,
/// sqrt(69/81) = 0.923 for independent random velocities. Row sums are added in row order, so the
/// result does not depend on the thread count.
GridNoise gridNoise(const GridNoiseField& field);

} // namespace lbdem::solver
