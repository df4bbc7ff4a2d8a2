// The bounce-back coupling's set-up, load hand-over and restart state.
#include "solver/coupling/BounceBackCoupling.h"

#include "solver/core/InputError.h"

#include <algorithm>

namespace lbdem::solver::coupling {

BounceBackCoupling::BounceBackCoupling(lattice::Lattice& lattice, dem::DemSystem& dem,
                                       const CouplingParams& params)
    : Coupling(lattice, dem, params) {
    m_owner.assign(static_cast<std::size_t>(lattice.cells()), -1);
    m_box.assign(m_dem.particles().size(), Box{});
}

void BounceBackCoupling::collectForces() {
    // The DEM gets the mean of the last two steps' loads. A fluid node between a grain and a wall
    // (or another grain), bounced back on both sides, keeps a period-two mode: its momentum
    // across the gap flips sign every step and nothing damps it as tau -> 1/2 (the collision
    // conserves momentum). The link force follows that momentum and the grain's velocity feeds
    // it back through the moving-wall term: per link, with grain mass M in lattice units, the gap
    // momentum j and grain velocity V obey j' = -j + (2/3) V, V' = V + (j - (2/3) V) / M, whose
    // eigenvalue -1/(3M) - sqrt(1 + 1/(9M^2)) lies outside the unit circle. This grew into a
    // Mach ~1 blow-up beside a grain resting in the floor-wall corner at tau = 0.506. The
    // two-step mean cancels the period-two part of the force and leaves slowly varying loads
    // unchanged.
    const bool average = m_previousLoad.size() == 3 * m_loadX.size();
    handOverLoads(average ? &m_previousLoad : nullptr);
    m_previousLoad.resize(3 * m_loadX.size());
    for (std::size_t i = 0; i < m_loadX.size(); ++i) {
        m_previousLoad[3 * i] = m_loadX[i];
        m_previousLoad[3 * i + 1] = m_loadY[i];
        m_previousLoad[3 * i + 2] = m_loadT[i];
    }
}

CouplingState BounceBackCoupling::state() const {
    // Covered nodes grain by grain, each grain's row by row: the order mapGrains finds them in.
    CouplingState state;
    state.initialised = m_initialised;
    state.previous_loads = m_previousLoad;
    for (std::size_t p = 0; p < m_box.size(); ++p) {
        const Box& box = m_box[p];
        for (int ju = box.j0; ju <= box.j1; ++ju)
            for (int iu = box.i0; iu <= box.i1; ++iu) {
                int i = iu, j = ju;
                if (!wrapNode(i, j)) continue;
                const long long c = m_lattice.index(i, j);
                if (m_owner[c] != static_cast<std::int32_t>(p)) continue;
                state.cells.push_back(c);
                state.grains.push_back(static_cast<std::int32_t>(p));
            }
    }
    return state;
}

void BounceBackCoupling::restore(const CouplingState& state) {
    if (state.cells.size() != state.grains.size())
        throw InputError("coupling state: cell and grain lists differ in length");
    const std::size_t n = m_dem.particles().size();
    if (!state.previous_loads.empty() && state.previous_loads.size() != 3 * n)
        throw InputError("coupling state: the previous loads do not match the grain count");
    resizeGrains();
    m_previousLoad = state.previous_loads;
    std::fill(m_owner.begin(), m_owner.end(), -1);
    std::fill(m_solid.begin(), m_solid.end(), 0.0);
    m_box.assign(n, Box{});
    forgetAnchors();
    m_initialised = state.initialised;
    const int nx = m_lattice.nx();
    for (std::size_t k = 0; k < state.cells.size(); ++k) {
        const long long c = state.cells[k];
        const std::int32_t p = state.grains[k];
        if (c < 0 || c >= m_lattice.cells() || p < 0 || static_cast<std::size_t>(p) >= n)
            throw InputError("coupling state does not match the lattice or the grains");
        m_owner[c] = p;
        m_solid[c] = 1;
        // The box that holds the grain's nodes, in wrapped indices: the next mapGrains scans it
        // for the nodes the grain leaves.
        const int i = static_cast<int>(c % nx), j = static_cast<int>(c / nx);
        Box& box = m_box[p];
        if (box.i0 > box.i1) box = {i, i, j, j};
        box = {std::min(box.i0, i), std::max(box.i1, i), std::min(box.j0, j), std::max(box.j1, j)};
    }
}

void BounceBackCoupling::renumberGrains(const std::vector<std::int32_t>& newToOld) {
    std::vector<std::int32_t> oldToNew(newToOld.size(), -1);
    for (std::size_t k = 0; k < newToOld.size(); ++k)
        oldToNew[newToOld[k]] = static_cast<std::int32_t>(k);
    for (std::int32_t& owner : m_owner)
        if (owner >= 0) owner = oldToNew[owner];
    if (m_box.size() == newToOld.size()) {
        const std::vector<Box> old = m_box;
        for (std::size_t k = 0; k < newToOld.size(); ++k)
            m_box[k] = old[newToOld[k]];
    }
    if (m_previousLoad.size() == 3 * newToOld.size()) {
        const std::vector<Real> old = m_previousLoad;
        for (std::size_t k = 0; k < newToOld.size(); ++k)
            for (int c = 0; c < 3; ++c)
                m_previousLoad[3 * k + c] = old[3 * newToOld[k] + c];
    }
    if (resizeGrains()) m_box.assign(m_dem.particles().size(), Box{});
    forgetAnchors();
}

} // namespace lbdem::solver::coupling
