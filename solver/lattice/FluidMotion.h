#pragma once
// How the fluid moves over a region: its rms speed, and how much of it is sound.
#include "solver/lattice/Lattice.h"

#include <vector>

namespace lbdem::solver::lattice {

/// Root-mean-square motion of the fluid over a set of nodes, in lattice units.
struct MotionRms {
    double speed = 0;    ///< rms |u|
    double acoustic = 0; ///< rms c_s |rho - 1|: the speed a plane sound wave of that density
                         ///< excess carries (near `speed` where the motion is sound, near 0 where
                         ///< it is incompressible flow, whose density excess is O(Mach^2))
};

/// rms speed and rms acoustic speed over `cells` (fluid nodes, summed in the given order;
/// none gives zeros).
MotionRms motionRms(const Lattice& lattice, const std::vector<long long>& cells);

} // namespace lbdem::solver::lattice
