// Linear spring-dashpot relations shared by the contact kernel and the planner.
#include "solver/dem/ContactLaw.h"
#include "solver/core/Constants.h"

#include <algorithm>
#include <cmath>

namespace lbdem::solver::dem {

Real dampingRatio(Real restitution) {
    // ln e = -pi zeta / sqrt(1 - zeta^2) for a linear oscillator that separates at zero overlap.
    const Real logE = std::log(std::clamp(restitution, Real(1e-6), Real(1)));
    return -logE / std::sqrt(kPi * kPi + logE * logE);
}

Real contactDuration(Real stiffness, Real effectiveMass, Real restitution) {
    // t_c = pi / (omega_0 sqrt(1 - zeta^2)), omega_0 = sqrt(k / m_eff): half a damped period.
    const Real zeta = dampingRatio(restitution);
    const Real omega0 = std::sqrt(stiffness / effectiveMass);
    return kPi / (omega0 * std::sqrt(1 - zeta * zeta));
}

Real dampingCoefficient(Real stiffness, Real effectiveMass, Real restitution) {
    return 2 * dampingRatio(restitution) * std::sqrt(stiffness * effectiveMass);
}

Real discMass(Real radius, Real density) {
    return density * kPi * radius * radius;
}

} // namespace lbdem::solver::dem
