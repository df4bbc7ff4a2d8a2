// Grains as moving solid nodes: covering and refilling nodes, Bouzidi moving-wall links and
// momentum exchange (the bounce-back coupling method).
#pragma once

#include "solver/core/HugePageAllocator.h"
#include "solver/core/OpenMp.h"
#include "solver/coupling/Coupling.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace lbdem::solver::coupling {

/// Request, for reading, every cache line that holds base[first] .. base[last] (first <= last: a
/// span of one lattice row of owners or flags, which the grain passes read next).
template <class T> inline void prefetchLines(const T* base, int first, int last) {
    constexpr std::uintptr_t kLine = 64;
    const auto end = reinterpret_cast<std::uintptr_t>(base + last);
    for (auto at = reinterpret_cast<std::uintptr_t>(base + first) & ~(kLine - 1); at <= end;
         at += kLine)
        __builtin_prefetch(reinterpret_cast<const void*>(at), 0);
}

/// The bounce-back coupling: each grain owns the nodes inside its hydrodynamic radius, which are
/// solid to the fluid; its surface nodes carry the moving-wall links. Built by makeCoupling.
class BounceBackCoupling final : public Coupling {
public:
    /// Couple the lattice and the grains; allocates the per-cell arrays once.
    BounceBackCoupling(lattice::Lattice& lattice, dem::DemSystem& dem,
                       const CouplingParams& params);

    /// Hand the DEM the mean of this step's and the last step's load (see the definition for
    /// why).
    void collectForces() override;
    /// The open fluid neighbours of the last mapGrains' surface nodes, grain by grain.
    void linkedFluidCells(std::vector<long long>& out) const override;
    /// Moving-wall links of the last mapGrains.
    std::size_t boundaryCount() const override { return m_linkCount; }
    /// Covered nodes grain by grain, tracking flag and the last step's loads.
    CouplingState state() const override;
    /// Restore the state written by state() (same lattice and grain count).
    void restore(const CouplingState& state) override;
    /// Follow dem.sortSpatially() in owners, scan boxes and the last step's loads.
    void renumberGrains(const std::vector<std::int32_t>& newToOld) override;
    /// Grains whose nodes the last mapGrains kept without a scan (within their quiet reach).
    std::size_t unmovedGrains() const {
        return static_cast<std::size_t>(std::count(m_unmoved.begin(), m_unmoved.end(), 1));
    }
    /// Grain covering each cell at the last mapGrains (-1: none).
    const HugeVector<std::int32_t>& owners() const { return m_owner; }

private:
    /// A node whose owner changes this step: a grain covers it, or its grain leaves it.
    struct Change {
        long long cell;
        std::int32_t grain;
        int iu, ju;
        bool cover;
    };
    /// A covered node within 1.5 of its grain's surface: reset to the surface motion, source of
    /// the moving-wall links. (i, j) wrapped into the lattice, (iu, ju) unwrapped, (sx, sy) from
    /// the grain's centre.
    struct SurfaceNode {
        long long cell;
        int i, j, iu, ju;
        std::int32_t grain;
        bool inBand; // within kSurfaceBand of the circle this step (the rest of the list is kept)
        Real sx, sy;
    };
    /// Where a grain was when its last full scan found its covered nodes all its own and no other
    /// node inside it; `reach2` is the square of how far it may move from there before a node can
    /// cross its circle (half the smallest distance of a node to the circle, at most 0.08).
    struct QuietAnchor {
        Real cx = 0, cy = 0, r = 0, reach2 = -1; // reach2 < 0: no anchor, scan every step
    };
    /// What the links of one grain need: radius and surface motion, lattice units.
    struct GrainMotion {
        Real r, vx, vy, w;
    };
    /// Mass an interpolated link sent into fluid node `fluid` (lattice row `row`) beyond what
    /// halfway bounce-back would (see linkSurfaceNode); taken back from that node's rest
    /// population once no link reads it any more.
    struct LinkMassExcess {
        long long fluid;
        int row;
        Real excess;
    };
    /// A thread's link mass excess still waiting for readers: one list per fluid row, in a ring
    /// by row. Before the links of surface row j run, the rows up to j - 2 are settled, and those
    /// links reach rows j - 1 .. j + 1: at most three rows wait at once, fewer than kRows, so each
    /// list holds one row. The lists keep their length from step to step (the pass counts the
    /// filled part). Aligned to a cache line: no two threads' lists share one.
    struct alignas(64) PendingExcess {
        static constexpr int kRows = 4; // a power of two: the slot of row r is r & (kRows - 1)
        std::vector<LinkMassExcess> list[kRows];
        /// Append the first `used` entries of list[slot] to `out`.
        void appendTo(int slot, std::size_t used, std::vector<LinkMassExcess>& out) const {
            out.insert(out.end(), list[slot].begin(),
                       list[slot].begin() + static_cast<std::ptrdiff_t>(used));
        }
    };
    /// The loads of one surface node's links, for a grain whose sum an earlier thread's block
    /// began: added after the link pass, in list order.
    struct DeferredLoad {
        std::int32_t grain;
        Real fx, fy, torque;
    };
    /// Node access of the links of surface nodes near the lattice's edges (wrapping, flags and
    /// owners through the lattice and this coupling); defined with the links.
    struct EdgeAccess;

