// The contact kernel: linear spring-dashpot normal force, tangential and rolling springs with
// Coulomb-type limits, for disc pairs and disc-wall contacts, each into its own slot; then the
// gather that sums every disc's slots in a fixed order (thread-count independent).
#include "solver/dem/DemSystem.h"

#include <algorithm>
#include <cmath>

namespace lbdem::solver::dem {

namespace {

/// Tangential and rolling parts shared by pair and wall contacts. vt is the sliding velocity of
/// the second body relative to the first along t, spin the relative rotation rate.
/// Returns the tangential force on the second body along t; sets the rolling torque on the first.
inline Real tangentialAndRolling(Real fn, Real vt, Real spin, Real dt, Real kt, Real gt, Real mu,
                                 Real reff, Real muRoll, Real& ut, Real& ur, Real& rollTorque) {
    // Tangential spring-dashpot with Coulomb limit |F_t| <= mu F_n; the spring is reset to the
    // limit while sliding, so slip stores no elastic energy.
    ut += vt * dt;
    Real ft = -kt * ut - gt * vt;
    const Real fmax = mu * std::max(fn, Real(0));
    if (std::abs(ft) > fmax) {
        ft = std::copysign(fmax, ft);
        ut = -ft / kt;
    }
    // Rolling spring k_r = k_t R_eff^2 (Iwashita & Oda 1998) with plastic limit mu_r R_eff F_n.
    const Real kr = kt * reff * reff;
    ur += spin * dt;
    Real m = -kr * ur;
    const Real mmax = muRoll * reff * std::max(fn, Real(0));
    if (std::abs(m) > mmax) {
        m = std::copysign(mmax, m);
        ur = kr > 0 ? -m / kr : 0;
    }
    rollTorque = m;
    return ft;
}

/// Read-only inputs of the kernel: state (with predicted velocities) and contact-law constants.
struct KernelView {
    const Real *x, *y, *vx, *vy, *w, *r;
    Real kn, kt, mu, muWall, muRoll, muRollWall, dt;
};

/// Forces of the pairs (i, j > i) of one row, each stored in its slot and load.
inline void pairRow(const KernelView& v, std::size_t i, PairSlot* slot, PairSlot* end,
                    PairLoad* load) {
    const Real xi = v.x[i], yi = v.y[i], ri = v.r[i];
    for (; slot < end; ++slot, ++load) {
        PairSlot& s = *slot;
        const std::int32_t j = s.j;
        const Real dx = v.x[j] - xi, dy = v.y[j] - yi, reach = ri + v.r[j];
        const Real d2 = dx * dx + dy * dy;
        if (d2 >= reach * reach) {
            s.ut = s.ur = s.fn = s.ft = 0;
            *load = PairLoad{};
            continue;
        }
        const Real d = std::sqrt(d2);
        const Real nx = dx / d, ny = dy / d; // normal from i to j; tangent t = (-ny, nx)
        const Real dvx = v.vx[j] - v.vx[i], dvy = v.vy[j] - v.vy[i];
        const Real vn = dvx * nx + dvy * ny; // > 0: separating
        const Real vt = -dvx * ny + dvy * nx - (ri * v.w[i] + v.r[j] * v.w[j]);
        const Real fn = v.kn * (reach - d) - s.gn * vn;
        Real roll = 0;
        const Real ft = tangentialAndRolling(fn, vt, v.w[i] - v.w[j], v.dt, v.kt, s.gt, v.mu,
                                             s.reff, v.muRoll, s.ut, s.ur, roll);
        s.fn = fn;
        s.ft = ft;
        load->fx = fn * nx - ft * ny; // force on j; i feels the opposite
        load->fy = fn * ny + ft * nx;
        load->ti = -ri * ft + roll;
        load->tj = -v.r[j] * ft - roll;
    }
}

/// Force of one disc-wall contact (the wall is the second body, at rest).
inline void wallContact(const KernelView& v, WallSlot& s, const Wall& wall) {
    const std::int32_t i = s.i;
    const Real ex = wall.b.x() - wall.a.x(), ey = wall.b.y() - wall.a.y();
    const Real len2 = ex * ex + ey * ey;
    Real t = len2 > 0 ? ((v.x[i] - wall.a.x()) * ex + (v.y[i] - wall.a.y()) * ey) / len2 : 0;
    t = std::clamp(t, Real(0), Real(1));
    const Real px = wall.a.x() + t * ex, py = wall.a.y() + t * ey;
    const Real dx = px - v.x[i], dy = py - v.y[i];
    const Real d2 = dx * dx + dy * dy, ri = v.r[i];
    s.px = px;
    s.py = py;
    if (d2 >= ri * ri || d2 <= 0) {
        s.ut = s.ur = s.fn = s.ft = s.fx = s.fy = s.torque = 0;
        return;
    }
    const Real d = std::sqrt(d2);
    const Real nx = dx / d, ny = dy / d; // from the disc centre to the wall
    const Real vn = -(v.vx[i] * nx + v.vy[i] * ny);
    const Real vt = v.vx[i] * ny - v.vy[i] * nx - ri * v.w[i];
    const Real fn = v.kn * (ri - d) - s.gn * vn;
    Real roll = 0;
    const Real ft = tangentialAndRolling(fn, vt, v.w[i], v.dt, v.kt, s.gt, v.muWall, ri,
                                         v.muRollWall, s.ut, s.ur, roll);
    s.fn = fn;
    s.ft = ft;
    s.fx = -(fn * nx - ft * ny);
    s.fy = -(fn * ny + ft * nx);
    s.torque = -ri * ft + roll;
}

} // namespace

void DemSystem::contactKernel(Real dt, int threads) {
    const std::size_t n = m_p.size();
    // Velocities predicted at the end of the step, so that the dashpots see v(t + dt).
    const KernelView view{m_p.x.data(),
                          m_p.y.data(),
                          m_vx.data(),
                          m_vy.data(),
                          m_w.data(),
                          m_p.radius.data(),
                          m_material.normal_stiffness,
                          m_kt,
                          m_material.friction,
                          m_material.wall_friction,
                          m_material.rolling_resistance,
                          m_material.wall_rolling_resistance,
                          dt};
    const std::uint32_t* start = m_rows.start.data();
    PairSlot* slots = m_slots.data();
    PairLoad* loads = m_loads.data();
    WallSlot* wslots = m_wallSlots.data();
    const std::uint32_t* wallStart = m_wallStart.data();
    const Wall* walls = m_walls.data();
    // Every contact writes its own slot only: no write conflicts, no atomics, no buffers.
#pragma omp parallel for num_threads(threads) schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
        pairRow(view, i, slots + start[i], slots + start[i + 1], loads + start[i]);
        for (std::uint32_t k = wallStart[i]; k < wallStart[i + 1]; ++k)
            wallContact(view, wslots[k], walls[wslots[k].wall]);
    }
}

