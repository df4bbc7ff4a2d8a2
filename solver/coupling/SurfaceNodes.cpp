// Surface nodes of the moving bounce-back coupling: each grain's covered nodes within
// kSurfaceBand of its circle (kept from the last step for a grain still within reach of its quiet
// anchor), then all of them counting-sorted by row for the row-by-row link pass
// (MovingBounceBack.cpp).
#include "solver/coupling/BounceBackCoupling.h"

#include "solver/core/OpenMp.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lbdem::solver::coupling {

void BounceBackCoupling::findSurfaceNodes() {
    const auto& g = m_dem.particles();
    const std::size_t n = g.size();
    const Real scale = m_params.dt / m_params.h;
    m_motion.resize(n);
    for (std::size_t p = 0; p < n; ++p) {
        Real cx, cy, r;
        grainGeometry(p, cx, cy, r);
        // u_w = (vx - w r_y, vy + w r_x), lattice units
        m_motion[p] = {r, g.vx[p] * scale, g.vy[p] * scale, g.omega[p] * m_params.dt};
    }
    // A grain that kept its anchor's nodes keeps the nodes found there (kQuietReachMax): only
    // their offsets from its centre are new. Then a counting sort by row, stable: row by
    // row, and within a row in grain order. Each thread counts and places the nodes of the same
    // static block of grains (two static loops over the same range share their blocks), and its
    // place in a row follows the counts of the blocks before it: the order of one thread.
    const int nx = m_lattice.nx(), ny = m_lattice.ny();
    const int threads = grainThreads();
    const std::size_t rows = static_cast<std::size_t>(ny);
    m_rowCursor.assign(threads * rows, 0);
    m_rowFirstColumn.assign(threads * rows, nx);
    m_rowLastColumn.assign(threads * rows, -1);
    m_rowStart.assign(rows + 1, 0);
    m_prefetchSpan.assign(2 * rows, -1);
#pragma omp parallel num_threads(threads) if (threads > 1)
    {
        const std::size_t t = static_cast<std::size_t>(ompThreadIndex());
        int* count = &m_rowCursor[t * rows];
        int* first = &m_rowFirstColumn[t * rows];
        int* last = &m_rowLastColumn[t * rows];
#pragma omp for schedule(static)
        for (long long p = 0; p < static_cast<long long>(n); ++p) {
            std::vector<SurfaceNode>& list = m_grainSurface[p];
            // The owners of the next grain's rows arrive while this one is handled.
            if (p + 1 < static_cast<long long>(n) && !m_unmoved[p + 1])
                prefetchBox(m_box[p + 1], false);
            if (m_unmoved[p]) {
                Real cx, cy, radius;
                grainGeometry(static_cast<std::size_t>(p), cx, cy, radius);
                for (SurfaceNode& node : list) {
                    node.sx = node.iu + m_originX - cx;
                    node.sy = node.ju + m_originY - cy;
                    node.inBand = inSurfaceBand(node.sx, node.sy, radius);
                }
            } else {
                list.clear();
                findGrainSurface(static_cast<std::size_t>(p), list);
            }
            for (const SurfaceNode& node : list) {
                if (!node.inBand) continue;
                ++count[node.j];
                first[node.j] = std::min(first[node.j], node.i);
                last[node.j] = std::max(last[node.j], node.i);
            }
        }
#pragma omp single
        {
            // Row starts, each block's cursor within its row, and per row the columns within
            // two rows of its surface nodes, which its links may touch (prefetched).
            for (std::size_t j = 0; j < rows; ++j) {
                int at = m_rowStart[j];
                for (std::size_t b = 0; b < static_cast<std::size_t>(threads); ++b) {
                    const int c = m_rowCursor[b * rows + j];
                    m_rowCursor[b * rows + j] = at;
                    at += c;
                    m_rowFirstColumn[j] =
                        std::min(m_rowFirstColumn[j], m_rowFirstColumn[b * rows + j]);
                    m_rowLastColumn[j] =
                        std::max(m_rowLastColumn[j], m_rowLastColumn[b * rows + j]);
                }
                m_rowStart[j + 1] = at;
            }
            for (int j = 0; j < ny; ++j) {
                int lo = nx, hi = -1;
                for (int k = std::max(j - 2, 0); k <= std::min(j + 2, ny - 1); ++k)
                    lo = std::min(lo, m_rowFirstColumn[k]), hi = std::max(hi, m_rowLastColumn[k]);
                if (hi < 0) continue; // no surface node within two rows: stays -1, no prefetch
                m_prefetchSpan[2 * j] = std::max(lo - 2, 0);
                m_prefetchSpan[2 * j + 1] = std::min(hi + 2, nx - 1);
            }
            m_surface.resize(static_cast<std::size_t>(m_rowStart[ny]));
            m_grainFirstEntry.resize(n);
        }
        int* cursor = &m_rowCursor[t * rows];
#pragma omp for schedule(static)
        for (long long p = 0; p < static_cast<long long>(n); ++p) {
            // A grain's nodes keep their order within a row, but across a periodic side in y its
            // later rows come first: its first place is the least.
            std::int32_t first = std::numeric_limits<std::int32_t>::max();
            for (const SurfaceNode& node : m_grainSurface[p])
                if (node.inBand) {
                    const int at = cursor[node.j]++;
                    m_surface[at] = &node;
                    first = std::min(first, at);
                }
            m_grainFirstEntry[p] = first;
        }
    }
}