    /// Refill uncovered nodes, make covered nodes solid, write the moving-wall links and sum the
    /// exchanged momentum.
    void placeGrains() override;
    Box grainBox(std::size_t p) const;
    /// Offset of node (iu, ju) from the centre (cx, cy), taken modulo the periodic lengths.
    void offsetFromCentre(int iu, int ju, Real cx, Real cy, Real& dx, Real& dy) const;
    /// Fill lists[t] with visit(p, lists[t]) for the t-th static block of grains, one block per
    /// thread (one thread for few grains): read in thread order, the lists hold their items in
    /// grain order whatever the thread count.
    /// Threads of a loop over the grains: one for fewer than kParallelGrains.
    int grainThreads() const {
        return m_dem.particles().size() >= kParallelGrains ? std::max(ompMaxThreads(), 1) : 1;
    }
    template <class Item, class Visit>
    void collectPerGrain(std::vector<std::vector<Item>>& lists, const Visit& visit);
    void findChanges();
    /// Request the owner lines (and the flag lines with `flags`) of the rows of `box` (the part
    /// within the lattice), which the scan of a grain is about to read.
    void prefetchBox(const Box& box, bool flags) const;
    /// Owner changes of grain p: none without a scan when it is still within reach of its quiet
    /// anchor, otherwise a scan of its boxes (which sets or drops the anchor).
    void findGrainChanges(std::size_t p, std::vector<Change>& out);
    /// Owner changes of the nodes iu in [i0, i1] of row (ju, wrapped row j) for grain p; lowers
    /// `closest` to the smallest |d^2 - r^2| of a node of the row (d: its distance to the centre).
    void scanRow(std::int32_t p, int ju, int j, Real dy, int i0, int i1, Real cx, Real r,
                 std::vector<Change>& out, Real& closest) const;
    /// How far grain p (centre (cx, cy), radius r, box `box`) may move before a node crosses its
    /// circle, squared and halved against rounding, from the smallest |d^2 - r^2| of its scan;
    /// -1 where its box (one node wider) leaves the lattice.
    Real quietReach2(Real cx, Real cy, Real r, const Box& box, Real closest) const;
    /// Drop every grain's quiet anchor: after a restore, a renumbering or a new grain count.
    void forgetAnchors();
    void applyChanges();
    void refillUncovered();
    /// The surface nodes of every grain, sorted row by row.
    void findSurfaceNodes();
    void findGrainSurface(std::size_t p, std::vector<SurfaceNode>& out) const;
    /// Reset every surface node and apply its links, visiting the nodes row by row (memory
    /// order); each grain's loads sum in list order. Returns the link count.
    std::size_t linkSurfaceNodes();
    template <class S> std::size_t linkSurfaceNodesStored(S* stored);
    /// Return the pending excess (the first used[slot] entries of each list) of fluid rows up to
    /// `upTo` (the links of later rows read no further than upTo + 1): from the nodes of rows that
    /// only this thread's links touch (from firstRow + 2 on, clear of the lattice's edges) at once,
    /// the rest to `deferred`.
    template <class S>
    void settleMassExcess(S* stored, const PendingExcess& pending, std::size_t* used,
                          std::vector<LinkMassExcess>& deferred, int upTo, int firstRow) const;
    /// Take one link's excess back from its fluid node's rest population.
    template <class S> static void returnMassExcess(S* stored, const LinkMassExcess& e);

