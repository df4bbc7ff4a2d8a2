// Grains as moving solid nodes: covering, refilling, Bouzidi moving-wall links, momentum exchange.
//
// Per fluid step, three passes, each over the grains' bounding boxes so that a grain's
// neighbourhood stays in cache while all of its work is done:
//   1. findChanges (parallel, read-only): the nodes each grain starts or stops covering;
//   2. applyChanges + refillUncovered (serial, cost ~ changed nodes): ownership, momentum of
//      swallowed and released fluid;
//   3. per grain (parallel): solid nodes to the equilibrium of the surface motion, then the
//      moving-wall links of its surface nodes, applied at once, with their momentum exchange.
// Grains write only the populations of their own solid nodes and read only fluid ones, so the
// grains of pass 3 are independent; loads sum per grain in a fixed order (any thread count).
#include "solver/coupling/Coupling.h"

#include "solver/coupling/DiscGeometry.h"
#include "solver/core/OpenMp.h"
#include "solver/lattice/D2Q9.h"

#include <algorithm>
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

/// Fewer grains than this map on one thread: a parallel region costs more than their work.
constexpr std::size_t kParallelGrains = 32;

} // namespace

void Coupling::mapBounceBack() {
    findChanges();
    applyChanges();
    refillUncovered();
    const long long n = static_cast<long long>(m_dem.particles().size());
    std::size_t links = 0;
#pragma omp parallel for schedule(static) reduction(+ : links) if (n >= static_cast<long long>(kParallelGrains))
    for (long long p = 0; p < n; ++p) links += bounceBackGrain(static_cast<std::size_t>(p));
    m_linkCount = links;
    m_initialised = true;
}

Coupling::Box Coupling::grainBox(std::size_t p) const {
    // A node is solid when its centre lies strictly inside r_h: these bounds hold every such node.
    Real cx, cy, r;
    grainGeometry(p, cx, cy, r);
    return {static_cast<int>(std::ceil(cx - r - m_originX)), static_cast<int>(std::floor(cx + r - m_originX)),
            static_cast<int>(std::ceil(cy - r - m_originY)), static_cast<int>(std::floor(cy + r - m_originY))};
}

void Coupling::findGrainChanges(std::size_t p, std::vector<Change>& out) const {
    // Scan the grain's box now and the box it had: nodes it covers but does not own, and nodes it
    // owns but no longer covers. Nothing is written, so grains scan in parallel.
    Real cx, cy, r;
    grainGeometry(p, cx, cy, r);
    Box scan = grainBox(p);
    const Box& last = m_box[p];
    if (last.i0 <= last.i1 && last.j0 <= last.j1) {
        scan.i0 = std::min(scan.i0, last.i0);
        scan.i1 = std::max(scan.i1, last.i1);
        scan.j0 = std::min(scan.j0, last.j0);
        scan.j1 = std::max(scan.j1, last.j1);
    }
    const int nx = m_lattice.nx(), ny = m_lattice.ny();
    // One period at most (a grain that just crossed a periodic side has boxes a period apart).
    if (m_periodicX && scan.i1 - scan.i0 >= nx) scan.i1 = scan.i0 + nx - 1;
    if (m_periodicY && scan.j1 - scan.j0 >= ny) scan.j1 = scan.j0 + ny - 1;
    const auto id = static_cast<std::int32_t>(p);
    for (int ju = scan.j0; ju <= scan.j1; ++ju)
        for (int iu = scan.i0; iu <= scan.i1; ++iu) {
            const long long c = wrapCell(iu, ju);
            if (c < 0) continue;
            Real dx = iu + m_originX - cx, dy = ju + m_originY - cy;
            if (m_periodicX) dx -= nx * std::round(dx / nx);
            if (m_periodicY) dy -= ny * std::round(dy / ny);
            const bool inside = dx * dx + dy * dy < r * r && m_lattice.isFluid(c);
            const std::int32_t owner = m_owner[c];
            if (inside && owner != id) out.push_back({c, id, iu, ju, true});
            else if (!inside && owner == id) out.push_back({c, id, iu, ju, false});
        }
}

void Coupling::findChanges() {
    const std::size_t n = m_dem.particles().size();
    const int threads = n >= kParallelGrains ? std::max(ompMaxThreads(), 1) : 1;
    if (m_threadChanges.size() < static_cast<std::size_t>(threads)) m_threadChanges.resize(threads);
    for (auto& list : m_threadChanges) list.clear();
    // Static schedule: thread t takes the t-th block of grains, so the lists, read in thread
    // order, hold the changes in grain order whatever the thread count.
#pragma omp parallel num_threads(threads) if (threads > 1)
    {
        std::vector<Change>& out = m_threadChanges[ompThreadIndex()];
#pragma omp for schedule(static)
        for (long long p = 0; p < static_cast<long long>(n); ++p) {
            findGrainChanges(static_cast<std::size_t>(p), out);
            m_box[p] = grainBox(static_cast<std::size_t>(p));
        }
    }
}

