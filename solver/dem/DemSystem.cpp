// DemSystem: setup, velocity-Verlet stepping, neighbour rebuilds with history carry-over.
#include "solver/dem/DemSystem.h"

#include "solver/core/OpenMp.h"

#include <algorithm>
#include <cmath>

namespace lbdem::solver::dem {

DemSystem::DemSystem(const Material& material, Real skin) : m_material(material), m_skin(skin) {}

std::size_t DemSystem::addDisc(Real x, Real y, Real radius) {
    m_rebuild = true;
    return m_p.add(x, y, radius, discMass(radius, m_material.density));
}

std::size_t DemSystem::addWall(const Vec2& a, const Vec2& b) {
    m_walls.push_back({a, b, true});
    m_rebuild = true;
    return m_walls.size() - 1;
}

void DemSystem::setWallActive(std::size_t wall, bool active) {
    m_walls.at(wall).active = active;
    m_rebuild = true;
}

void DemSystem::reserve(std::size_t n) {
    m_p.reserve(n);
    m_grid.reserve(n);
    // A dense 2D packing has about 3 partners j > i within the skin; 6 leaves room.
    m_rows.start.reserve(n + 1);
    m_rows.cols.reserve(6 * n);
    m_slots.reserve(6 * n);
    m_loads.reserve(6 * n);
    m_oldStart.reserve(n + 1);
    m_oldSlots.reserve(6 * n);
    m_wallSlots.reserve(n);
    m_wallStart.reserve(n + 1);
    m_oldWallSlots.reserve(n);
    m_inStart.reserve(n + 2);
    m_inSlots.reserve(6 * n);
    m_refX.reserve(n);
    m_refY.reserve(n);
    m_vx.reserve(n);
    m_vy.reserve(n);
    m_w.reserve(n);
}

void DemSystem::setMaterial(const Material& material) {
    // Masses follow the density; the dashpots of every slot are re-derived on the rebuild.
    if (material.density != m_material.density) {
        for (std::size_t i = 0; i < m_p.size(); ++i) {
            m_p.mass[i] = discMass(m_p.radius[i], material.density);
            m_p.inertia[i] = m_p.mass[i] * m_p.radius[i] * m_p.radius[i] / 2;
        }
    }
    // Keep tangential and rolling forces continuous: the springs' elongations scale by k_old /
    // k_new.
    const Real scale = m_material.tangential_stiffness / material.tangential_stiffness;
    if (scale != 1) {
        for (PairSlot& s : m_slots) {
            s.ut *= scale;
            s.ur *= scale;
        }
        for (WallSlot& s : m_wallSlots) {
            s.ut *= scale;
            s.ur *= scale;
        }
    }
    m_material = material;
    m_rebuild = true;
}

int DemSystem::threadCount() const {
    return m_threads > 0 ? m_threads : ompMaxThreads();
}

void DemSystem::step(Real dt) {
    const std::size_t n = m_p.size();
    const Real h = dt / 2;
    Real* x = m_p.x.data();
    Real* y = m_p.y.data();
    Real* vx = m_p.vx.data();
    Real* vy = m_p.vy.data();
    Real* w = m_p.omega.data();
    const Real *fx = m_p.fx.data(), *fy = m_p.fy.data(), *tq = m_p.torque.data();
    const Real *m = m_p.mass.data(), *in = m_p.inertia.data();
    const Real *rx = m_refX.data(), *ry = m_refY.data();
    const bool haveRef = m_refX.size() == n;
    if (m_vx.size() != n) resizePredicted();
    Real *pvx = m_vx.data(), *pvy = m_vy.data(), *pw = m_w.data();
    Real maxShift2 = 0;
    const int threads = threadCount();
#pragma omp parallel for num_threads(threads) schedule(static) reduction(max : maxShift2)
    for (std::size_t i = 0; i < n; ++i) {
        // First half kick and drift of velocity Verlet.
        vx[i] += h * fx[i] / m[i];
        vy[i] += h * fy[i] / m[i];
        w[i] += h * tq[i] / in[i];
        x[i] += dt * vx[i];
        y[i] += dt * vy[i];
        pvx[i] = vx[i] + h * fx[i] / m[i];
        pvy[i] = vy[i] + h * fy[i] / m[i];
        pw[i] = w[i] + h * tq[i] / in[i];
        if (haveRef) {
            const Real dx = x[i] - rx[i], dy = y[i] - ry[i];
            maxShift2 = std::max(maxShift2, dx * dx + dy * dy);
        }
    }
    m_time += dt;
    ++m_steps;
    // Two discs that each moved less than skin / 2 cannot have closed the skin between them.
    const Real half = m_skin / 2;
    if (m_rebuild || !haveRef || maxShift2 > half * half) rebuildNeighbours();
    contactKernel(dt, threads);
    finishForces(h, true);
}

void DemSystem::advance(Real dt, int substeps) {
    const int n = std::max(substeps, 1);
    for (int s = 0; s < n; ++s)
        step(dt / n);
}

void DemSystem::resizePredicted() {
    const std::size_t n = m_p.size();
    m_vx.resize(n);
    m_vy.resize(n);
    m_w.resize(n);
}

void DemSystem::computeForces() {
    if (m_rebuild || m_refX.size() != m_p.size()) rebuildNeighbours();
    resizePredicted();
    m_vx = m_p.vx;
    m_vy = m_p.vy;
    m_w = m_p.omega;
    contactKernel(0, threadCount());
    finishForces(0, false);
}

void DemSystem::rebuildNeighbours() {
    const std::size_t n = m_p.size();
    Real rmax = 0, rmin = n ? m_p.radius[0] : 0;
    for (std::size_t i = 0; i < n; ++i) {
        rmax = std::max(rmax, m_p.radius[i]);
        rmin = std::min(rmin, m_p.radius[i]);
    }
    // Default margin: a fifth of the smallest radius, rebuilt after a tenth of it is travelled.
    if (m_skin <= 0) m_skin = rmin / 5;
    if (!m_restorePending) {
        std::swap(m_rows.start, m_oldStart);
        std::swap(m_slots, m_oldSlots);
        std::swap(m_wallSlots, m_oldWallSlots);
        m_haveOld = m_oldStart.size() == n + 1;
    }
    m_restorePending = false;
    m_grid.build(m_p.x.data(), m_p.y.data(), n, 2 * rmax + m_skin);
    m_grid.pairs(m_p.x.data(), m_p.y.data(), m_p.radius.data(), m_skin, m_rows);
    mergeHistory();
    buildIncoming();
    buildWallSlots();
    m_refX = m_p.x;
    m_refY = m_p.y;
    m_kt = m_material.tangential_stiffness;
    m_rebuild = false;
    ++m_rebuildCount;
}

void DemSystem::mergeHistory() {
    const std::size_t n = m_p.size();
    m_slots.resize(m_rows.cols.size());
    m_loads.resize(m_rows.cols.size());
    const Real zeta = dampingRatio(m_material.restitution);
    const Real kn = m_material.normal_stiffness;
    const Real ratio = std::sqrt(m_material.tangential_stiffness / kn);
    for (std::size_t i = 0; i < n; ++i) {
        std::uint32_t o = m_haveOld ? m_oldStart[i] : 0;
        const std::uint32_t oEnd = m_haveOld ? m_oldStart[i + 1] : 0;
        for (std::uint32_t k = m_rows.start[i]; k < m_rows.start[i + 1]; ++k) {
            const std::int32_t j = m_rows.cols[k];
            PairSlot& s = m_slots[k];
            s = PairSlot{};
            s.j = j;
            while (o < oEnd && m_oldSlots[o].j < j)
                ++o;
            if (o < oEnd && m_oldSlots[o].j == j) {
                s.ut = m_oldSlots[o].ut;
                s.ur = m_oldSlots[o].ur;
                s.fn = m_oldSlots[o].fn;
                s.ft = m_oldSlots[o].ft;
            }
            const Real mi = m_p.mass[i], mj = m_p.mass[j];
            const Real ri = m_p.radius[i], rj = m_p.radius[j];
            s.gn = 2 * zeta * std::sqrt(kn * mi * mj / (mi + mj));
            s.gt = s.gn * ratio;
            s.reff = ri * rj / (ri + rj);
        }
    }
}

void DemSystem::buildWallSlots() {
    const std::size_t n = m_p.size();
    const Real zeta = dampingRatio(m_material.restitution);
    const Real kn = m_material.normal_stiffness;
    const Real ratio = std::sqrt(m_material.tangential_stiffness / kn);
    m_wallSlots.clear();
    m_wallStart.resize(n + 1);
    m_wallStart[0] = 0;
    std::size_t o = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 c(m_p.x[i], m_p.y[i]);
        for (std::size_t w = 0; w < m_walls.size(); ++w) {
            if (!m_walls[w].active) continue;
            const Vec2 ab = m_walls[w].b - m_walls[w].a;
            const Real t =
                std::clamp((c - m_walls[w].a).dot(ab) / std::max(ab.squaredNorm(), Real(1e-300)),
                           Real(0), Real(1));
            const Vec2 p = m_walls[w].a + t * ab;
            const Real reach = m_p.radius[i] + m_skin;
            if ((p - c).squaredNorm() >= reach * reach) continue;
            WallSlot s;
            s.i = static_cast<std::int32_t>(i);
            s.wall = static_cast<std::int32_t>(w);
            auto before = [&](const WallSlot& a) {
                return a.i < s.i || (a.i == s.i && a.wall < s.wall);
            };
            while (o < m_oldWallSlots.size() && before(m_oldWallSlots[o]))
                ++o;
            if (o < m_oldWallSlots.size() && m_oldWallSlots[o].i == s.i &&
                m_oldWallSlots[o].wall == s.wall) {
                s.ut = m_oldWallSlots[o].ut;
                s.ur = m_oldWallSlots[o].ur;
                s.fn = m_oldWallSlots[o].fn;
                s.ft = m_oldWallSlots[o].ft;
            }
            s.gn = 2 * zeta * std::sqrt(kn * m_p.mass[i]);
            s.gt = s.gn * ratio;
            s.px = p.x();
            s.py = p.y();
            m_wallSlots.push_back(s);
        }
        m_wallStart[i + 1] = static_cast<std::uint32_t>(m_wallSlots.size());
    }
}

Real DemSystem::kineticEnergy() const {
    Real e = 0;
    for (std::size_t i = 0; i < m_p.size(); ++i)
        e += 0.5 * m_p.mass[i] * (m_p.vx[i] * m_p.vx[i] + m_p.vy[i] * m_p.vy[i]) +
             0.5 * m_p.inertia[i] * m_p.omega[i] * m_p.omega[i];
    return e;
}

Real DemSystem::maxSpeed() const {
    Real v2 = 0;
    for (std::size_t i = 0; i < m_p.size(); ++i)
        v2 = std::max(v2, m_p.vx[i] * m_p.vx[i] + m_p.vy[i] * m_p.vy[i]);
    return std::sqrt(v2);
}

} // namespace lbdem::solver::dem