    /// Surface nodes lie within kSurfaceBand of the circle (every node with a fluid neighbour
    /// lies within sqrt(2) of it). A grain's list is found kQuietReachMax deeper, so that it still
    /// holds all of them while the grain moves within its quiet reach.
    static constexpr Real kSurfaceBand = 1.5;
    /// Fewer grains than this are visited on one thread: a parallel region costs more than their
    /// work.
    static constexpr std::size_t kParallelGrains = 32;
    /// The farthest a grain may move from its quiet anchor (see kSurfaceBand).
    static constexpr Real kQuietReachMax = 0.08;
    /// Whether a node at (sx, sy) from the centre of a circle of radius r lies within
    /// kSurfaceBand of it; stored in SurfaceNode::inBand. One explicit fused multiply-add, so
    /// that every place that inlines it rounds alike (fresh and kept lists agree to the bit).
    static bool inSurfaceBand(Real sx, Real sy, Real r) {
        const Real deep = r - kSurfaceBand;
        return !(deep > 0 && std::fma(sx, sx, sy * sy) < deep * deep);
    }

    bool m_initialised = false;
    HugeVector<std::int32_t> m_owner; // per cell: grain covering it, -1 none, -2 just uncovered
    std::vector<Box> m_box;           // per grain: the box its nodes lie in
    std::vector<std::vector<Change>> m_threadChanges; // per thread, grains in order
    std::vector<Change> m_uncovered;                  // nodes left by their grain this step
    std::vector<QuietAnchor> m_anchor;                // per grain: see QuietAnchor
    std::vector<std::uint8_t> m_unmoved; // per grain: 1 when this step kept its anchor's nodes
    std::vector<std::vector<SurfaceNode>> m_grainSurface; // per grain, row by row
    // Surface nodes of all grains, row by row (grain order): pointers into m_grainSurface, which
    // the sort places as 8 bytes each where copies took 48 (docs/performance.md).
    std::vector<const SurfaceNode*> m_surface;
    std::vector<std::int32_t> m_rowStart; // counting sort of m_surface by row
    std::vector<int> m_rowCursor;         // per block of grains and row: count, then next place
    std::vector<int> m_rowFirstColumn;    // per block of grains and row (block 0: merged)
    std::vector<int> m_rowLastColumn;     // per block of grains and row (block 0: merged)
    std::vector<int> m_prefetchSpan; // per row: first and last column its links' rows may touch
    std::vector<std::int32_t> m_grainFirstEntry; // per grain: its first place in m_surface
    std::vector<std::vector<DeferredLoad>> m_threadDeferredLoads; // per thread: for after the pass
    std::vector<std::vector<LinkMassExcess>> m_threadMassExcess;  // per thread: for after the pass
    std::vector<PendingExcess> m_threadPendingExcess;             // per thread: rows in reach
    std::vector<GrainMotion> m_motion;                            // per grain, this step
    std::size_t m_linkCount = 0;                                  // links of the last mapGrains
    std::vector<Real> m_previousLoad; // (fx, fy, torque) per grain of the step before
};

template <class Item, class Visit>
void BounceBackCoupling::collectPerGrain(std::vector<std::vector<Item>>& lists,
                                         const Visit& visit) {
    const std::size_t n = m_dem.particles().size();
    const int threads = grainThreads();
    if (lists.size() < static_cast<std::size_t>(threads)) lists.resize(threads);
    for (auto& list : lists)
        list.clear();
        // Static schedule: thread t takes the t-th block of grains.
#pragma omp parallel num_threads(threads) if (threads > 1)
    {
        std::vector<Item>& out = lists[ompThreadIndex()];
#pragma omp for schedule(static)
        for (long long p = 0; p < static_cast<long long>(n); ++p)
            visit(static_cast<std::size_t>(p), out);
    }
}

} // namespace lbdem::solver::coupling
