// The sponge layer: which nodes it covers, their strength, and the relaxation pass.
#include "solver/lattice/AbsorbingLayer.h"

#include "solver/core/FlushSubnormals.h"
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
            const bool interior = i >= 1 && i < lattice.nx() - 1 && j >= 1 && j < lattice.ny() - 1;
            // A new run where the row's cells stop being consecutive, at the lattice's edge, or
            // at kMaxRun cells (runs are the threads' units of work).
            if (m_runs.empty() || m_runs.back().interior != interior ||
                m_runs.back().firstCell + m_runs.back().count != cell ||
                m_runs.back().count == kMaxRun)
                m_runs.push_back({cell, m_cells.size(), 0, interior});
            ++m_runs.back().count;
            m_cells.push_back(cell);
            m_sigma.push_back(sigma);
        }
}

namespace {

/// Relax the node whose population f_i is stored at slot[i][c] (S: PopulationStorage) by sigma
/// toward rest: f_i -= sigma (f_i^eq(rho, u) - rest_i). A function of its own so that the
/// populations stay in registers when its caller's loop is vectorised (an array declared in the
/// loop's body would become a per-lane array there).
template <class S>
LBDEM_KERNEL_INLINE void relaxStoredNode(S* const slot[kQ], int c, Real sigma,
                                         const Real rest[kQ]) {
    Real f[kQ], rho = 0, jx = 0, jy = 0;
    for (int q = 0; q < kQ; ++q)
        f[q] = StoredPopulation<S>::load(slot[q][c], kW[q]);
    for (int q = 0; q < kQ; ++q) {
        rho += f[q];
        jx += kCx[q] * f[q];
        jy += kCy[q] * f[q];
    }
    const Real ux = jx / rho, uy = jy / rho;
    for (int q = 0; q < kQ; ++q)
        slot[q][c] = StoredPopulation<S>::store(
            f[q] - sigma * (equilibrium(q, rho, ux, uy) - rest[q]), kW[q]);
}

} // namespace

template <class S> void AbsorbingLayer::relaxStored(Lattice& lattice, S* stored) const {
    Real rest[kQ];
    long long offset[kQ];
    for (int q = 0; q < kQ; ++q) {
        rest[q] = equilibrium(q, m_rho, 0, 0);
        offset[q] = lattice.postSlotOffset(q);
    }
    const long long runs = static_cast<long long>(m_runs.size());
    // Each node changes only its own populations: any order and thread count give the same
    // result, so the runs (a few long ones along the top, many short ones along the right side)
    // are dealt out as the threads come free.
#pragma omp parallel if (m_cells.size() * 16 >= kParallelMinCells)
    {
        const ScopedFlushSubnormals flush(StoredPopulation<S>::kFlushSubnormals);
#pragma omp for schedule(dynamic, 4)
        for (long long r = 0; r < runs; ++r) {
            const Run& run = m_runs[r];
            const Real* sigma = m_sigma.data() + run.firstIndex;
            if (run.interior) {
                // Consecutive cells whose neighbours need no wrapping: each direction's slots are
                // consecutive too, at the parity's fixed offset.
                S* slot[kQ];
                for (int q = 0; q < kQ; ++q)
                    slot[q] = stored + run.firstCell + offset[q];
#pragma omp simd
                for (int c = 0; c < run.count; ++c)
                    relaxStoredNode(slot, c, sigma[c], rest);
                continue;
            }
            for (int c = 0; c < run.count; ++c) {
                long long slots[kQ];
                lattice.postSlots(run.firstCell + c, slots);
                S* slot[kQ];
                for (int q = 0; q < kQ; ++q)
                    slot[q] = stored + slots[q];
                relaxStoredNode(slot, 0, sigma[c], rest);
            }
        }
    }
}

void AbsorbingLayer::apply(Lattice& lattice) const {
    if (m_cells.empty()) return;
    if (lattice.storage() == PopulationStorage::Float)
        relaxStored(lattice, lattice.storedFloats());
    else
        relaxStored(lattice, lattice.storedDoubles());
}

} // namespace lbdem::solver::lattice
