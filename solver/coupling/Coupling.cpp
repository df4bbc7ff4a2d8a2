// Coupling set-up, unit conversion and the hand-over of hydrodynamic loads to the DEM.
#include "solver/coupling/Coupling.h"

#include "solver/core/InputError.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lbdem::solver::coupling {

Coupling::Coupling(lattice::Lattice& lattice, dem::DemSystem& dem, const CouplingParams& params)
    : m_lattice(lattice), m_dem(dem), m_params(params) {
    if (!(params.h > 0) || !(params.dt > 0) || !(params.rho_f > 0))
        throw InputError("the coupling needs positive h, dt and fluid density");
    if (!(params.hydro_radius_ratio > 0) || params.hydro_radius_ratio > 1)
        throw InputError("the hydrodynamic radius ratio must lie in (0, 1]");
    const auto& setup = lattice.setup();
    m_periodicX = setup.left.type == lattice::SideType::Periodic;
    m_periodicY = setup.bottom.type == lattice::SideType::Periodic;
    m_originX = lattice.nodeX(0);
    m_originY = lattice.nodeY(0);
    const auto cells = static_cast<std::size_t>(lattice.cells());
    m_owner.assign(cells, -1);
    m_solid.assign(cells, 0.0);
    resizeGrains();
}

void Coupling::resizeGrains() {
    const std::size_t n = m_dem.particles().size();
    if (m_loadX.size() == n) return;
    m_box.assign(n, Box{});
    m_loadX.assign(n, 0.0);
    m_loadY.assign(n, 0.0);
    m_loadT.assign(n, 0.0);
}

void Coupling::mapGrains() {
    resizeGrains();
    std::fill(m_loadX.begin(), m_loadX.end(), 0.0);
    std::fill(m_loadY.begin(), m_loadY.end(), 0.0);
    std::fill(m_loadT.begin(), m_loadT.end(), 0.0);
    if (m_params.method == CouplingMethod::BounceBack)
        mapBounceBack();
    else
        mapPsm();
    m_lattice.setLastSweptRow(topGrainRow());
}

int Coupling::topGrainRow() const {
    // Two rows above the highest grain: its links reach one node out, the next kernel step one
    // more.
    Real top = -1;
    for (std::size_t p = 0; p < m_dem.particles().size(); ++p) {
        Real cx, cy, r;
        grainGeometry(p, cx, cy, r);
        top = std::max(top, cy + r + 2);
    }
    // Compared as Real: a grain far above the lattice (a hostile checkpoint) converts no huge
    // value.
    const Real last = m_lattice.ny() - 1;
    return static_cast<int>(top < 0 || !(top < last) ? last : top);
}

void Coupling::collectForces() {
    if (m_params.method == CouplingMethod::Psm) collidePsm();
    auto& g = m_dem.particles();
    const std::size_t n = std::min(g.size(), m_loadX.size());
    const Real fu = forceUnit(), tu = torqueUnit();
    // Bounce-back: the DEM gets the mean of the last two steps' loads. A fluid node between a grain
    // and a wall (or another grain), bounced back on both sides, keeps a period-two mode: its
    // momentum across the gap flips sign every step and nothing damps it as tau -> 1/2 (the
    // collision conserves momentum). The link force follows that momentum and the grain's velocity
    // feeds it back through the moving-wall term: per link, with grain mass M in lattice units,
    // the gap momentum j and grain velocity V obey j' = -j + (2/3) V, V' = V + (j - (2/3) V) / M,
    // whose eigenvalue -1/(3M) - sqrt(1 + 1/(9M^2)) lies outside the unit circle. This grew into a
    // Mach ~1 blow-up beside a grain resting in the floor-wall corner at tau = 0.506. The two-step
    // mean cancels the period-two part of the force and leaves slowly varying loads unchanged.
    const bool average = m_params.method == CouplingMethod::BounceBack &&
                         m_previousLoad.size() == 3 * m_loadX.size();
    for (std::size_t i = 0; i < n; ++i) {
        Real lx = m_loadX[i], ly = m_loadY[i], lt = m_loadT[i];
        if (average) {
            lx = 0.5 * (lx + m_previousLoad[3 * i]);
            ly = 0.5 * (ly + m_previousLoad[3 * i + 1]);
            lt = 0.5 * (lt + m_previousLoad[3 * i + 2]);
        }
        // The DEM's stored totals include the previous external load; shift them by the change
        // so the first half-kick of the next sub-step already sees the new hydrodynamic load.
        const Real fx = lx * fu, fy = ly * fu, t = lt * tu;
        g.fx[i] += fx - g.ext_fx[i];
        g.fy[i] += fy - g.ext_fy[i];
        g.torque[i] += t - g.ext_torque[i];
        g.ext_fx[i] = fx;
        g.ext_fy[i] = fy;
        g.ext_torque[i] = t;
    }
    if (m_params.method != CouplingMethod::BounceBack) return;
    m_previousLoad.resize(3 * m_loadX.size());
    for (std::size_t i = 0; i < m_loadX.size(); ++i) {
        m_previousLoad[3 * i] = m_loadX[i];
        m_previousLoad[3 * i + 1] = m_loadY[i];
        m_previousLoad[3 * i + 2] = m_loadT[i];
    }
}

GrainLoad Coupling::latticeLoad(std::size_t i) const {
    if (i >= m_loadX.size()) return {};
    return {m_loadX[i], m_loadY[i], m_loadT[i]};
}

GrainLoad Coupling::load(std::size_t i) const {
    const GrainLoad l = latticeLoad(i);
    return {l.fx * forceUnit(), l.fy * forceUnit(), l.torque * torqueUnit()};
}

std::size_t Coupling::boundaryCount() const {
    return m_params.method == CouplingMethod::BounceBack ? m_linkCount : m_psm.size();
}

CouplingState Coupling::state() const {
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

void Coupling::restore(const CouplingState& state) {
    if (state.cells.size() != state.grains.size())
        throw InputError("coupling state: cell and grain lists differ in length");
    const std::size_t n = m_dem.particles().size();
    if (!state.previous_loads.empty() && state.previous_loads.size() != 3 * n)
        throw InputError("coupling state: the previous loads do not match the grain count");
    resizeGrains();
    m_previousLoad = state.previous_loads;
    if (m_params.method == CouplingMethod::BounceBack) {
        std::fill(m_owner.begin(), m_owner.end(), -1);
        std::fill(m_solid.begin(), m_solid.end(), 0.0);
    }
    m_box.assign(n, Box{});
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

void Coupling::renumberGrains(const std::vector<std::int32_t>& newToOld) {
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
    resizeGrains();
}

} // namespace lbdem::solver::coupling
