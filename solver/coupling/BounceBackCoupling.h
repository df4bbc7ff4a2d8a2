// Grains as moving solid nodes: covering and refilling nodes, Bouzidi moving-wall links and
// momentum exchange (the bounce-back coupling method).
#pragma once

#include "solver/core/HugePageAllocator.h"
#include "solver/core/OpenMp.h"
#include "solver/coupling/Coupling.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace lbdem::solver::coupling {

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
    /// Moving-wall links of the last mapGrains.
    std::size_t boundaryCount() const override { return m_linkCount; }
    /// Covered nodes grain by grain, tracking flag and the last step's loads.
    CouplingState state() const override;
    /// Restore the state written by state() (same lattice and grain count).
    void restore(const CouplingState& state) override;
    /// Follow dem.sortSpatially() in owners, scan boxes and the last step's loads.
    void renumberGrains(const std::vector<std::int32_t>& newToOld) override;
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
    /// the moving-wall links. (i, j) wrapped into the lattice, (sx, sy) from the grain's centre.
    struct SurfaceNode {
        long long cell;
        int i, j;
        std::int32_t grain;
        Real sx, sy;
    };
    /// What the links of one grain need: radius and surface motion, lattice units.
    struct GrainMotion {
        Real r, vx, vy, w;
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
    template <class Item, class Visit>
    void collectPerGrain(std::vector<std::vector<Item>>& lists, const Visit& visit);
    void findChanges();
    void findGrainChanges(std::size_t p, std::vector<Change>& out) const;
    /// Owner changes of the nodes iu in [i0, i1] of row (ju, wrapped row j) for grain p.
    void scanRow(std::int32_t p, int ju, int j, Real dy, int i0, int i1, Real cx, Real r,
                 std::vector<Change>& out) const;
    void applyChanges();
    void refillUncovered();
    /// The surface nodes of every grain, sorted row by row.
    void findSurfaceNodes();
    void findGrainSurface(std::size_t p, std::vector<SurfaceNode>& out) const;
    /// Reset every surface node and apply its links, visiting the nodes row by row (memory
    /// order); loads are summed per grain afterwards in grain order. Returns the link count.
    std::size_t linkSurfaceNodes();
    template <class S> std::size_t linkSurfaceNodesStored(S* stored);

    bool m_initialised = false;
    HugeVector<std::int32_t> m_owner; // per cell: grain covering it, -1 none, -2 just uncovered
    std::vector<Box> m_box;           // per grain: the box its nodes lie in
    std::vector<std::vector<Change>> m_threadChanges;      // per thread, grains in order
    std::vector<Change> m_uncovered;                       // nodes left by their grain this step
    std::vector<std::vector<SurfaceNode>> m_threadSurface; // per thread, grains in order
    std::vector<SurfaceNode> m_surface;   // surface nodes of all grains, row by row (grain order)
    std::vector<std::int32_t> m_rowStart; // counting sort of m_surface by row
    std::vector<int> m_prefetchSpan;   // per row: first and last column its links' rows may touch
    std::vector<Real> m_surfaceLoad;   // per surface node: (fx, fy, torque) of its links
    std::vector<GrainMotion> m_motion; // per grain, this step
    std::size_t m_linkCount = 0;       // links of the last mapGrains
    std::vector<Real> m_previousLoad;  // (fx, fy, torque) per grain of the step before
};

template <class Item, class Visit>
void BounceBackCoupling::collectPerGrain(std::vector<std::vector<Item>>& lists,
                                         const Visit& visit) {
    // Fewer grains than this are visited on one thread: a parallel region costs more than their
    // work.
    constexpr std::size_t kParallelGrains = 32;
    const std::size_t n = m_dem.particles().size();
    const int threads = n >= kParallelGrains ? std::max(ompMaxThreads(), 1) : 1;
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
