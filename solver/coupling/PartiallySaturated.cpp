// Partially saturated cells (Noble & Torczynski 1998): solid fractions, weighted solid collision,
// loads.
#include "solver/coupling/PsmCoupling.h"

#include "solver/core/InputError.h"
#include "solver/coupling/DiscGeometry.h"
#include "solver/lattice/Collision.h"
#include "solver/lattice/D2Q9.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace lbdem::solver::coupling {

// The cells' collision works in the lattice's own terms throughout (velocity set, equilibrium,
// operators and their dispatch).
using namespace lattice;

PsmCoupling::PsmCoupling(lattice::Lattice& lattice, dem::DemSystem& dem,
                         const CouplingParams& params)
    : Coupling(lattice, dem, params) {}

void PsmCoupling::collectForces() {
    collidePsm();
    handOverLoads(nullptr);
}

void PsmCoupling::restore(const CouplingState& state) {
    if (!state.cells.empty() || !state.grains.empty())
        throw InputError("coupling state: partially saturated cells keep no covered nodes, but " +
                         std::to_string(state.cells.size()) + " are given");
    resizeGrains();
}

void PsmCoupling::placeGrains() {
    // eps of a cell = exact area of the unit cell covered by the disc of radius r_h. A cell two
    // grains overlap keeps one entry per grain; its total fraction is clipped at 1.
    for (long long c : m_psmCells)
        m_solid[c] = 0;
    m_psmCells.clear();
    m_psm.clear();
    const std::size_t n = m_dem.particles().size();
    for (std::size_t p = 0; p < n; ++p) {
        Real cx, cy, r;
        grainGeometry(p, cx, cy, r);
        const Box box = clippedBox(cx, cy, r, 0.5); // cells the disc overlaps
        for (int ju = box.j0; ju <= box.j1; ++ju)
            for (int iu = box.i0; iu <= box.i1; ++iu) {
                const Real px = iu + m_originX, py = ju + m_originY;
                const Real eps = cellSolidFraction(cx, cy, r, px, py);
                if (eps <= 0) continue;
                const long long c = wrapCell(iu, ju);
                if (c < 0 || !m_lattice.isFluid(c)) continue;
                m_solid[c] += eps;
                m_psm.push_back({c, static_cast<std::int32_t>(p), eps, px - cx, py - cy});
            }
    }
    // Entries of one cell next to each other (in-place sort: no allocation in steady state).
    std::sort(m_psm.begin(), m_psm.end(), [](const PsmEntry& a, const PsmEntry& b) {
        return a.cell != b.cell ? a.cell < b.cell : a.grain < b.grain;
    });
    // One group of entries per cell, in cell order; the lattice records what streams into
    // these cells during the next step, and collidePsm() re-collides them from that.
    m_psmCells.clear();
    m_linkStart.clear();
    for (std::size_t k = 0; k < m_psm.size(); ++k)
        if (k == 0 || m_psm[k].cell != m_psm[k - 1].cell) {
            m_psmCells.push_back(m_psm[k].cell);
            m_linkStart.push_back(static_cast<long long>(k));
        }
    m_linkStart.push_back(static_cast<long long>(m_psm.size()));
    m_lattice.setRecordedCells(m_psmCells);
}

namespace {

/// Everything the solid collision of one cell needs besides the cell's entries.
struct PsmContext {
    lattice::Lattice* lattice; // its post-collision populations are overwritten (setPopulation)
    const Real* incoming;      // per cell group: the kQ populations the step streamed into the cell
    int nx;
    Real fx, fy; // lattice body force (Guo), part of the fluid velocity
    Real tauMinusHalf;
    bool ntWeight;
    bool zouHeLeft, zouHeRight;
};

/// B(eps): eps, or eps (tau - 1/2) / ((1 - eps) + (tau - 1/2)) (Noble & Torczynski 1998).
inline Real psmWeight(const PsmContext& ctx, Real eps) {
    if (!ctx.ntWeight) return eps;
    return eps * ctx.tauMinusHalf / ((1 - eps) + ctx.tauMinusHalf);
}

} // namespace

