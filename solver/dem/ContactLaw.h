// Material constants of the disc contact law and the spring-dashpot relations they imply.
#pragma once

#include "solver/core/Real.h"

namespace lbdem::solver::dem {

/// Contact-law parameters per unit thickness (2D discs). Defaults are the paper's.
struct Material {
    Real normal_stiffness = 1.6e6;     ///< k_n [N/m]
    Real tangential_stiffness = 1.0e6; ///< k_t [N/m]
    Real restitution = 0.5;            ///< normal coefficient of restitution e (sets the dashpot)
    Real friction = 0.48773258856586;  ///< grain-grain Coulomb coefficient, tan(26 deg)
    Real wall_friction = 0.466;        ///< grain-wall Coulomb coefficient
    Real rolling_resistance = 0.01;    ///< mu_r: rolling torque limited to mu_r R_eff F_n
    /// Rolling resistance of disc-wall contacts (the frictional floor): torque limited to
    /// mu_r,wall R F_n. Above tan(theta) a disc alone on a slope theta comes to rest; 0.2 exceeds
    /// tan(7.5 deg) = 0.13, the steepest slope of the paper, by half.
    Real wall_rolling_resistance = 0.2;
    /// Contacts exert torque (tangential force times radius, rolling resistance); false: they
    /// push the discs' centres only and never turn them (as in the reference's published code).
    bool contact_torque = true;
    Real density = 2650; ///< grain density [kg/m^3]
};

/// Damping ratio zeta of a linear spring-dashpot that gives restitution e when the contact ends
/// at zero overlap: ln e = -pi zeta / sqrt(1 - zeta^2).
Real dampingRatio(Real restitution);

/// Duration of a binary linear spring-dashpot contact between bodies of effective mass m_eff.
Real contactDuration(Real stiffness, Real effectiveMass, Real restitution);

/// Dashpot coefficient gamma = 2 zeta sqrt(k m_eff) giving restitution e.
Real dampingCoefficient(Real stiffness, Real effectiveMass, Real restitution);

/// Mass per unit thickness of a disc of the given radius [kg/m].
Real discMass(Real radius, Real density);

} // namespace lbdem::solver::dem
