// Grain-state checks: the DEM's stability guard and the restore-time validation.
#include "solver/dem/DemGuard.h"

#include "solver/core/InputError.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace lbdem::solver::dem {

namespace {

bool finiteState(const Particles& p, std::size_t i) {
    return std::isfinite(p.x[i]) && std::isfinite(p.y[i]) && std::isfinite(p.vx[i]) &&
           std::isfinite(p.vy[i]) && std::isfinite(p.omega[i]);
}

} // namespace

void checkGrainMotion(const Particles& p, Real subStepS, Real timeS) {
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Real travel = std::hypot(p.vx[i], p.vy[i]) * subStepS;
        const bool finite = finiteState(p, i);
        if (finite && travel <= kMaxSubstepTravel * p.radius[i]) continue;
        char text[512];
        if (!finite)
            std::snprintf(
                text, sizeof text,
                "the DEM became unstable at t = %.6g s: grain %zu has a position or velocity that "
                "is not finite; the DEM step (%.3g s) is too long for the contact stiffness: raise "
                "coupling.substeps (0 chooses it) or lower grains.dt_safety",
                timeS, i, subStepS);
        else
            std::snprintf(
                text, sizeof text,
                "the DEM became unstable at t = %.6g s: grain %zu at (%.4g, %.4g) m moves %.3g of "
                "its "
                "radius in one DEM step of %.3g s (the guard stops at %.2g); the DEM step is too "
                "long for the contact stiffness: raise coupling.substeps (0 chooses it) or lower "
                "grains.dt_safety",
                timeS, i, p.x[i], p.y[i], travel / p.radius[i], subStepS, kMaxSubstepTravel);
        throw SimulationError(text);
    }
}

void checkRestoredGrains(const Particles& p, Real widthM, Real heightM) {
    const std::size_t n = p.size();
    for (const auto* array : {&p.y, &p.vx, &p.vy, &p.omega, &p.fx, &p.fy, &p.torque, &p.radius,
                              &p.ext_fx, &p.ext_fy, &p.ext_torque})
        if (array->size() != n)
            throw InputError("the grain arrays of the state differ in length (" +
                             std::to_string(array->size()) + " and " + std::to_string(n) +
                             " discs)");
    for (std::size_t i = 0; i < n; ++i) {
        const Real r = p.radius[i];
        if (!finiteState(p, i) || !std::isfinite(r) || r <= 0)
            throw InputError("grain " + std::to_string(i) +
                             " of the state has a position, velocity or radius that "
                             "is not finite");
        if (p.x[i] < -r || p.x[i] > widthM + r || p.y[i] < -r || p.y[i] > 2 * heightM) {
            char text[256];
            std::snprintf(text, sizeof text,
                          "grain %zu of the state lies at (%.4g, %.4g) m, outside the %.4g m x "
                          "%.4g m domain",
                          i, p.x[i], p.y[i], widthM, heightM);
            throw InputError(text);
        }
    }
}

} // namespace lbdem::solver::dem