void BounceBackCoupling::findGrainSurface(std::size_t p, std::vector<SurfaceNode>& out) const {
    Real cx, cy, r;
    grainGeometry(p, cx, cy, r);
    const Box& box = m_box[p];
    const auto id = static_cast<std::int32_t>(p);
    // Only nodes within 1.5 of the surface: deeper ones have all eight neighbours covered, so
    // nothing they hold reaches the fluid (they keep near the equilibrium of the grain's motion
    // by themselves: the surface nodes around them are reset every step). Kept a little deeper,
    // to kSurfaceBand + kQuietReachMax, so that the list still holds every surface node after
    // the grain has moved within its quiet reach; inBand marks those of this step.
    const Real deep = r - kSurfaceBand - kQuietReachMax;
    const Real centreI = cx - m_originX;
    for (int ju = box.j0; ju <= box.j1; ++ju) {
        const Real sy = ju + m_originY - cy;
        if (sy * sy >= r * r) continue; // no node of this row is inside (exact: dx^2 >= 0)
        // The row's chord, one node wider on each side against rounding; the owner decides.
        // (Bounds are clipped to the box as Real: no conversion of an out-of-range value.)
        const Real half = std::sqrt(r * r - sy * sy);
        const int lo =
            static_cast<int>(std::max(static_cast<Real>(box.i0), std::floor(centreI - half)));
        const int hi =
            static_cast<int>(std::min(static_cast<Real>(box.i1), std::ceil(centreI + half)));
        // Nodes surely deeper than `deep`, one node narrower on each side against rounding.
        int deepLo = hi + 1, deepHi = hi;
        if (deep > 0 && sy * sy < deep * deep) {
            const Real deepHalf = std::sqrt(deep * deep - sy * sy);
            const Real dl = std::max(static_cast<Real>(lo), std::ceil(centreI - deepHalf) + 1);
            const Real dh = std::min(static_cast<Real>(hi), std::floor(centreI + deepHalf) - 1);
            if (dl <= dh) deepLo = static_cast<int>(dl), deepHi = static_cast<int>(dh);
        }
        for (int iu = lo; iu <= hi; ++iu) {
            if (iu == deepLo) iu = deepHi + 1;
            if (iu > hi) break;
            int i = iu, j = ju;
            if (!wrapNode(i, j)) continue;
            const long long cell = m_lattice.index(i, j);
            if (m_owner[cell] != id) continue;
            const Real sx = iu + m_originX - cx;
            if (deep > 0 && sx * sx + sy * sy < deep * deep) continue;
            out.push_back({cell, i, j, iu, ju, id, inSurfaceBand(sx, sy, r), sx, sy});
        }
    }
}

} // namespace lbdem::solver::coupling