void Coupling::applyChanges() {
    // Grains first leave nodes, then take nodes in grain order, the lowest index winning a node
    // two grains overlap. A node passing straight from one grain to another is not fluid at any
    // point: it is neither refilled nor swallowed.
    m_uncovered.clear();
    for (const auto& list : m_threadChanges)
        for (const Change& ch : list)
            if (!ch.cover && m_owner[ch.cell] == ch.grain) {
                m_owner[ch.cell] = kJustUncovered;
                m_uncovered.push_back(ch);
            }
    for (const auto& list : m_threadChanges)
        for (const Change& ch : list) {
            if (!ch.cover) continue;
            const std::int32_t owner = m_owner[ch.cell];
            if (owner >= 0 && owner < ch.grain) continue;
            if (owner == kNone && m_initialised) {
                // Fluid swallowed by the grain hands its momentum to it.
                Real cx, cy, r;
                grainGeometry(ch.grain, cx, cy, r);
                Real dx = ch.iu + m_originX - cx, dy = ch.ju + m_originY - cy;
                if (m_periodicX) dx -= m_lattice.nx() * std::round(dx / m_lattice.nx());
                if (m_periodicY) dy -= m_lattice.ny() * std::round(dy / m_lattice.ny());
                long long slots[kQ];
                m_lattice.postSlots(ch.cell, slots);
                Real jx = 0, jy = 0;
                for (int q = 1; q < kQ; ++q) {
                    const Real v = m_lattice.population(slots[q], q);
                    jx += kCx[q] * v;
                    jy += kCy[q] * v;
                }
                m_loadX[ch.grain] += jx;
                m_loadY[ch.grain] += jy;
                m_loadT[ch.grain] += dx * jy - dy * jx;
            }
            m_owner[ch.cell] = ch.grain;
            m_solid[ch.cell] = 1;
        }
}

void Coupling::refillUncovered() {
    // Refill (e.g. Peng et al. 2016): equilibrium at the mean density of the fluid neighbours and
    // the velocity of the surface that just left the node; the grain pays that momentum.
    for (const Change& c : m_uncovered) {
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
        Real cx, cy, r, ux, uy;
        grainGeometry(c.grain, cx, cy, r);
        // Wrapped or not, the offset to the centre is taken modulo the periodic length.
        Real dx = c.iu + m_originX - cx, dy = c.ju + m_originY - cy;
        if (m_periodicX) dx -= m_lattice.nx() * std::round(dx / m_lattice.nx());
        if (m_periodicY) dy -= m_lattice.ny() * std::round(dy / m_lattice.ny());
        surfaceVelocity(c.grain, dx, dy, ux, uy);
        m_loadX[c.grain] -= rho * ux;
        m_loadY[c.grain] -= rho * uy;
        m_loadT[c.grain] -= rho * (dx * uy - dy * ux);
        long long slots[kQ];
        m_lattice.postSlots(c.cell, slots);
        for (int q = 0; q < kQ; ++q) m_lattice.setPopulation(slots[q], q, equilibrium(q, rho, ux, uy));
        m_solid[c.cell] = 0;
    }
    for (const Change& c : m_uncovered)
        if (m_owner[c.cell] == kJustUncovered) m_owner[c.cell] = kNone;
}

std::size_t Coupling::bounceBackGrain(std::size_t p) {
    Real cx, cy, r;
    grainGeometry(p, cx, cy, r);
    const Box& box = m_box[p];
    const auto id = static_cast<std::int32_t>(p);
    const auto& g = m_dem.particles();
    const Real scale = m_params.dt / m_params.h, vx = g.vx[p] * scale, vy = g.vy[p] * scale;
    const Real w = g.omega[p] * m_params.dt; // u_w = (vx - w r_y, vy + w r_x), lattice units
    Real loadX = m_loadX[p], loadY = m_loadY[p], loadT = m_loadT[p];
    std::size_t links = 0;
    // Only nodes within 1.5 of the surface are visited: deeper ones have all eight neighbours
    // covered, so nothing they hold reaches the fluid (they keep near the equilibrium of the
    // grain's motion by themselves: the surface nodes around them are reset every step).
    const Real deep = r - 1.5;
    const Real centreI = cx - m_originX;
    for (int ju = box.j0; ju <= box.j1; ++ju) {
        const Real sy = ju + m_originY - cy;
        if (sy * sy >= r * r) continue; // no node of this row is inside (exact: dx^2 >= 0)
        // The row's chord, one node wider on each side against rounding; the owner decides.
        const Real half = std::sqrt(r * r - sy * sy);
        const int lo = std::max(box.i0, static_cast<int>(std::floor(centreI - half))),
                  hi = std::min(box.i1, static_cast<int>(std::ceil(centreI + half)));
        // Nodes surely deeper than `deep`, one node narrower on each side against rounding.
        int deepLo = hi + 1, deepHi = hi;
        if (deep > 0 && sy * sy < deep * deep) {
            const Real deepHalf = std::sqrt(deep * deep - sy * sy);
            deepLo = static_cast<int>(std::ceil(centreI - deepHalf)) + 1;
            deepHi = static_cast<int>(std::floor(centreI + deepHalf)) - 1;
            if (deepLo > deepHi) deepLo = hi + 1, deepHi = hi;
        }
        for (int iu = lo; iu <= hi; ++iu) {
            if (iu == deepLo) iu = deepHi + 1;
            if (iu > hi) break;
            int i = iu, j = ju;
            if (!wrapNode(i, j) || m_owner[m_lattice.index(i, j)] != id) continue;
            const Real sx = iu + m_originX - cx;
            if (deep > 0 && sx * sx + sy * sy < deep * deep) continue;
            // The surface node holds the equilibrium of the surface motion (finite values for
            // the branch-free bulk kernel, a meaningful velocity in snapshots); its links then
            // overwrite the slots its fluid neighbours read.
            long long solidSlots[kQ];
            m_lattice.postSlots(i, j, solidSlots);
            const Real sux = vx - w * sy, suy = vy + w * sx;
            for (int q = 0; q < kQ; ++q) m_lattice.setPopulation(solidSlots[q], q, equilibrium(q, 1.0, sux, suy));
            links += linkSurfaceNode(iu, ju, sx, sy, r, solidSlots, vx, vy, w, loadX, loadY, loadT);
        }
    }
    m_loadX[p] = loadX;
    m_loadY[p] = loadY;
    m_loadT[p] = loadT;
    return links;
}

