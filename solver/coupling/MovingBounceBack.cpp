// Grains as moving solid nodes: covering, refilling, Bouzidi moving-wall links, momentum exchange.
#include "solver/coupling/Coupling.h"

#include "solver/coupling/DiscGeometry.h"
#include "solver/lattice/D2Q9.h"

#include <cmath>

namespace lbdem::solver::coupling {

using lattice::equilibrium;
using lattice::kCx;
using lattice::kCy;
using lattice::kOpposite;
using lattice::kQ;
using lattice::kW;

namespace {

constexpr std::int32_t kNone = -1, kJustUncovered = -2;

} // namespace

void Coupling::mapBounceBack() {
    coverNodes();
    refillUncovered();
    buildLinks();
    applyLinks();
    m_initialised = true;
}

void Coupling::coverNodes() {
    // A node is solid when its centre lies inside r_h. Only the bounding box of each grain is
    // visited, so the cost is O(covered nodes); the lists keep their capacity between steps.
    std::swap(m_cover, m_oldCover);
    m_cover.clear();
    for (const Cover& c : m_oldCover) m_owner[c.cell] = kJustUncovered;
    Real* f = m_lattice.populations().data();
    const std::size_t n = m_dem.particles().size();
    for (std::size_t p = 0; p < n; ++p) {
        Real cx, cy, r;
        grainGeometry(p, cx, cy, r);
        const int i0 = static_cast<int>(std::ceil(cx - r - m_originX));
        const int i1 = static_cast<int>(std::floor(cx + r - m_originX));
        const int j0 = static_cast<int>(std::ceil(cy - r - m_originY));
        const int j1 = static_cast<int>(std::floor(cy + r - m_originY));
        for (int ju = j0; ju <= j1; ++ju)
            for (int iu = i0; iu <= i1; ++iu) {
                const Real dx = iu + m_originX - cx, dy = ju + m_originY - cy;
                if (dx * dx + dy * dy >= r * r) continue;
                const long long c = wrapCell(iu, ju);
                if (c < 0 || !m_lattice.isFluid(c) || m_owner[c] >= 0) continue;
                if (m_owner[c] == kNone && m_initialised) {
                    // Fluid swallowed by the grain hands its momentum to it.
                    long long slots[kQ];
                    m_lattice.postSlots(c, slots);
                    Real jx = 0, jy = 0;
                    for (int q = 1; q < kQ; ++q) {
                        jx += kCx[q] * f[slots[q]];
                        jy += kCy[q] * f[slots[q]];
                    }
                    m_loadX[p] += jx;
                    m_loadY[p] += jy;
                    m_loadT[p] += dx * jy - dy * jx;
                }
                m_owner[c] = static_cast<std::int32_t>(p);
                m_solid[c] = 1;
                // Nodes deeper than sqrt(2) inside have all eight neighbours covered: no links.
                const Real deep = r - 1.5;
                const bool surface = deep <= 0 || dx * dx + dy * dy >= deep * deep;
                m_cover.push_back({c, static_cast<std::int32_t>(p), iu, ju, surface});
            }
    }
    // Solid nodes hold the equilibrium of the surface motion: finite values for the branch-free
    // bulk kernel (which collides them too) and a meaningful velocity in fluid snapshots.
    const long long covered = static_cast<long long>(m_cover.size());
#pragma omp parallel for schedule(static) if (covered > kParallelMin)
    for (long long k = 0; k < covered; ++k) {
        const Cover& s = m_cover[k];
        Real cx, cy, r, ux, uy;
        grainGeometry(s.grain, cx, cy, r);
        surfaceVelocity(s.grain, s.iu + m_originX - cx, s.ju + m_originY - cy, ux, uy);
        long long slots[kQ];
        m_lattice.postSlots(s.cell, slots);
        for (int q = 0; q < kQ; ++q) f[slots[q]] = equilibrium(q, 1.0, ux, uy);
    }
}

void Coupling::refillUncovered() {
    // Refill (e.g. Peng et al. 2016): equilibrium at the mean density of the fluid neighbours and
    // the velocity of the surface that just left the node; the grain pays that momentum.
    Real* f = m_lattice.populations().data();
    const std::size_t n = m_dem.particles().size();
    for (const Cover& c : m_oldCover) {
        if (m_owner[c.cell] != kJustUncovered) continue;
        Real rho = 0;
        int count = 0;
        for (int q = 1; q < kQ; ++q) {
            const long long nb = wrapCell(c.iu + kCx[q], c.ju + kCy[q]);
            if (nb < 0 || !m_lattice.isFluid(nb) || m_owner[nb] != kNone) continue;
            rho += m_lattice.density(nb);
            ++count;
        }
        rho = count > 0 ? rho / count : 1.0;
        Real ux = 0, uy = 0;
        if (c.grain >= 0 && static_cast<std::size_t>(c.grain) < n) {
            Real cx, cy, r;
            grainGeometry(c.grain, cx, cy, r);
            // Wrapped or not, the offset to the centre is taken modulo the periodic length.
            Real dx = c.iu + m_originX - cx, dy = c.ju + m_originY - cy;
            if (m_periodicX) dx -= m_lattice.nx() * std::round(dx / m_lattice.nx());
            if (m_periodicY) dy -= m_lattice.ny() * std::round(dy / m_lattice.ny());
            surfaceVelocity(c.grain, dx, dy, ux, uy);
            m_loadX[c.grain] -= rho * ux;
            m_loadY[c.grain] -= rho * uy;
            m_loadT[c.grain] -= rho * (dx * uy - dy * ux);
        }
        long long slots[kQ];
        m_lattice.postSlots(c.cell, slots);
        for (int q = 0; q < kQ; ++q) f[slots[q]] = equilibrium(q, rho, ux, uy);
        m_solid[c.cell] = 0;
    }
    for (const Cover& c : m_oldCover)
        if (m_owner[c.cell] == kJustUncovered) m_owner[c.cell] = kNone;
}

int Coupling::linksOf(const Cover& s, Link* out) const {
    // Fluid neighbour n = s + c_d of a covered node; its link into the grain points along -c_d.
    if (!s.surface) return 0;
    Real cx, cy, r;
    grainGeometry(s.grain, cx, cy, r);
    int count = 0;
    for (int d = 1; d < kQ; ++d) {
        const int iu = s.iu + kCx[d], ju = s.ju + kCy[d];
        const long long nb = wrapCell(iu, ju);
        if (nb < 0 || !m_lattice.isFluid(nb) || m_owner[nb] >= 0) continue;
        if (out) {
            const int dir = kOpposite[d];
            const Real px = iu + m_originX - cx, py = ju + m_originY - cy;
            const Real q = linkWallFraction(px, py, kCx[dir], kCy[dir], r);
            long long behind = wrapCell(iu + kCx[d], ju + kCy[d]);
            if (behind >= 0 && (!m_lattice.isFluid(behind) || m_owner[behind] >= 0)) behind = -1;
            out[count] = {nb, s.cell, s.grain, dir, q, behind, px + q * kCx[dir], py + q * kCy[dir]};
        }
        ++count;
    }
    return count;
}

void Coupling::buildLinks() {
    // Count, prefix-sum, fill: parallel and in a fixed order (links grouped by grain) whatever
    // the thread count; the vectors keep their capacity, so steady state does not allocate.
    const long long covered = static_cast<long long>(m_cover.size());
    m_linkStart.resize(m_cover.size() + 1);
#pragma omp parallel for schedule(static) if (covered > kParallelMin)
    for (long long k = 0; k < covered; ++k) m_linkStart[k + 1] = linksOf(m_cover[k], nullptr);
    m_linkStart[0] = 0;
    for (std::size_t k = 0; k < m_cover.size(); ++k) m_linkStart[k + 1] += m_linkStart[k];
    m_links.resize(m_linkStart.back());
#pragma omp parallel for schedule(static) if (covered > kParallelMin)
    for (long long k = 0; k < covered; ++k) linksOf(m_cover[k], m_links.data() + m_linkStart[k]);
}

void Coupling::applyLinks() {
    // Interpolated moving-wall bounce-back (Bouzidi, Firdaouss & Lallemand 2001; wall-velocity
    // term of Lallemand & Luo 2003), with f_out leaving fluid node x_f along c (into the grain):
    //   q <  1/2: f_in(x_f) = 2q f_out(x_f) + (1 - 2q) f_out(x_f - c) + 6 w rho c_in.u_w
    //   q >= 1/2: f_in(x_f) = f_out/(2q) + (2q - 1)/(2q) f_in^post(x_f) + 3 w rho c_in.u_w / q
    // u_w = u_p + omega x r at the wall point x_f + q c. The value is stored where the next step
    // reads the population arriving at x_f along c_in (Lattice::inSlot). Momentum exchange, Galilean invariant (Wen et al. 2014):
    //   dP = (c - u_w) f_out - (c_in - u_w) f_in.
    Real* f = m_lattice.populations().data();
    const long long count = static_cast<long long>(m_links.size());
    m_linkLoad.resize(3 * m_links.size());
    Real* dp = m_linkLoad.data();
    // Each link writes its own incoming slot (one per fluid node and direction): no conflicts.
#pragma omp parallel for schedule(static) if (count > kParallelMin)
    for (long long k = 0; k < count; ++k) {
        const Link& l = m_links[k];
        const int d = l.dir, in = kOpposite[d];
        long long slots[kQ];
        m_lattice.postSlots(l.fluid, slots);
        const Real out = f[slots[d]];
        Real rho = 0;
        for (int q = 0; q < kQ; ++q) rho += f[slots[q]];
        Real ux, uy;
        surfaceVelocity(l.grain, l.rx, l.ry, ux, uy);
        const Real moving = 6.0 * kW[in] * rho * (kCx[in] * ux + kCy[in] * uy);
        Real value;
        if (l.q < 0.5 && l.behind >= 0)
            value = 2 * l.q * out + (1 - 2 * l.q) * f[m_lattice.postSlot(l.behind, d)] + moving;
        else if (l.q < 0.5)
            value = out + moving;
        else
            value = (out + (2 * l.q - 1) * f[slots[in]] + moving) / (2 * l.q);
        f[m_lattice.inSlot(l.fluid, in)] = value;
        const Real dpx = kCx[d] * (out + value) - ux * (out - value);
        const Real dpy = kCy[d] * (out + value) - uy * (out - value);
        dp[3 * k] = dpx;
        dp[3 * k + 1] = dpy;
        dp[3 * k + 2] = l.rx * dpy - l.ry * dpx;
    }
    // Sum per grain in link order: the same result for any thread count.
    for (long long k = 0; k < count; ++k) {
        const std::int32_t g = m_links[k].grain;
        m_loadX[g] += dp[3 * k];
        m_loadY[g] += dp[3 * k + 1];
        m_loadT[g] += dp[3 * k + 2];
    }
}

} // namespace lbdem::solver::coupling
