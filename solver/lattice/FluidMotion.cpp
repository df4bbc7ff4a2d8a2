#include "solver/lattice/FluidMotion.h"

#include "solver/lattice/D2Q9.h"

#include <cmath>

namespace lbdem::solver::lattice {

MotionRms motionRms(const Lattice& lattice, const std::vector<long long>& cells) {
    if (cells.empty()) return {};
    double speedSquares = 0, densitySquares = 0;
    for (const long long cell : cells) {
        Real ux, uy;
        lattice.velocity(cell, ux, uy);
        const double densityExcess = lattice.density(cell) - 1.0;
        speedSquares += ux * ux + uy * uy;
        densitySquares += densityExcess * densityExcess;
    }
    const auto n = static_cast<double>(cells.size());
    return {std::sqrt(speedSquares / n), std::sqrt(kCs2 * densitySquares / n)};
}

} // namespace lbdem::solver::lattice
