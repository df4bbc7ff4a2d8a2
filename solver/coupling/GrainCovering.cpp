// Which nodes the grains cover: clipped scan boxes, owner changes, swallowed and refilled fluid.
//
// A grain moves far less than a node per step, so from one step to the next it changes the owner
// of a thin ring of nodes only. Each row of its scan box is split at the chord of the disc: the
// nodes surely inside (one node clear of the circle) need only their owner read, and only the
// few nodes near the circle get the exact test |x - c| < r_h. Nodes change owner in grain order
// and, within a grain, row by row: the same order whatever the thread count. A grain at rest
// is not scanned at all: its last scan found how far it may move before any node can cross its
// circle (its quiet anchor), and until it has moved that far, or another grain takes one of its
// nodes, its nodes stay as they are.
#include "solver/coupling/BounceBackCoupling.h"

#include "solver/lattice/D2Q9.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lbdem::solver::coupling {

using lattice::equilibrium;
using lattice::kCx;
using lattice::kCy;
using lattice::kQ;

namespace {

constexpr std::int32_t kNone = -1, kJustUncovered = -2;

} // namespace

BounceBackCoupling::Box BounceBackCoupling::grainBox(std::size_t p) const {
    // A node is solid when its centre lies strictly inside r_h: these bounds hold every such node.
    Real cx, cy, r;
    grainGeometry(p, cx, cy, r);
    return clippedBox(cx, cy, r, 0);
}

void BounceBackCoupling::findGrainChanges(std::size_t p, std::vector<Change>& out) {
    Real cx, cy, r;
    grainGeometry(p, cx, cy, r);
    QuietAnchor& anchor = m_anchor[p];
    const Real mx = cx - anchor.cx, my = cy - anchor.cy;
    // Within reach of its anchor no node has crossed the grain's circle and no other grain has
    // taken one of its nodes (applyChanges drops the anchor of a grain that loses a node): the
    // scan would find nothing. (A centre that is not a number fails the comparison.)
    m_unmoved[p] = anchor.reach2 > 0 && r == anchor.r && mx * mx + my * my < anchor.reach2;
    if (m_unmoved[p]) return;
    // Scan the grain's box now and the box it had: nodes it covers but does not own, and nodes it
    // owns but no longer covers (all of them lie in the old box). Nothing is written but this
    // grain's anchor, so grains scan in parallel.
    const Box now = grainBox(p);
    Box scan = now;
    const Box& last = m_box[p];
    if (scan.i0 > scan.i1)
        scan = last;
    else if (last.i0 <= last.i1 && last.j0 <= last.j1) {
        scan.i0 = std::min(scan.i0, last.i0);
        scan.i1 = std::max(scan.i1, last.i1);
        scan.j0 = std::min(scan.j0, last.j0);
        scan.j1 = std::max(scan.j1, last.j1);
    }
    const int nx = m_lattice.nx(), ny = m_lattice.ny();
    // One period at most (a grain that just crossed a periodic side has boxes a period apart).
    if (m_periodicX && scan.i1 - scan.i0 >= nx) scan.i1 = scan.i0 + nx - 1;
    if (m_periodicY && scan.j1 - scan.j0 >= ny) scan.j1 = scan.j0 + ny - 1;
    const std::size_t before = out.size();
    Real closest = std::numeric_limits<Real>::infinity();
    for (int ju = scan.j0; ju <= scan.j1; ++ju) {
        int i = 0, j = ju;
        if (!wrapNode(i, j)) continue;
        Real dy = ju + m_originY - cy;
        if (m_periodicY) dy -= ny * std::round(dy / ny);
        scanRow(static_cast<std::int32_t>(p), ju, j, dy, scan.i0, scan.i1, cx, r, out, closest);
    }
    // The scan box may hold the old box only one node beyond the new one: quietReach2 bounds the
    // distances of the scanned nodes by that.
    const bool near = scan.i0 >= now.i0 - 1 && scan.i1 <= now.i1 + 1 && scan.j0 >= now.j0 - 1 &&
                      scan.j1 <= now.j1 + 1;
    anchor = {};
    if (out.size() == before && near) anchor = {cx, cy, r, quietReach2(cx, cy, r, now, closest)};
}

