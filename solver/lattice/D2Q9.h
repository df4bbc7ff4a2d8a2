// The D2Q9 velocity set in the order of docs/design.md §5: rest, E, N, W, S, NE, NW, SW, SE.
#pragma once

namespace lbdem::solver::lattice {

constexpr int kQ = 9;
/// x components of the lattice velocities c_i.
constexpr int kCx[kQ] = {0, 1, 0, -1, 0, 1, -1, -1, 1};
/// y components of the lattice velocities c_i.
constexpr int kCy[kQ] = {0, 0, 1, 0, -1, 1, 1, -1, -1};
/// Index of -c_i.
constexpr int kOpposite[kQ] = {0, 3, 4, 1, 2, 7, 8, 5, 6};
/// Lattice weights w_i (4/9, 1/9, 1/36).
constexpr double kW[kQ] = {4.0 / 9,  1.0 / 9,  1.0 / 9,  1.0 / 9, 1.0 / 9,
                           1.0 / 36, 1.0 / 36, 1.0 / 36, 1.0 / 36};
/// Squared lattice speed of sound c_s^2 = 1/3.
constexpr double kCs2 = 1.0 / 3.0;
/// Lattice speed of sound c_s = 1/sqrt(3), the root of kCs2.
constexpr double kCs = 0.57735026918962576;

/// Lattices smaller than this run their loops on one thread: a parallel region and its
/// barrier cost microseconds, and on a shared, oversubscribed machine a descheduled thread
/// stalls every step (measured: a 130^2 cavity ran 30x slower on 2 threads than on 1).
constexpr long long kParallelMinCells = 65536;

/// Equilibrium f_i^eq = w_i rho (1 + 3 c.u + 4.5 (c.u)^2 - 1.5 u^2) (second-order Maxwellian).
inline double equilibrium(int i, double rho, double ux, double uy) {
    const double cu = kCx[i] * ux + kCy[i] * uy;
    return kW[i] * rho * (1.0 + 3.0 * cu + 4.5 * cu * cu - 1.5 * (ux * ux + uy * uy));
}

} // namespace lbdem::solver::lattice
