// The stability guard: one parallel scan, one diagnosis sentence.
#include "solver/lattice/StabilityGuard.h"

#include "solver/core/InputError.h"
#include "solver/core/OpenMp.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace lbdem::solver::lattice {

StabilityGuard::StabilityGuard(Real h_m, int interval, Real maxMach)
    : m_h(h_m), m_interval(interval > 0 ? interval : kDefaultInterval), m_maxMach(maxMach) {}

namespace {

/// Whether a fluid node of density rho and velocity (ux, uy) fails the guard's limits; written
/// so that NaN fails every comparison and lands in the failing branch.
bool outOfBounds(Real rho, Real ux, Real uy, Real maxU2) {
    return !(rho >= StabilityGuard::kMinDensity && rho <= StabilityGuard::kMaxDensity) ||
           !(ux * ux + uy * uy <= maxU2);
}

/// The first fluid cell (in cell order) that fails the limits, or the largest long long. Nodes
/// off the lattice's edges sum their stored values S at the parity's fixed slot offsets, in the
/// order and arithmetic of Lattice::density and Lattice::velocity (the same decision as theirs,
/// at a fraction of the cost of two calls per node); edge nodes go through those calls.
template <class S> long long firstBadCell(const Lattice& lattice, const S* f, Real maxU2) {
    const int nx = lattice.nx(), ny = lattice.ny();
    const std::uint8_t* flags = lattice.flags();
    const Real fx = lattice.setup().fx, fy = lattice.setup().fy;
    long long offset[kQ];
    for (int q = 0; q < kQ; ++q)
        offset[q] = lattice.postSlotOffset(q);
    long long bad = std::numeric_limits<long long>::max();
    const bool parallel = lattice.cells() >= kParallelMinCells;
#pragma omp parallel for schedule(static) reduction(min : bad) if (parallel)
    for (int j = 0; j < ny; ++j) {
        const bool edgeRow = j == 0 || j == ny - 1;
        for (int i = 0; i < nx; ++i) {
            const long long c = lattice.index(i, j);
            if (flags[c] != Lattice::kFluid) continue;
            Real rho = 0, ux, uy;
            if (edgeRow || i == 0 || i == nx - 1) {
                rho = lattice.density(c);
                lattice.velocity(c, ux, uy);
            } else {
                Real jx = 0, jy = 0;
                for (int q = 0; q < kQ; ++q) {
                    const Real v = StoredPopulation<S>::load(f[c + offset[q]], kW[q]);
                    rho += v;
                    jx += kCx[q] * v;
                    jy += kCy[q] * v;
                }
                ux = (jx - 0.5 * fx) / rho;
                uy = (jy - 0.5 * fy) / rho;
            }
            if (outOfBounds(rho, ux, uy, maxU2)) {
                bad = std::min(bad, c);
                break; // the row's first; later cells of the row come after it
            }
        }
    }
    return bad;
}

} // namespace

void StabilityGuard::check(const Lattice& lattice) const {
    const Real maxU2 = m_maxMach * m_maxMach * kCs2;
    const long long bad = lattice.setup().storage == PopulationStorage::Float
                              ? firstBadCell(lattice, lattice.storedFloats(), maxU2)
                              : firstBadCell(lattice, lattice.storedDoubles(), maxU2);
    if (bad == std::numeric_limits<long long>::max()) return;

    const int i = static_cast<int>(bad % lattice.nx()), j = static_cast<int>(bad / lattice.nx());
    const Real rho = lattice.density(bad);
    Real ux, uy;
    lattice.velocity(bad, ux, uy);
    const Real mach = std::sqrt((ux * ux + uy * uy) / kCs2);
    char what[160];
    if (!std::isfinite(rho) || !std::isfinite(mach))
        std::snprintf(what, sizeof what, "the density or velocity is not a number");
    else if (!(rho >= kMinDensity && rho <= kMaxDensity))
        std::snprintf(what, sizeof what,
                      "the density is %.3g, outside [%.2g, %.2g] of the fluid at rest (1)", rho,
                      kMinDensity, kMaxDensity);
    else
        std::snprintf(what, sizeof what, "the lattice Mach number is %.3g, above the limit %.3g",
                      mach, m_maxMach);

    const CollisionParams& p = lattice.setup().collision;
    std::string cause;
    const bool densityOnly = std::isfinite(rho) && std::isfinite(mach) && mach <= m_maxMach;
    if (densityOnly) {
        cause = "the fluid is no longer nearly incompressible there: fluid shut in a pore that "
                "grains or walls seal off (gaps between hydrodynamic radii narrower than a node), "
                "or a pressure wave too strong for the lattice; refine the lattice "
                "(fluid.resolution)";
    } else if (p.tau - 0.5 < 0.01 && p.model != CollisionModel::MrtLes) {
        char text[240];
        std::snprintf(text, sizeof text,
                      "tau - 0.5 = %.3g is too close to 0.5 for collision '%s' without LES; use "
                      "collision = \"mrt_les\" or raise tau",
                      p.tau - 0.5, enumWord(p.model));
        cause = text;
    } else {
        cause = "the velocity is too high for the lattice; lower the flow velocity (Mach number) "
                "or refine the lattice";
    }
    char message[600];
    std::snprintf(message, sizeof message,
                  "step %lld: the fluid diverged at node (%d, %d), x = %.4g m, y = %.4g m: %s. "
                  "Likely cause: %s.",
                  lattice.stepCount(), i, j, lattice.nodeX(i) * m_h, lattice.nodeY(j) * m_h, what,
                  cause.c_str());
    throw SimulationError(message);
}

} // namespace lbdem::solver::lattice
