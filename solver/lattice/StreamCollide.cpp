// The time step: boundary link pass, fused pull stream-collide kernel, Zou-He nodes.
#include "solver/lattice/Lattice.h"

#include <cstdint>
#include <utility>

#if defined(__AVX512F__)
#include <immintrin.h>
#endif
#ifdef _OPENMP
#include <omp.h>
#endif

namespace lbdem::solver::lattice {

namespace {

/// Lattices whose two population sets exceed this stay in memory anyway; below it (a few
/// tens of MB, the size of a server's last-level cache) plain stores keep them in cache.
constexpr double kStreamingMinBytes = 64.0 * (1 << 20);

/// Copy n values to dst; with `streaming`, whole 64-byte lines go out as streaming stores.
/// The destination is not read again this step, so skipping the read-for-ownership
/// (write-allocate) of the two-lattice scheme saves 72 of its 216 bytes of memory traffic per
/// update. Only full lines are streamed: partial-line streaming stores were measured 30x slower.
inline void writeRow(Real* __restrict dst, const Real* __restrict src, int n, bool streaming) {
    if (!streaming) {
        for (int k = 0; k < n; ++k) dst[k] = src[k];
        return;
    }
#if defined(__AVX512F__)
    int k = 0;
    while (k < n && reinterpret_cast<std::uintptr_t>(dst + k) % 64 != 0) { dst[k] = src[k]; ++k; }
    for (; k + 8 <= n; k += 8) _mm512_stream_pd(dst + k, _mm512_loadu_pd(src + k));
    for (; k < n; ++k) dst[k] = src[k];
#else
    for (int k = 0; k < n; ++k) dst[k] = src[k];
#endif
}

/// Fused pull stream-collide over all rows: dst(x) = collide(src(x - c_i)), periodic wrap.
/// Pre: src holds post-collision populations of step t with the link slots of solid nodes
/// filled; post: dst holds the post-collision populations of step t + 1 at every node.
/// Loads are contiguous per direction and row (x fastest); the inner loop has no branches
/// and writes one row of results to a per-thread buffer (cache resident), which writeRow
/// then streams to memory.
template <class C>
void bulkKernel(const Real* __restrict src, Real* __restrict dst, int nx, int ny, long long cells,
                const C& collide, std::vector<Real>& scratch) {
    const bool streaming = 2.0 * 9 * sizeof(Real) * static_cast<double>(cells) > kStreamingMinBytes;
#pragma omp parallel if (cells >= kParallelMinCells)
    {
#ifdef _OPENMP
        Real* __restrict buffer = scratch.data() + static_cast<std::size_t>(omp_get_thread_num()) * 9 * nx;
#else
        Real* __restrict buffer = scratch.data();
#endif
#pragma omp for schedule(static)
        for (int y = 0; y < ny; ++y) {
            const long long row = static_cast<long long>(y) * nx;
            const long long rowS = static_cast<long long>((y + 1) % ny) * nx;      // pulls with cy = -1
            const long long rowN = static_cast<long long>((y - 1 + ny) % ny) * nx; // pulls with cy = +1
            const Real* __restrict s0 = src + row;
            const Real* __restrict s1 = src + cells + row;
            const Real* __restrict s2 = src + 2 * cells + rowN;
            const Real* __restrict s3 = src + 3 * cells + row;
            const Real* __restrict s4 = src + 4 * cells + rowS;
            const Real* __restrict s5 = src + 5 * cells + rowN;
            const Real* __restrict s6 = src + 6 * cells + rowN;
            const Real* __restrict s7 = src + 7 * cells + rowS;
            const Real* __restrict s8 = src + 8 * cells + rowS;
            auto node = [&](int x, int xm, int xp) {
                Real f[9] = {s0[x], s1[xm], s2[x], s3[xp], s4[x], s5[xm], s6[xp], s7[xp], s8[xm]};
                collide(f);
                for (int q = 0; q < 9; ++q) buffer[q * nx + x] = f[q];
            };
            node(0, nx - 1, 1 % nx);
#pragma omp simd
            for (int x = 1; x < nx - 1; ++x) node(x, x - 1, x + 1);
            if (nx > 1) node(nx - 1, nx - 2, 0);
            for (int q = 0; q < 9; ++q) writeRow(dst + q * cells + row, buffer + q * nx, nx, streaming);
        }
#if defined(__AVX512F__)
        _mm_sfence(); // streaming stores are weakly ordered: publish them before the barrier
#endif
    }
}

} // namespace

void Lattice::applyLinks() {
    Real* f = m_f.data();
    const long long cells = m_cells;
    const auto& copies = m_copyLinks;
#pragma omp parallel for schedule(static) if (cells >= kParallelMinCells)
    for (std::size_t k = 0; k < copies.size(); ++k) f[copies[k].slot] = f[copies[k].source] + copies[k].add;
    // Constant pressure (anti-bounce-back, Ginzburg et al. 2008): f_in = -f_out + 2 f_in^eq,sym(rho_b, u).
    for (const auto& link : m_pressureLinks) {
        Real ux, uy;
        velocity(link.node, ux, uy);
        const int in = kOpposite[link.dir];
        const Real cu = kCx[in] * ux + kCy[in] * uy;
        const Real sym = kW[in] * link.rho * (1.0 + 4.5 * cu * cu - 1.5 * (ux * ux + uy * uy));
        f[in * cells + neighbour(link.node, link.dir)] = -f[link.dir * cells + link.node] + 2.0 * sym;
    }
    // Interpolated bounce-back, Bouzidi, Firdaouss & Lallemand (2001), linear two-branch form.
    for (const auto& link : m_obstacleLinks) {
        const int d = link.dir, in = kOpposite[d];
        const Real out = f[d * cells + link.node];
        Real value;
        if (link.q < 0.5 && link.interior)
            value = 2 * link.q * out + (1 - 2 * link.q) * f[d * cells + neighbour(link.node, in)];
        else if (link.q < 0.5)
            value = out;
        else
            value = out / (2 * link.q) + (2 * link.q - 1) / (2 * link.q) * f[in * cells + link.node];
        f[in * cells + neighbour(link.node, d)] = value;
    }
}

void Lattice::computeLoads() {
    for (auto& load : m_loads) load = ObstacleLoad{};
    const Real* f = m_f.data();
    for (const auto& link : m_obstacleLinks) {
        // Momentum exchange (Ladd 1994): the wall receives (f_out + f_in) c_out per link.
        const int d = link.dir;
        const Real push = f[d * m_cells + link.node] + f[kOpposite[d] * m_cells + neighbour(link.node, d)];
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

template <class C>
void Lattice::runStep(const C& collide) {
    applyLinks();
    if (!m_obstacleLinks.empty()) computeLoads();
#ifdef _OPENMP
    const std::size_t scratch = static_cast<std::size_t>(omp_get_max_threads()) * kQ * m_nx;
#else
    const std::size_t scratch = static_cast<std::size_t>(kQ) * m_nx;
#endif
    if (m_rowScratch.size() < scratch) m_rowScratch.resize(scratch); // only when threads grow
    bulkKernel(m_f.data(), m_g.data(), m_nx, m_ny, m_cells, collide, m_rowScratch);
    // Zou & He (1997): the populations entering from outside follow from the known ones, the
    // imposed velocity (or density) and bounce-back of the non-equilibrium normal part.
    const SideCondition* sides[2] = {&m_setup.left, &m_setup.right};
    for (int s = 0; s < 2; ++s) {
        const auto& cellsOfSide = m_zouHeCells[s];
        const SideCondition& side = *sides[s];
        const Real sign = s == 0 ? 1.0 : -1.0; // inward normal along x
        for (long long c : cellsOfSide) {
            const int x = static_cast<int>(c % m_nx), y = static_cast<int>(c / m_nx);
            Real f[9];
            for (int q = 0; q < kQ; ++q)
                f[q] = m_f[q * m_cells + index((x - kCx[q] + m_nx) % m_nx, (y - kCy[q] + m_ny) % m_ny)];
            // Known: rest, N, S and the three leaving the domain (W, NW, SW on the left).
            const int out = s == 0 ? 3 : 1, outN = s == 0 ? 6 : 5, outS = s == 0 ? 7 : 8;
            const Real tangential = f[0] + f[2] + f[4], leaving = f[out] + f[outN] + f[outS];
            Real rho, un; // un: velocity along the inward normal
            if (side.type == SideType::ZouHeVelocity) {
                const int row = y - m_ghostBottom;
                const Real ux = side.profile.empty() ? side.ux : side.profile.at(row);
                un = sign * ux;
                rho = (tangential + 2 * leaving) / (1 - un);
            } else {
                rho = side.rho;
                un = 1 - (tangential + 2 * leaving) / rho;
            }
            const int in = kOpposite[out], inN = kOpposite[outS], inS = kOpposite[outN];
            f[in] = f[out] + 2.0 / 3.0 * rho * un;
            f[inN] = f[outS] - 0.5 * (f[2] - f[4]) + rho * un / 6.0;
            f[inS] = f[outN] + 0.5 * (f[2] - f[4]) + rho * un / 6.0;
            collide(f);
            for (int q = 0; q < kQ; ++q) m_g[q * m_cells + c] = f[q];
        }
    }
    resetSolids(m_g);
    std::swap(m_f, m_g);
    ++m_step;
}

void Lattice::step() {
    const CollisionParams& p = m_setup.collision;
    const Real fx = m_setup.fx, fy = m_setup.fy;
    const bool force = fx != 0 || fy != 0;
    const Real sNu = 1.0 / p.tau, c2x18 = 18.0 * p.smagorinsky * p.smagorinsky;
    // One dispatch per step: each branch runs a fully inlined kernel for one model.
    switch (p.model) {
    case CollisionModel::Bgk:
        if (force) runStep(BgkCollision<true>{sNu, fx, fy});
        else runStep(BgkCollision<false>{sNu, fx, fy});
        break;
    case CollisionModel::Mrt:
        if (force) runStep(MrtCollision<false, true>{sNu, p.s_e, p.s_eps, p.s_q, p.tau, c2x18, fx, fy});
        else runStep(MrtCollision<false, false>{sNu, p.s_e, p.s_eps, p.s_q, p.tau, c2x18, fx, fy});
        break;
    case CollisionModel::MrtLes:
        if (force) runStep(MrtCollision<true, true>{sNu, p.s_e, p.s_eps, p.s_q, p.tau, c2x18, fx, fy});
        else runStep(MrtCollision<true, false>{sNu, p.s_e, p.s_eps, p.s_q, p.tau, c2x18, fx, fy});
        break;
    }
}

} // namespace lbdem::solver::lattice
