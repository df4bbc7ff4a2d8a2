// The time step: boundary passes, then the fused stream-collide kernel of the AA pattern.
#include "solver/lattice/Lattice.h"

#include "solver/core/FlushSubnormals.h"
#include "solver/core/OpenMp.h"

#include <type_traits>
#include <utility>

namespace lbdem::solver::lattice {

namespace {

/// Run row(y) once for every row y < ny, each thread first its share of the rows above `last`,
/// then its share of the rows 0..last: every thread ends in the rows up to `last`, which are then
/// the freshest in the shared cache (Lattice::setLastSweptRow). Static shares, as schedule(static).
/// With `flushSubnormals` (StoredPopulation::kFlushSubnormals) each thread reads and writes
/// subnormals as zero.
template <class Row>
void sweepRows(int ny, int last, bool parallel, bool flushSubnormals, const Row& row) {
#pragma omp parallel if (parallel)
    {
        const ScopedFlushSubnormals flush(flushSubnormals);
        const int threads = ompThreadCount(), t = ompThreadIndex();
        const int above = ny - 1 - last, band = last + 1;
        for (int y = last + 1 + above * t / threads; y < last + 1 + above * (t + 1) / threads; ++y)
            row(y);
        for (int y = band * t / threads; y < band * (t + 1) / threads; ++y)
            row(y);
    }
}

/// Collide the nine stored values g of one node in their own arithmetic: doubles are the
/// populations f_i, floats the deviations f_i - w_i (PopulationStorage), collided as such.
template <class S, class C> LBDEM_KERNEL_INLINE void collideStored(const C& collide, S* g) {
    collide.template apply<S, std::is_same_v<S, float>>(g);
}

/// One AA step over the stored values f (S: double, or float holding f_i - w_i, which is also the
/// arithmetic: no conversion on the way). Node x reads the nine populations that arrived and
/// writes its nine post-collision values f*_i back to the same nine places, owned by x alone, so
/// the update is in place and free of races between nodes, rows and threads:
///  - from an even step count (kStream false) they are its own slots: f_i arrived in slot i, f*_i
///    goes to slot opp(i);
///  - from an odd one (kStream true), f_i arrived in slot opp(i) of x - c_i, where that neighbour
///    left it, and f*_i goes to slot i of x + c_i (periodic wrap on all sides).
/// Written as q_i, the place f*_i goes, both read f_i from q_opp(i). Rows are swept in the order
/// of sweepRows.
/// Pre: the boundary passes have filled the slots that solid neighbours send into the fluid.
template <bool kStream, class S, class C>
void aaSweep(S* __restrict f, int nx, int ny, long long cells, int lastRow, const C& collide) {
    sweepRows(
        ny, lastRow, cells >= kParallelMinCells,
        StoredPopulation<S>::kFlushSubnormals, [&](int y) __attribute__((always_inline)) {
            const long long row = static_cast<long long>(y) * nx;
            long long rowN = row, rowS = row;
            if (kStream) {
                rowN = static_cast<long long>(y + 1 == ny ? 0 : y + 1) * nx;
                rowS = static_cast<long long>(y == 0 ? ny - 1 : y - 1) * nx;
            }
            // Slot of q_i: i after an odd step count, opp(i) after an even one.
            auto slot = [](int i, int opposite) { return kStream ? i : opposite; };
            S* __restrict q0 = f + row;
            S* __restrict q1 = f + slot(1, 3) * cells + row;
            S* __restrict q2 = f + slot(2, 4) * cells + rowN;
            S* __restrict q3 = f + slot(3, 1) * cells + row;
            S* __restrict q4 = f + slot(4, 2) * cells + rowS;
            S* __restrict q5 = f + slot(5, 7) * cells + rowN;
            S* __restrict q6 = f + slot(6, 8) * cells + rowN;
            S* __restrict q7 = f + slot(7, 5) * cells + rowS;
            S* __restrict q8 = f + slot(8, 6) * cells + rowS;
            // xm, xp: the columns of x - 1 and x + 1 (both x without streaming).
            auto node = [&](int x, int xm, int xp) __attribute__((always_inline)) {
                S g[9] = {q0[x], q3[xm], q4[x], q1[xp], q2[x], q7[xm], q8[xp], q5[xp], q6[xm]};
                collideStored(collide, g);
                q0[x] = g[0];
                q1[xp] = g[1];
                q2[x] = g[2];
                q3[xm] = g[3];
                q4[x] = g[4];
                q5[xp] = g[5];
                q6[xm] = g[6];
                q7[xm] = g[7];
                q8[xp] = g[8];
            };
            // Each node touches only its own values, so the loop carries no dependence.
            if (!kStream) {
#pragma omp simd
                for (int x = 0; x < nx; ++x)
                    node(x, x, x);
                return;
            }
            node(0, nx - 1, 1 % nx);
#pragma omp simd
            for (int x = 1; x < nx - 1; ++x)
                node(x, x - 1, x + 1);
            if (nx > 1) node(nx - 1, nx - 2, 0);
        });
}

/// One AA step of the bulk kernel on the stored values f, from an odd or an even step count.
template <class S, class C>
void aaStep(S* f, bool odd, int nx, int ny, long long cells, int lastRow, const C& collide) {
    if (odd)
        aaSweep<true>(f, nx, ny, cells, lastRow, collide);
    else
        aaSweep<false>(f, nx, ny, cells, lastRow, collide);
}

/// f[slot] = f[source] + add for every copy link, on the stored values: source and slot hold
/// directions of one weight, so float storage's shift cancels (Lattice::buildWallLinks).
template <class S, class Links>
void applyCopyLinks(S* f, const Links& links, long long parity, bool parallel) {
#pragma omp parallel for schedule(static) if (parallel)
    for (std::size_t k = 0; k < links.size(); ++k)
        f[links[k].slot[parity]] = static_cast<S>(f[links[k].source[parity]] + links[k].add);
}

} // namespace

void Lattice::applyLinks() {
    const long long parity = m_step & 1;
    const bool parallel = m_cells >= kParallelMinCells;
    if (m_setup.storage == PopulationStorage::Float)
        applyCopyLinks(m_f32.data(), m_copyLinks, parity, parallel);
    else
        applyCopyLinks(m_f64.data(), m_copyLinks, parity, parallel);
    // Constant pressure (anti-bounce-back, Ginzburg et al. 2008): f_in = -f_out + 2
    // f_in^eq,sym(rho_b, u).
    for (const auto& link : m_pressureLinks) {
        Real ux, uy;
        velocity(link.node, ux, uy);
        const int in = kOpposite[link.dir];
        const Real cu = kCx[in] * ux + kCy[in] * uy;
        const Real sym = kW[in] * link.rho * (1.0 + 4.5 * cu * cu - 1.5 * (ux * ux + uy * uy));
        // On the populations, not the stored values: the shift would not cancel in -f_out + 2 sym.
        setPopulation(inSlot(link.node, in), in,
                      -population(postSlot(link.node, link.dir), link.dir) + 2.0 * sym);
    }
    // Interpolated bounce-back, Bouzidi, Firdaouss & Lallemand (2001), linear two-branch form.
    for (const auto& link : m_obstacleLinks) {
        const int d = link.dir, in = kOpposite[d];
        const Real out = population(postSlot(link.node, d), d);
        Real value;
        if (link.q < 0.5 && link.interior)
            value = 2 * link.q * out +
                    (1 - 2 * link.q) * population(postSlot(neighbour(link.node, in), d), d);
        else if (link.q < 0.5)
            value = out;
        else
            value = out / (2 * link.q) +
                    (2 * link.q - 1) / (2 * link.q) * population(postSlot(link.node, in), in);
        setPopulation(inSlot(link.node, in), in, value);
    }
}

void Lattice::computeLoads() {
    for (auto& load : m_loads)
        load = ObstacleLoad{};
    for (const auto& link : m_obstacleLinks) {
        // Momentum exchange (Ladd 1994): the wall receives (f_out + f_in) c_out per link.
        const int d = link.dir, in = kOpposite[d];
        const Real push =
            population(postSlot(link.node, d), d) + population(inSlot(link.node, in), in);
        const Real dfx = push * kCx[d], dfy = push * kCy[d];
        const int i = static_cast<int>(link.node % m_nx), j = static_cast<int>(link.node / m_nx);
        const Real rx = nodeX(i) + link.q * kCx[d] - m_owners[link.owner].cx;
        const Real ry = nodeY(j) + link.q * kCy[d] - m_owners[link.owner].cy;
        ObstacleLoad& load = m_loads[link.owner];
        load.fx += dfx;
        load.fy += dfy;
        load.torque += rx * dfy - ry * dfx;
    }
}

void Lattice::applyZouHe() {
    // Zou & He (1997): the populations entering from outside follow from the known ones, the
    // imposed velocity (or density) and bounce-back of the non-equilibrium normal part. They are
    // written where the kernel will read them, and the kernel collides the node as any other.
    const SideCondition* sides[2] = {&m_setup.left, &m_setup.right};
    for (int s = 0; s < 2; ++s) {
        const SideCondition& side = *sides[s];
        const Real sign = s == 0 ? 1.0 : -1.0; // inward normal along x
        for (long long c : m_zouHeCells[s]) {
            Real f[kQ];
            for (int q = 0; q < kQ; ++q)
                f[q] = population(inSlot(c, q), q);
            // Known: rest, N, S and the three leaving the domain (W, NW, SW on the left).
            const int out = s == 0 ? 3 : 1, outN = s == 0 ? 6 : 5, outS = s == 0 ? 7 : 8;
            const Real tangential = f[0] + f[2] + f[4], leaving = f[out] + f[outN] + f[outS];
            Real rho, un; // un: velocity along the inward normal
            if (side.type == SideType::ZouHeVelocity) {
                const int row = static_cast<int>(c / m_nx) - m_ghostBottom;
                const Real ux = side.profile.empty() ? side.ux : side.profile.at(row);
                un = sign * ux;
                rho = (tangential + 2 * leaving) / (1 - un);
            } else {
                rho = side.rho;
                un = 1 - (tangential + 2 * leaving) / rho;
            }
            const int in = kOpposite[out], inN = kOpposite[outS], inS = kOpposite[outN];
            setPopulation(inSlot(c, in), in, f[out] + 2.0 / 3.0 * rho * un);
            setPopulation(inSlot(c, inN), inN, f[outS] - 0.5 * (f[2] - f[4]) + rho * un / 6.0);
            setPopulation(inSlot(c, inS), inS, f[outN] + 0.5 * (f[2] - f[4]) + rho * un / 6.0);
        }
    }
}

void Lattice::recordIncoming() {
    m_recorded.resize(m_recordedCells.size() * kQ); // keeps its capacity between steps
    for (std::size_t k = 0; k < m_recordedCells.size(); ++k)
        for (int q = 0; q < kQ; ++q)
            m_recorded[k * kQ + q] = population(inSlot(m_recordedCells[k], q), q);
}

template <class C> void Lattice::runStep(const C& collide) {
    applyLinks();
    if (!m_obstacleLinks.empty()) computeLoads();
    applyZouHe();
    recordIncoming();
    const int lastRow = m_lastSweptRow >= 0 && m_lastSweptRow < m_ny ? m_lastSweptRow : m_ny - 1;
    if (m_setup.storage == PopulationStorage::Float)
        aaStep(m_f32.data(), m_step & 1, m_nx, m_ny, m_cells, lastRow, collide);
    else
        aaStep(m_f64.data(), m_step & 1, m_nx, m_ny, m_cells, lastRow, collide);
    ++m_step;
    resetSolids();
}

void Lattice::step() {
    withCollision(m_setup.collision, m_setup.fx, m_setup.fy,
                  [this](const auto& collide) { runStep(collide); });
}

} // namespace lbdem::solver::lattice