Real BounceBackCoupling::quietReach2(Real cx, Real cy, Real r, const Box& box, Real closest) const {
    // Only boxes one node clear of the lattice's edges: no clipping, no periodic images.
    if (box.i0 < 1 || box.j0 < 1 || box.i1 > m_lattice.nx() - 2 || box.j1 > m_lattice.ny() - 2)
        return -1;
    // Nodes outside the box lie beyond the next node past the circle's extent along an axis.
    const Real ci = cx - m_originX, cj = cy - m_originY;
    const Real outside = std::min({ci - r - (box.i0 - 1), box.i1 + 1 - (ci + r),
                                   cj - r - (box.j0 - 1), box.j1 + 1 - (cj + r)});
    // Scanned nodes: |d - r| = |d^2 - r^2| / (d + r), and within the box one node wider
    // d <= sqrt(2) (r + 2), so d + r < 2.5 r + 3.
    const Real scanned = closest / (2.5 * r + 3);
    // Half of it against rounding; at most kQuietReachMax, so that the nodes found at the anchor
    // still hold every surface node (findGrainSurface).
    const Real reach = std::min({0.5 * outside, 0.5 * scanned, kQuietReachMax});
    return reach > 0 ? reach * reach : -1; // NaN fails too
}

void BounceBackCoupling::forgetAnchors() {
    const std::size_t n = m_dem.particles().size();
    m_anchor.assign(n, QuietAnchor{});
    m_unmoved.assign(n, 0);
    m_grainSurface.resize(n);
}

void BounceBackCoupling::scanRow(std::int32_t id, int ju, int j, Real dy, int i0, int i1, Real cx,
                                 Real r, std::vector<Change>& out, Real& closest) const {
    const int nx = m_lattice.nx();
    const long long rowBase = m_lattice.index(0, j);
    // Nodes surely inside: at least one node inside the row's chord, so their distance to the
    // circle dwarfs any rounding (empty across a periodic x side, where every node is tested,
    // and for a centre that is not a number, which no comparison below would exclude).
    int in0 = i1 + 1, in1 = i1;
    if (!m_periodicX && dy * dy < r * r && std::isfinite(cx)) {
        const Real half = std::sqrt(r * r - dy * dy), centre = cx - m_originX;
        const Real lo = std::max(static_cast<Real>(i0), std::ceil(centre - half) + 1);
        const Real hi = std::min(static_cast<Real>(i1), std::floor(centre + half) - 1);
        if (lo <= hi) {
            in0 = static_cast<int>(lo), in1 = static_cast<int>(hi);
            // The farthest of them from the centre is one of the two ends.
            const Real ends = std::max(std::abs(in0 - centre), std::abs(in1 - centre));
            closest = std::min(closest, r * r - (ends * ends + dy * dy));
        }
    }
    for (int iu = i0; iu <= i1; ++iu) {
        long long c;
        bool geometric;
        if (iu >= in0 && iu <= in1) {
            c = rowBase + iu;
            geometric = true;
        } else {
            int i = iu, jw = j;
            if (!wrapNode(i, jw)) continue;
            c = rowBase + i;
            Real dx = iu + m_originX - cx;
            if (m_periodicX) dx -= nx * std::round(dx / nx);
            const Real d2 = dx * dx + dy * dy;
            geometric = d2 < r * r;
            closest = std::min(closest, std::abs(d2 - r * r));
        }
        const bool inside = geometric && m_lattice.isFluid(c);
        const std::int32_t owner = m_owner[c];
        if (inside && owner != id)
            out.push_back({c, id, iu, ju, true});
        else if (!inside && owner == id)
            out.push_back({c, id, iu, ju, false});
    }
}

void BounceBackCoupling::prefetchBox(const Box& box, bool flags) const {
    const int i0 = std::max(box.i0, 0), i1 = std::min(box.i1, m_lattice.nx() - 1);
    const int j0 = std::max(box.j0, 0), j1 = std::min(box.j1, m_lattice.ny() - 1);
    if (i0 > i1) return;
    for (int j = j0; j <= j1; ++j) {
        const long long row = m_lattice.index(0, j);
        prefetchLines(m_owner.data() + row, i0, i1);
        if (flags) prefetchLines(m_lattice.flags() + row, i0, i1);
    }
}