/// The solid collision of one cell with its entries [first, last), the same fluid collision
/// operator as the bulk kernel, and the loads on the grains. Post-condition:
///   f_i <- f_i + (1 - B) Omega^f_i(f) + sum_p B_p Omega^s_i(u_p),
///   Omega^s_i = [f_-i - f_-i^eq(rho, u)] - [f_i - f_i^eq(rho, u_p)]   (NT 1998),
///   B = B(eps_total), B_p = B eps_p / sum eps, load on p: -B_p sum_i Omega^s_i c_i.
template <class C, class Entry, class Surface, class Load>
static void psmCell(const PsmContext& ctx, const C& collide, const Real* incoming,
                    const Entry* first, const Entry* last, const Surface& surface,
                    const Load& addLoad) {
    const long long cell = first->cell;
    const int x = static_cast<int>(cell % ctx.nx);
    if ((ctx.zouHeLeft && x == 0) || (ctx.zouHeRight && x == ctx.nx - 1)) {
        for (const Entry* e = first; e != last; ++e)
            addLoad(e, 0, 0, 0); // Zou-He nodes stay fluid
        return;
    }
    Real f[kQ];
    std::copy(incoming, incoming + kQ, f);
    Real rho = 0, jx = 0, jy = 0, sumEps = 0;
    for (int q = 0; q < kQ; ++q) {
        rho += f[q];
        jx += kCx[q] * f[q];
        jy += kCy[q] * f[q];
    }
    const Real ux = (jx + 0.5 * ctx.fx) / rho, uy = (jy + 0.5 * ctx.fy) / rho;
    for (const Entry* e = first; e != last; ++e)
        sumEps += e->eps;
    const Real b = psmWeight(ctx, std::min(sumEps, Real(1)));
    Real fc[kQ], out[kQ];
    std::copy(f, f + kQ, fc);
    collide(fc);
    for (int q = 0; q < kQ; ++q)
        out[q] = f[q] + (1 - b) * (fc[q] - f[q]);
    for (const Entry* e = first; e != last; ++e) {
        const Real bp = b * e->eps / sumEps;
        Real sx, sy;
        surface(e->grain, e->rx, e->ry, sx, sy);
        Real px = 0, py = 0;
        for (int q = 0; q < kQ; ++q) {
            const int o = kOpposite[q];
            const Real omega =
                (f[o] - equilibrium(o, rho, ux, uy)) - (f[q] - equilibrium(q, rho, sx, sy));
            out[q] += bp * omega;
            px += bp * omega * kCx[q];
            py += bp * omega * kCy[q];
        }
        addLoad(e, -px, -py, -(e->rx * py - e->ry * px));
    }
    long long slots[kQ];
    ctx.lattice->postSlots(cell, slots);
    for (int q = 0; q < kQ; ++q)
        ctx.lattice->setPopulation(slots[q], q, out[q]);
}

void PsmCoupling::collidePsm() {
    const LatticeSetup& s = m_lattice.setup();
    const CollisionParams& p = s.collision;
    const Real* incoming = m_lattice.recordedIncoming().data();
    PsmContext ctx{&m_lattice,
                   incoming,
                   m_lattice.nx(),
                   s.fx,
                   s.fy,
                   p.tau - 0.5,
                   m_params.psm_weight == PsmWeight::Nt,
                   s.left.type == SideType::ZouHeVelocity || s.left.type == SideType::ZouHePressure,
                   s.right.type == SideType::ZouHeVelocity ||
                       s.right.type == SideType::ZouHePressure};
    auto surface = [this](std::int32_t g, Real rx, Real ry, Real& ux, Real& uy) {
        surfaceVelocity(g, rx, ry, ux, uy);
    };
    // Loads go to one slot per entry and are summed per grain afterwards, in entry order, so
    // the cells can be collided in parallel with a result independent of the thread count.
    m_linkLoad.resize(3 * m_psm.size());
    const PsmEntry* base = m_psm.data();
    Real* slots = m_linkLoad.data();
    auto addLoad = [base, slots](const PsmEntry* e, Real fx, Real fy, Real t) {
        const std::size_t k = 3 * static_cast<std::size_t>(e - base);
        slots[k] = fx;
        slots[k + 1] = fy;
        slots[k + 2] = t;
    };
    const long long groups = static_cast<long long>(m_linkStart.size()) - 1;
    // The bulk kernel's operator and parameters (Lattice::step), so a cell with B = 0 is
    // unchanged.
    withCollision(p, s.fx, s.fy, [&](const auto& collide) {
#pragma omp parallel for schedule(static) if (groups > kParallelMin)
        for (long long g = 0; g < groups; ++g)
            psmCell(ctx, collide, incoming + g * kQ, base + m_linkStart[g],
                    base + m_linkStart[g + 1], surface, addLoad);
    });
    addEntryLoads(m_linkLoad, m_psm.size(), [base](std::size_t k) { return base[k].grain; });
}

} // namespace lbdem::solver::coupling
