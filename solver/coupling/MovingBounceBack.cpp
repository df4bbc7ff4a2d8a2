// Grains as moving solid nodes: covering, refilling, Bouzidi moving-wall links, momentum exchange.
//
// Per fluid step:
//   1. findChanges (parallel over grains, each writing only its own anchor): the nodes each grain
//      starts or stops covering, found in the ring it swept (GrainCovering.cpp);
//   2. applyChanges + refillUncovered (serial, cost ~ changed nodes): ownership, momentum of
//      swallowed and released fluid;
//   3. findSurfaceNodes (parallel over grains): each grain's covered nodes within 1.5 of its
//      surface, sorted by row (SurfaceNodes.cpp);
//   4. linkSurfaceNodes (parallel over rows): the surface nodes row by row, in memory order, so
//      that the populations of a few neighbouring rows serve every grain crossing them while they
//      are in cache (grain by grain, each lattice line was fetched again by every neighbouring
//      grain); each node with a fluid neighbour is reset to the equilibrium of the surface motion
//      and its moving-wall links applied, with their momentum exchange; each link's mass excess
//      over halfway bounce-back goes back to its fluid node's rest population once every link
//      reading that node has run.
// A surface node writes only its own populations and reads only fluid ones, so the nodes of pass 4
// are independent; their loads sum per grain in list order, and the mass returns reach each node
// in list order (any thread count).
#include "solver/coupling/BounceBackCoupling.h"

#include "solver/core/FlushSubnormals.h"
#include "solver/core/OpenMp.h"
#include "solver/coupling/DiscGeometry.h"
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

void BounceBackCoupling::placeGrains() {
    const std::size_t n = m_dem.particles().size();
    if (m_box.size() != n) m_box.assign(n, Box{});
    if (m_anchor.size() != n) forgetAnchors();
    findChanges();
    applyChanges();
    refillUncovered();
    findSurfaceNodes();
    m_linkCount = linkSurfaceNodes();
    m_initialised = true;
}

