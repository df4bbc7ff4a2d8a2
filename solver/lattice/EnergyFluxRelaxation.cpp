// Energy-flux moments of chosen nodes relaxed at their own rate (EnergyFluxRelaxation.h).
#include "solver/lattice/EnergyFluxRelaxation.h"

#include "solver/lattice/D2Q9.h"

#include <stdexcept>

namespace lbdem::solver::lattice {

Real energyFluxFactor(Real bulk, Real local) {
    if (bulk == 1) throw std::invalid_argument("energyFluxFactor: a bulk s_q of 1 leaves no q");
    return (1 - local) / (1 - bulk);
}

void rescaleEnergyFlux(Lattice& lat, const std::vector<long long>& cells, Real factor) {
    const auto count = static_cast<long long>(cells.size());
#pragma omp parallel for schedule(static) if (count > 4096)
    for (long long k = 0; k < count; ++k) {
        long long slots[kQ];
        lat.postSlots(cells[static_cast<std::size_t>(k)], slots);
        Real f[kQ];
        for (int q = 0; q < kQ; ++q)
            f[q] = lat.population(slots[q], q);
        // q_x = sum c_x (3 c^2 - 5) f, its equilibrium -j_x (Lallemand & Luo 2000); M^-1's row
        // of q_x is (0, -2, 0, 2, 0, 1, -1, -1, 1) / 12, of q_y (0, 0, -2, 0, 2, 1, 1, -1, -1)
        // / 12.
        const Real jx = f[1] - f[3] + f[5] - f[6] - f[7] + f[8];
        const Real jy = f[2] - f[4] + f[5] + f[6] - f[7] - f[8];
        const Real qx = -2 * (f[1] - f[3]) + f[5] - f[6] - f[7] + f[8];
        const Real qy = -2 * (f[2] - f[4]) + f[5] + f[6] - f[7] - f[8];
        const Real dx = (factor - 1) * (qx + jx) / 12, dy = (factor - 1) * (qy + jy) / 12;
        f[1] -= 2 * dx;
        f[3] += 2 * dx;
        f[2] -= 2 * dy;
        f[4] += 2 * dy;
        f[5] += dx + dy;
        f[6] += -dx + dy;
        f[7] += -dx - dy;
        f[8] += dx - dy;
        for (int q = 1; q < kQ; ++q)
            lat.setPopulation(slots[q], q, f[q]);
    }
}

} // namespace lbdem::solver::lattice
