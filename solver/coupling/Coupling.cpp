// Coupling set-up, unit conversion, the method factory and the hand-over of hydrodynamic loads to
// the DEM.
#include "solver/coupling/Coupling.h"

#include "solver/core/InputError.h"
#include "solver/coupling/BounceBackCoupling.h"
#include "solver/coupling/PsmCoupling.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lbdem::solver::coupling {

namespace {

/// Clip the node range [lo, hi] (whole numbers held as Real, possibly NaN or huge) to [min, max]
/// and at most `period` nodes long (0: no limit); empty (i0 > i1) when nothing is left.
void clipRange(Real lo, Real hi, Real min, Real max, Real period, int& i0, int& i1) {
    i0 = 0;
    i1 = -1;
    if (!(lo <= hi)) return; // empty, or NaN
    lo = std::max(lo, min);
    hi = std::min(hi, max);
    if (period > 0) hi = std::min(hi, lo + period - 1);
    if (lo > hi) return;
    i0 = static_cast<int>(lo);
    i1 = static_cast<int>(hi);
}

} // namespace

std::unique_ptr<Coupling> makeCoupling(lattice::Lattice& lattice, dem::DemSystem& dem,
                                       const CouplingParams& params) {
    if (params.method == CouplingMethod::Psm)
        return std::make_unique<PsmCoupling>(lattice, dem, params);
    return std::make_unique<BounceBackCoupling>(lattice, dem, params);
}

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
    m_solid.assign(static_cast<std::size_t>(lattice.cells()), 0.0);
    resizeGrains();
}

bool Coupling::resizeGrains() {
    const std::size_t n = m_dem.particles().size();
    if (m_loadX.size() == n) return false;
    m_loadX.assign(n, 0.0);
    m_loadY.assign(n, 0.0);
    m_loadT.assign(n, 0.0);
    return true;
}

void Coupling::mapGrains() {
    resizeGrains();
    std::fill(m_loadX.begin(), m_loadX.end(), 0.0);
    std::fill(m_loadY.begin(), m_loadY.end(), 0.0);
    std::fill(m_loadT.begin(), m_loadT.end(), 0.0);
    placeGrains();
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

void Coupling::handOverLoads(const std::vector<Real>* previous) {
    auto& g = m_dem.particles();
    const std::size_t n = std::min(g.size(), m_loadX.size());
    const Real fu = forceUnit(), tu = torqueUnit();
    for (std::size_t i = 0; i < n; ++i) {
        Real lx = m_loadX[i], ly = m_loadY[i], lt = m_loadT[i];
        if (previous) {
            lx = 0.5 * (lx + (*previous)[3 * i]);
            ly = 0.5 * (ly + (*previous)[3 * i + 1]);
            lt = 0.5 * (lt + (*previous)[3 * i + 2]);
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
}

Coupling::Box Coupling::clippedBox(Real cx, Real cy, Real r, Real margin) const {
    // Along a wall-bounded side the lattice itself; along a periodic one the unwrapped indices a
    // period either side (grainGeometry brings centres there) and one period long at most.
    const Real nx = m_lattice.nx(), ny = m_lattice.ny();
    Box box;
    clipRange(std::ceil(cx - r - m_originX - margin), std::floor(cx + r - m_originX + margin),
              m_periodicX ? -nx : 0, m_periodicX ? 2 * nx - 1 : nx - 1, m_periodicX ? nx : 0,
              box.i0, box.i1);
    clipRange(std::ceil(cy - r - m_originY - margin), std::floor(cy + r - m_originY + margin),
              m_periodicY ? -ny : 0, m_periodicY ? 2 * ny - 1 : ny - 1, m_periodicY ? ny : 0,
              box.j0, box.j1);
    if (box.i0 > box.i1 || box.j0 > box.j1) return Box{};
    return box;
}

GrainLoad Coupling::latticeLoad(std::size_t i) const {
    if (i >= m_loadX.size()) return {};
    return {m_loadX[i], m_loadY[i], m_loadT[i]};
}

GrainLoad Coupling::load(std::size_t i) const {
    const GrainLoad l = latticeLoad(i);
    return {l.fx * forceUnit(), l.fy * forceUnit(), l.torque * torqueUnit()};
}

} // namespace lbdem::solver::coupling