namespace {

/// Node access of the links of a surface node at least two nodes from every edge of the lattice:
/// neighbours at fixed offsets, populations straight from the stored values S at the parity's
/// slot offsets (Lattice::postSlotOffset). Nothing here wraps, divides or branches on storage.
template <class S> struct InteriorAccess {
    S* f;
    const std::uint8_t* flags;
    const std::int32_t* owner;
    long long slot[kQ];   // postSlot(cell, q) = cell + slot[q]
    long long offset[kQ]; // the node at cell + c_q

    long long neighbour(long long cell, int dir) const { return cell + offset[dir]; }
    /// Fluid and covered by no grain.
    bool open(long long cell) const {
        return flags[cell] == lattice::Lattice::kFluid && owner[cell] < 0;
    }
    Real get(long long cell, int dir) const {
        return lattice::StoredPopulation<S>::load(f[cell + slot[dir]], kW[dir]);
    }
    void set(long long cell, int dir, Real v) const {
        f[cell + slot[dir]] = lattice::StoredPopulation<S>::store(v, kW[dir]);
    }
};

/// Reset the surface node `cell` (offset (sx, sy) from the centre of a grain of radius r moving
/// with (vx, vy, w), lattice units) to the equilibrium of its surface motion, then apply its
/// moving-wall links; adds their momentum exchange to the loads and returns their count.
///
/// Interpolated moving-wall bounce-back (Bouzidi, Firdaouss & Lallemand 2001; wall-velocity term
/// of Lallemand & Luo 2003), with f_out leaving fluid node x_f along c (into the grain):
///   q <  1/2: f_in(x_f) = 2q f_out(x_f) + (1 - 2q) f_out(x_f - c) + 6 w rho c_in.u_w
///   q >= 1/2: f_in(x_f) = f_out/(2q) + (2q - 1)/(2q) f_in^post(x_f) + 3 w rho c_in.u_w / q
/// u_w = u_p + omega x r at the wall point x_f + q c. The value is stored where the next step
/// reads the population arriving at x_f along c_in: the solid node's post-collision slot.
/// Momentum exchange, Galilean invariant (Wen et al. 2014): dP = (c - u_w) f_out - (c_in - u_w)
/// f_in, on the excess populations f - w rho_0 (rho_0 = 1, the fluid at rest): the rest state's
/// share 2 w rho_0 c integrates to zero over a closed wetted surface (each lattice line enters
/// and leaves it), but where the surface faces another grain or a wall and has no link, it
/// would leave a pull of the absolute pressure rho_0 c_s^2 on the open side. Subtracting it
/// makes an unwetted part of a surface contribute nothing (the verify case near-contact).
///
/// Mass: the interpolations return value = out + moving + excess, where halfway bounce-back
/// (value = out + moving) gives back exactly the mass that left plus the wall's displacement.
/// The excess is small in open fluid, but in a pore that grains and a wall seal off (the gaps
/// between hydrodynamic discs are about a node or less at d_min/h = 6) it accumulated: a sealed
/// pore of the dense 5 deg column drained to rho = 0.14 in 4.6 tau_c, its suction pressed two
/// floor grains together with 400 times their buoyant weight, and the run diverged
/// (docs/coupling-methods.md, "Mass in sealed pores"). Each link's excess is appended to
/// `massExcess` and later taken from the fluid node's rest population, which carries no momentum:
/// the momentum exchange and the interpolated wall stay as they are, and the links conserve mass.
template <class Access, class ExcessList>
int linkSurfaceNode(const Access& a, long long cell, Real sx, Real sy, Real r, Real vx, Real vy,
                    Real w, Real& loadX, Real& loadY, Real& loadT, ExcessList& massExcess) {
    // The surface node holds the equilibrium of the surface motion (finite values for the
    // branch-free bulk kernel, a meaningful velocity in snapshots), except in the slots its fluid
    // neighbours read, which its links write.
    unsigned open = 0; // bit `back`: the node at cell + c_back is fluid that no grain covers
    for (int back = 1; back < kQ; ++back) {
        const long long fluid = a.neighbour(cell, back);
        if (fluid >= 0 && a.open(fluid)) open |= 1u << back;
    }
    const Real sux = vx - w * sy, suy = vy + w * sx;
    for (int q = 0; q < kQ; ++q)
        if (!(open >> q & 1u)) a.set(cell, q, equilibrium(q, 1.0, sux, suy));
    if (open == 0) return 0;
    // The wall fractions of all eight directions in one branch-free loop: their square roots
    // overlap (or share a vector) where each link waited on its own; links 2.94 -> 2.70 ms per
    // step on the paper case (docs/performance.md).
    Real wallFraction[kQ];
    for (int back = 1; back < kQ; ++back) // along c_toward = -c_back from x_f = solid + c_back
        wallFraction[back] =
            linkWallFraction(sx + kCx[back], sy + kCy[back], -kCx[back], -kCy[back], r);
    int links = 0;
    // The open directions in turn, lowest first: a loop exit to predict instead of a branch per
    // direction (links 2.33-2.43 -> 2.25-2.28 ms per step on the paper case).
    for (unsigned left = open; left != 0; left &= left - 1) {
        const int back = __builtin_ctz(left); // fluid node x_f = solid + c_back
        const long long fluid = a.neighbour(cell, back);
        const int toward = kOpposite[back];
        const Real px = sx + kCx[back], py = sy + kCy[back];
        const Real q = wallFraction[back];
        const Real rx = px + q * kCx[toward], ry = py + q * kCy[toward];
        const Real out = a.get(fluid, toward);
        Real rho = 0;
        for (int k = 0; k < kQ; ++k)
            rho += a.get(fluid, k);
        const Real ux = vx - w * ry, uy = vy + w * rx;
        const Real moving = 6.0 * kW[back] * rho * (kCx[back] * ux + kCy[back] * uy);
        Real value;
        const long long behind = q < 0.5 ? a.neighbour(fluid, back) : -1; // x_f - c
        if (behind >= 0 && a.open(behind))
            value = 2 * q * out + (1 - 2 * q) * a.get(behind, toward) + moving;
        else if (q < 0.5)
            value = out + moving;
        else
            value = (out + (2 * q - 1) * a.get(fluid, back) + moving) / (2 * q);
        a.set(cell, back, value);
        const Real extraMass = value - (out + moving);
        if (extraMass != 0) massExcess.add(fluid, back, extraMass);
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

/// Where linkSurfaceNode leaves each link's excess mass: the thread's pending list of the fluid
/// node's lattice row (that of the surface node plus the link's c_y; outside the lattice where it
/// wraps, which settleMassExcess treats as an edge row). With a list per row, settling a row
/// touches its own entries only, where one list for all rows was scanned whole on every row (the
/// grain mapping of the paper case ran a tenth faster, docs/performance.md). The lists only grow,
/// on a cold path, so that a link's append is a compare and a store: push_back, which the compiler
/// left out of line, took 2.5 % of a paper run's samples beside the link pass's 13 %.
template <class Pending> struct ExcessCollector {
    Pending* pending;
    std::size_t used[Pending::kRows] = {}; // on the thread's stack: written by every add
    int surfaceRow = 0;
    bool enabled = true; // false: the links keep their excess (coupling.link_mass_correction)
    void add(long long fluid, int back, Real excess) {
        if (!enabled) return;
        const int row = surfaceRow + kCy[back];
        const int slot = row & (Pending::kRows - 1);
        auto& list = pending->list[slot];
        if (used[slot] == list.size()) list.resize(2 * used[slot] + 256);
        list[used[slot]++] = {fluid, row, excess};
    }
};

/// Requests, a few lines at a time, the lines of one lattice row that the links of the rows
/// around it will read: the nine population arrays over the row's prefetch span. Spread over
/// the surface nodes of the row being linked, a share per node, the grain mapping ran about
/// 17 % faster than with all of them issued on entering the row (docs/performance.md). The
/// row's flags and owners over the span, which every open test reads and which are few lines,
/// are requested on entering the row.
template <class S> class RowPrefetcher {
public:
    RowPrefetcher(const S* stored, const std::int32_t* owner, const lattice::Lattice& lattice,
                  const int* span)
        : m_stored(stored), m_owner(owner), m_lattice(lattice), m_span(span) {}

    /// Request what is left of the last row, then aim at `row` (none beyond the lattice or
    /// without links near it), spreading its lines over `nodes` calls of next().
    void aim(int row, long long nodes) {
        next(m_left);
        m_q = kQ;
        if (row >= m_lattice.ny() || m_span[2 * row + 1] < 0) return;
        m_first = m_span[2 * row];
        m_last = m_span[2 * row + 1];
        const long long rowStart = m_lattice.index(0, row);
        prefetchLines(m_owner + rowStart, m_first, m_last);
        prefetchLines(m_lattice.flags() + rowStart, m_first, m_last);
        m_row = m_stored + rowStart;
        m_q = 0;
        m_i = m_first;
        m_left = kQ * ((m_last - m_first) / kPerLine + 1);
        m_perNode = static_cast<int>((m_left + nodes - 1) / std::max(nodes, 1LL));
    }
    /// Request the next share of the row's lines (one surface node's).
    void next() { next(m_perNode); }

private:
    static constexpr int kPerLine = 64 / static_cast<int>(sizeof(S));
    void next(long long count) {
        for (; count > 0 && m_q < kQ; --count, --m_left) {
            __builtin_prefetch(m_row + m_q * m_lattice.cells() + m_i, 1);
            m_i += kPerLine;
            if (m_i > m_last) ++m_q, m_i = m_first;
        }
    }

    const S* m_stored;
    const std::int32_t* m_owner;
    const lattice::Lattice& m_lattice;
    const int* m_span; // per row: first and last column (BounceBackCoupling::m_prefetchSpan)
    const S* m_row = nullptr;
    int m_first = 0, m_last = -1, m_q = kQ, m_i = 0, m_perNode = 0;
    long long m_left = 0; // lines of the aimed row not yet requested
};

} // namespace

/// Node access through the lattice's own accessors, wrapping across periodic sides: for surface
/// nodes within two nodes of an edge of the lattice.
struct BounceBackCoupling::EdgeAccess {
    const BounceBackCoupling& c;
    lattice::Lattice& lattice;

    long long neighbour(long long cell, int dir) const {
        const int nx = lattice.nx();
        return c.wrapCell(static_cast<int>(cell % nx) + kCx[dir],
                          static_cast<int>(cell / nx) + kCy[dir]);
    }
    bool open(long long cell) const { return lattice.isFluid(cell) && c.m_owner[cell] < 0; }
    Real get(long long cell, int dir) const {
        return lattice.population(lattice.postSlot(cell, dir), dir);
    }
    void set(long long cell, int dir, Real v) const {
        lattice.setPopulation(lattice.postSlot(cell, dir), dir, v);
    }
};

void BounceBackCoupling::linkedFluidCells(std::vector<long long>& out) const {
    for (const SurfaceNode* node : m_surface)
        for (int back = 1; back < kQ; ++back) {
            const long long fluid = wrapCell(node->iu + kCx[back], node->ju + kCy[back]);
            if (fluid >= 0 && m_lattice.isFluid(fluid) && m_owner[fluid] < 0) out.push_back(fluid);
        }
}

std::size_t BounceBackCoupling::linkSurfaceNodes() {
    return m_lattice.storage() == lattice::PopulationStorage::Float
               ? linkSurfaceNodesStored(m_lattice.storedFloats())
               : linkSurfaceNodesStored(m_lattice.storedDoubles());
}

template <class S> std::size_t BounceBackCoupling::linkSurfaceNodesStored(S* stored) {
    constexpr int kPrefetchRows = 5;     // the links of row j touch rows j - 2 .. j + 2
    constexpr long long kNodesAhead = 8; // m_surface points into the grains' lists: requested ahead
    InteriorAccess<S> interior{stored, m_lattice.flags(), m_owner.data(), {}, {}};
    for (int q = 0; q < kQ; ++q) {
        interior.slot[q] = m_lattice.postSlotOffset(q);
        interior.offset[q] = kCx[q] + static_cast<long long>(kCy[q]) * m_lattice.nx();
    }
    const EdgeAccess edge{*this, m_lattice};
    const int nx = m_lattice.nx(), ny = m_lattice.ny();
    const auto count = static_cast<long long>(m_surface.size());
    std::size_t links = 0;
    // Static schedule over the row-sorted list: each thread takes a band of rows. While it links
    // the nodes of a row, it requests the lines that the links kPrefetchRows rows further on will
    // need, a share per node, so that the loads overlap instead of waiting one by one.
    // Each link's excess mass goes back to its fluid node's rest population once every link that
    // reads that node (those of the surface rows beside it) has run, while the row is in cache,
    // by the one thread whose links touch it; rows two threads share wait for a serial pass.
    // Either way a node's returns come in list order after all its readers: the same bits on
    // any thread count as returning everything after the pass.
    const int threads = count >= kParallelMin ? ompMaxThreads() : 1;
    // The pending lists keep their length from step to step (ExcessCollector counts the used
    // part); the deferred ones start empty.
    const auto perThread = static_cast<std::size_t>(threads);
    if (m_threadMassExcess.size() < perThread) m_threadMassExcess.resize(perThread);
    if (m_threadPendingExcess.size() < perThread) m_threadPendingExcess.resize(perThread);
    if (m_threadDeferredLoads.size() < perThread) m_threadDeferredLoads.resize(perThread);
    for (auto& list : m_threadMassExcess)
        list.clear();
    for (auto& list : m_threadDeferredLoads)
        list.clear();
    // Each grain's loads sum in list order, which the static schedule splits into the threads'
    // blocks in thread order. The thread whose block holds a grain's first surface node adds
    // that grain's loads at once, alone: no earlier block has any, later blocks defer theirs.
    // The deferred loads follow in thread order after the pass: the same additions in the same
    // order as one thread's.
    const std::int32_t* firstEntry = m_grainFirstEntry.data();
#pragma omp parallel num_threads(threads) reduction(+ : links) if (threads > 1)
    {
        const ScopedFlushSubnormals flush(lattice::StoredPopulation<S>::kFlushSubnormals);
        RowPrefetcher<S> prefetch(stored, m_owner.data(), m_lattice, m_prefetchSpan.data());
        auto& deferred = m_threadMassExcess[ompThreadIndex()];
        auto& pending = m_threadPendingExcess[ompThreadIndex()];
        auto& deferredLoads = m_threadDeferredLoads[ompThreadIndex()];
        ExcessCollector<PendingExcess> massExcess{&pending};
        massExcess.enabled = m_params.link_mass_correction;
        bool aimed = false;       // at the row kPrefetchRows beyond this thread's current row
        int firstRow = 0;         // of this thread's block
        long long blockStart = 0; // its first place in the list
#pragma omp for schedule(static)
        for (long long k = 0; k < count; ++k) {
            if (k + kNodesAhead < count) __builtin_prefetch(m_surface[k + kNodesAhead], 0);
            const SurfaceNode& node = *m_surface[k];
            if (!aimed || node.j != m_surface[k - 1]->j) {
                prefetch.aim(node.j + kPrefetchRows, m_rowStart[node.j + 1] - k);
                if (!aimed) firstRow = node.j, blockStart = k;
                aimed = true;
                settleMassExcess(stored, pending, massExcess.used, deferred, node.j - 2, firstRow);
                massExcess.surfaceRow = node.j;
            }
            prefetch.next();
            const GrainMotion& m = m_motion[node.grain];
            Real loadX = 0, loadY = 0, loadT = 0;
            // Fluid neighbours lie one node away, the nodes behind them two.
            const bool inner = node.i >= 2 && node.i < nx - 2 && node.j >= 2 && node.j < ny - 2;
            links += inner ? linkSurfaceNode(interior, node.cell, node.sx, node.sy, m.r, m.vx, m.vy,
                                             m.w, loadX, loadY, loadT, massExcess)
                           : linkSurfaceNode(edge, node.cell, node.sx, node.sy, m.r, m.vx, m.vy,
                                             m.w, loadX, loadY, loadT, massExcess);
            const std::int32_t g = node.grain;
            if (firstEntry[g] >= blockStart)
                addLoad(g, loadX, loadY, loadT);
            else
                deferredLoads.push_back({g, loadX, loadY, loadT});
        }
        // The last rows' nodes may be read by the next thread's links.
        for (int slot = 0; slot < PendingExcess::kRows; ++slot)
            pending.appendTo(slot, massExcess.used[slot], deferred);
    }
    for (const auto& list : m_threadDeferredLoads)
        for (const DeferredLoad& d : list)
            addLoad(d.grain, d.fx, d.fy, d.torque);
    // The static schedule gave thread t the t-th block of the surface list: the lists in thread
    // order keep each node's returns in list order.
    for (const auto& list : m_threadMassExcess)
        for (const LinkMassExcess& e : list)
            returnMassExcess(stored, e);
    return links;
}

template <class S>
void BounceBackCoupling::settleMassExcess(S* stored, const PendingExcess& pending,
                                          std::size_t* used, std::vector<LinkMassExcess>& deferred,
                                          int upTo, int firstRow) const {
    // Fluid rows within kEdgeRows of the lattice's edges may be linked across a periodic side.
    constexpr int kEdgeRows = 3;
    const int lastOwn = m_lattice.ny() - kEdgeRows;
    // Each list holds one row, its entries in list order: a node's returns keep that order.
    for (int slot = 0; slot < PendingExcess::kRows; ++slot) {
        if (used[slot] == 0) continue;
        const std::vector<LinkMassExcess>& list = pending.list[slot];
        const int row = list[0].row;
        if (row > upTo) continue;
        if (row >= firstRow + 2 && row >= kEdgeRows && row < lastOwn)
            for (std::size_t n = 0; n < used[slot]; ++n)
                returnMassExcess(stored, list[n]);
        else
            pending.appendTo(slot, used[slot], deferred);
        used[slot] = 0;
    }
}

template <class S> void BounceBackCoupling::returnMassExcess(S* stored, const LinkMassExcess& e) {
    // The rest population f_0 of a node sits at the node itself at either parity.
    static_assert(kCx[0] == 0 && kCy[0] == 0 && kOpposite[0] == 0);
    using Stored = lattice::StoredPopulation<S>;
    S& f0 = stored[e.fluid];
    f0 = Stored::store(Stored::load(f0, kW[0]) - e.excess, kW[0]);
}

} // namespace lbdem::solver::coupling