void DemSystem::finishForces(Real h, bool kick) {
    const std::size_t n = m_p.size();
    const PairLoad* loads = m_loads.data();
    const WallSlot* wslots = m_wallSlots.data();
    const std::uint32_t *start = m_rows.start.data(), *wallStart = m_wallStart.data();
    const std::uint32_t *inStart = m_inStart.data(), *inSlots = m_inSlots.data();
    Real *fx = m_p.fx.data(), *fy = m_p.fy.data(), *tq = m_p.torque.data();
    Real *vx = m_p.vx.data(), *vy = m_p.vy.data(), *w = m_p.omega.data();
    const Real *m = m_p.mass.data(), *in = m_p.inertia.data();
    const Real *ex = m_p.ext_fx.data(), *ey = m_p.ext_fy.data(), *et = m_p.ext_torque.data();
    const Real gx = m_gravity.x(), gy = m_gravity.y();
    const Real turn = m_material.contact_torque ? 1 : 0; // 1 * t == t: the default is unchanged
    // Each disc sums its contact loads in one fixed order (pairs where it is the partner j by
    // increasing i, pairs of its own row by increasing j, its walls by index), then adds them to
    // its body and external load: the same bits whichever thread handles it, and the same bits
    // as the single-threaded per-disc buffers this replaced.
#pragma omp parallel for num_threads(threadCount()) schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
        Real cx = 0, cy = 0, ct = 0;
        for (std::uint32_t k = inStart[i]; k < inStart[i + 1]; ++k) {
            const PairLoad& l = loads[inSlots[k]];
            cx += l.fx;
            cy += l.fy;
            ct += turn * l.tj;
        }
        for (std::uint32_t k = start[i]; k < start[i + 1]; ++k) {
            const PairLoad& l = loads[k];
            cx -= l.fx;
            cy -= l.fy;
            ct += turn * l.ti;
        }
        for (std::uint32_t k = wallStart[i]; k < wallStart[i + 1]; ++k) {
            cx += wslots[k].fx;
            cy += wslots[k].fy;
            ct += turn * wslots[k].torque;
        }
        const Real sx = m[i] * gx + ex[i] + cx, sy = m[i] * gy + ey[i] + cy, st = et[i] + ct;
        fx[i] = sx;
        fy[i] = sy;
        tq[i] = st;
        if (kick) {
            vx[i] += h * sx / m[i];
            vy[i] += h * sy / m[i];
            w[i] += h * st / in[i];
        }
    }
}

void DemSystem::buildIncoming() {
    // Counting sort of the slots by partner j; a stable pass keeps each group in increasing i.
    const std::size_t n = m_p.size();
    m_inStart.assign(n + 2, 0);
    for (const PairSlot& s : m_slots)
        ++m_inStart[s.j + 2];
    for (std::size_t j = 0; j < n; ++j)
        m_inStart[j + 2] += m_inStart[j + 1];
    // m_inStart[j + 1] is now where group j starts; filling advances it to where j ends, which
    // is where group j + 1 starts: m_inStart[0 .. n] ends up as the group starts.
    m_inSlots.resize(m_slots.size());
    for (std::size_t k = 0; k < m_slots.size(); ++k)
        m_inSlots[m_inStart[m_slots[k].j + 1]++] = static_cast<std::uint32_t>(k);
    m_inStart.pop_back();
}

} // namespace lbdem::solver::dem