void BounceBackCoupling::findChanges() {
    const std::size_t n = m_dem.particles().size();
    collectPerGrain(m_threadChanges, [this, n](std::size_t p, std::vector<Change>& out) {
        // The rows of the next grain's last box arrive while this one is scanned: a grain's scan
        // otherwise waits on each of its rows in turn.
        if (p + 1 < n) prefetchBox(m_box[p + 1], true);
        findGrainChanges(p, out);
        m_box[p] = grainBox(p);
    });
}

void BounceBackCoupling::offsetFromCentre(int iu, int ju, Real cx, Real cy, Real& dx,
                                          Real& dy) const {
    dx = iu + m_originX - cx;
    dy = ju + m_originY - cy;
    if (m_periodicX) dx -= m_lattice.nx() * std::round(dx / m_lattice.nx());
    if (m_periodicY) dy -= m_lattice.ny() * std::round(dy / m_lattice.ny());
}

void BounceBackCoupling::applyChanges() {
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
            if (owner >= 0) { // taken from a grain of higher index: it must scan again
                m_anchor[owner] = QuietAnchor{};
                m_unmoved[owner] = 0;
            }
            if (owner == kNone && m_initialised) {
                // Fluid swallowed by the grain hands its momentum to it.
                Real cx, cy, r;
                grainGeometry(ch.grain, cx, cy, r);
                Real dx, dy;
                offsetFromCentre(ch.iu, ch.ju, cx, cy, dx, dy);
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

void BounceBackCoupling::refillUncovered() {
    // Refill (e.g. Peng et al. 2016): equilibrium at the mean density of the fluid neighbours and
    // the velocity of the surface that just left the node (coupling.refill = surface_equilibrium),
    // or the mean of the neighbours' populations, which carries their motion and stress
    // (neighbour_mean); the grain pays the new fluid's momentum either way.
    const bool neighbourMean = m_params.refill == RefillRule::NeighbourMean;
    for (const Change& c : m_uncovered) {
        if (m_owner[c.cell] != kJustUncovered) continue;
        Real rho = 0, mean[kQ] = {};
        int count = 0;
        for (int q = 1; q < kQ; ++q) {
            const long long nb = wrapCell(c.iu + kCx[q], c.ju + kCy[q]);
            if (nb < 0 || !m_lattice.isFluid(nb) || m_owner[nb] != kNone) continue;
            rho += m_lattice.density(nb);
            ++count;
            if (!neighbourMean) continue;
            long long slots[kQ];
            m_lattice.postSlots(nb, slots);
            for (int k = 0; k < kQ; ++k)
                mean[k] += m_lattice.population(slots[k], k);
        }
        rho = count > 0 ? rho / count : 1.0;
        Real cx, cy, r, ux, uy;
        grainGeometry(c.grain, cx, cy, r);
        // Wrapped or not, the offset to the centre is taken modulo the periodic length.
        Real dx, dy;
        offsetFromCentre(c.iu, c.ju, cx, cy, dx, dy);
        surfaceVelocity(c.grain, dx, dy, ux, uy);
        Real f[kQ];
        for (int q = 0; q < kQ; ++q)
            f[q] = neighbourMean && count > 0 ? mean[q] / count : equilibrium(q, rho, ux, uy);
        if (neighbourMean && count > 0) {
            Real jx = 0, jy = 0;
            for (int q = 1; q < kQ; ++q) {
                jx += kCx[q] * f[q];
                jy += kCy[q] * f[q];
            }
            m_loadX[c.grain] -= jx;
            m_loadY[c.grain] -= jy;
            m_loadT[c.grain] -= dx * jy - dy * jx;
        } else {
            m_loadX[c.grain] -= rho * ux;
            m_loadY[c.grain] -= rho * uy;
            m_loadT[c.grain] -= rho * (dx * uy - dy * ux);
        }
        long long slots[kQ];
        m_lattice.postSlots(c.cell, slots);
        for (int q = 0; q < kQ; ++q)
            m_lattice.setPopulation(slots[q], q, f[q]);
        m_solid[c.cell] = 0;
    }
    for (const Change& c : m_uncovered)
        if (m_owner[c.cell] == kJustUncovered) m_owner[c.cell] = kNone;
}

} // namespace lbdem::solver::coupling
