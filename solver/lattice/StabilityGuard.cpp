// The stability guard: one parallel scan, one diagnosis sentence.
#include "solver/lattice/StabilityGuard.h"

#include "solver/core/InputError.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace lbdem::solver::lattice {

StabilityGuard::StabilityGuard(Real h_m, int interval, Real maxMach)
    : m_h(h_m), m_interval(interval > 0 ? interval : kDefaultInterval), m_maxMach(maxMach) {}

void StabilityGuard::check(const Lattice& lattice) const {
    const long long cells = lattice.cells();
    const Real maxU2 = m_maxMach * m_maxMach * kCs2;
    long long bad = std::numeric_limits<long long>::max();
#pragma omp parallel for schedule(static) reduction(min : bad) if (cells >= kParallelMinCells)
    for (long long c = 0; c < cells; ++c) {
        if (!lattice.isFluid(c)) continue;
        const Real rho = lattice.density(c);
        Real ux, uy;
        lattice.velocity(c, ux, uy);
        // Written so that NaN fails every comparison and lands in the bad branch.
        if (!(rho >= kMinDensity && rho <= kMaxDensity) || !(ux * ux + uy * uy <= maxU2))
            bad = std::min(bad, c);
    }
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
