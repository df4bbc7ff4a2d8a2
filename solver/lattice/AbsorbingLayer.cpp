// The sponge layer: which nodes it covers, their strength, and the relaxation pass.
#include "solver/lattice/AbsorbingLayer.h"

#include "solver/core/InputError.h"
#include "solver/lattice/Lattice.h"

#include <algorithm>
#include <string>

namespace lbdem::solver::lattice {

AbsorbingLayer::AbsorbingLayer(const Lattice& lattice, const AbsorbingLayerSetup& setup)
    : m_rho(setup.rho) {
    if (setup.nodes < 0)
        throw InputError("the absorbing layer needs a thickness of 0 or more nodes, not " +
                         std::to_string(setup.nodes));
    if (setup.strength < 0 || setup.strength > 1)
        throw InputError("the absorbing layer's strength must lie in [0, 1], not " +
                         std::to_string(setup.strength));
    if (setup.nodes == 0 || setup.strength == 0) return;
    const LatticeSetup& s = lattice.setup();
    const bool open[4] = {s.left.type == SideType::Pressure, s.right.type == SideType::Pressure,
                          s.bottom.type == SideType::Pressure, s.top.type == SideType::Pressure};
    const int x0 = lattice.firstFluidX(), y0 = lattice.firstFluidY();
    const Real n = setup.nodes;
    for (int j = y0; j < y0 + s.ny; ++j)
        for (int i = x0; i < x0 + s.nx; ++i) {
            const long long cell = lattice.index(i, j);
            if (!lattice.isFluid(cell)) continue;
            // Distance from each side in nodes: half a node for the outermost row.
            const Real distance[4] = {i - x0 + 0.5, x0 + s.nx - 1 - i + 0.5, j - y0 + 0.5,
                                      y0 + s.ny - 1 - j + 0.5};
            Real sigma = 0;
            for (int side = 0; side < 4; ++side)
                if (open[side] && distance[side] < n) {
                    const Real depth = (n - distance[side]) / n;
                    sigma = std::max(sigma, setup.strength * depth * depth);
                }
            if (sigma <= 0) continue;
            m_cells.push_back(cell);
            m_sigma.push_back(sigma);
        }
}

void AbsorbingLayer::apply(Lattice& lattice) const {
    Real rest[kQ];
    for (int q = 0; q < kQ; ++q)
        rest[q] = equilibrium(q, m_rho, 0, 0);
    const long long count = static_cast<long long>(m_cells.size());
    // Each node changes only its own populations: any order and thread count give the same result.
#pragma omp parallel for schedule(static) if (count * 16 >= kParallelMinCells)
    for (long long k = 0; k < count; ++k) {
        long long slots[kQ];
        lattice.postSlots(m_cells[k], slots);
        Real f[kQ], rho = 0, jx = 0, jy = 0;
        for (int q = 0; q < kQ; ++q) {
            f[q] = lattice.population(slots[q], q);
            rho += f[q];
            jx += kCx[q] * f[q];
            jy += kCy[q] * f[q];
        }
        const Real ux = jx / rho, uy = jy / rho, sigma = m_sigma[k];
        for (int q = 0; q < kQ; ++q)
            lattice.setPopulation(slots[q], q,
                                  f[q] - sigma * (equilibrium(q, rho, ux, uy) - rest[q]));
    }
}

} // namespace lbdem::solver::lattice