int Coupling::linkSurfaceNode(int iu, int ju, Real sx, Real sy, Real r, const long long solidSlots[kQ],
                              Real vx, Real vy, Real w, Real& loadX, Real& loadY, Real& loadT) {
    // Interpolated moving-wall bounce-back (Bouzidi, Firdaouss & Lallemand 2001; wall-velocity
    // term of Lallemand & Luo 2003), with f_out leaving fluid node x_f along c (into the grain):
    //   q <  1/2: f_in(x_f) = 2q f_out(x_f) + (1 - 2q) f_out(x_f - c) + 6 w rho c_in.u_w
    //   q >= 1/2: f_in(x_f) = f_out/(2q) + (2q - 1)/(2q) f_in^post(x_f) + 3 w rho c_in.u_w / q
    // u_w = u_p + omega x r at the wall point x_f + q c. The value is stored where the next step
    // reads the population arriving at x_f along c_in: the solid node's post-collision slot.
    // Momentum exchange, Galilean invariant (Wen et al. 2014): dP = (c - u_w) f_out - (c_in - u_w) f_in,
    // on the excess populations f - w rho_0 (rho_0 = 1, the fluid at rest): the rest state's
    // share 2 w rho_0 c integrates to zero over a closed wetted surface (each lattice line enters
    // and leaves it), but where the surface faces another grain or a wall and has no link, it
    // would leave a pull of the absolute pressure rho_0 c_s^2 on the open side. Subtracting it
    // makes an unwetted part of a surface contribute nothing (the verify case near-contact).
    int links = 0;
    for (int back = 1; back < kQ; ++back) { // fluid node x_f = solid + c_back
        int fi = iu + kCx[back], fj = ju + kCy[back];
        if (!wrapNode(fi, fj)) continue;
        const long long fluid = m_lattice.index(fi, fj);
        if (!m_lattice.isFluid(fluid) || m_owner[fluid] >= 0) continue;
        const int toward = kOpposite[back];
        const Real px = sx + kCx[back], py = sy + kCy[back];
        const Real q = linkWallFraction(px, py, kCx[toward], kCy[toward], r);
        const Real rx = px + q * kCx[toward], ry = py + q * kCy[toward];
        long long slots[kQ];
        m_lattice.postSlots(fi, fj, slots);
        const Real out = m_lattice.population(slots[toward], toward);
        Real rho = 0;
        for (int k = 0; k < kQ; ++k) rho += m_lattice.population(slots[k], k);
        const Real ux = vx - w * ry, uy = vy + w * rx;
        const Real moving = 6.0 * kW[back] * rho * (kCx[back] * ux + kCy[back] * uy);
        Real value;
        int bi = fi + kCx[back], bj = fj + kCy[back]; // x_f - c, behind the fluid node
        bool behindFluid = false;
        if (q < 0.5 && wrapNode(bi, bj)) {
            const long long behind = m_lattice.index(bi, bj);
            behindFluid = m_lattice.isFluid(behind) && m_owner[behind] < 0;
        }
        if (behindFluid)
            value = 2 * q * out + (1 - 2 * q) * m_lattice.population(m_lattice.postSlot(bi, bj, toward), toward) + moving;
        else if (q < 0.5)
            value = out + moving;
        else
            value = (out + (2 * q - 1) * m_lattice.population(slots[back], back) + moving) / (2 * q);
        m_lattice.setPopulation(solidSlots[back], back, value);
        const Real excess = out + value - 2 * kW[toward];
        const Real dpx = kCx[toward] * excess - ux * (out - value);
        const Real dpy = kCy[toward] * excess - uy * (out - value);
        loadX += dpx;
        loadY += dpy;
        loadT += rx * dpy - ry * dpx;
        ++links;
    }
    return links;
}

} // namespace lbdem::solver::coupling
