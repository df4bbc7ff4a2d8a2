// The relaxation time of a lattice and the stability warnings of its plan, for every scene.
#pragma once

#include "solver/scene/CaseSpec.h"
#include "solver/scene/Plan.h"

namespace lbdem::solver {

/// True when a case's relaxation time (fluid.tau or flow.tau) is imposed: above 1/2. Otherwise
/// the scene derives it from the viscosity its velocity scale gives.
bool imposesTau(double caseTau);

/// The relaxation time of every scene with a lattice: caseTau when it is imposed, else
/// tau = 1/2 + 3 nu dt / h^2 for the viscosity nu at time step dt and spacing h (a viscosity in
/// lattice units with dt = h = 1).
double relaxationTime(double caseTau, double viscosity, double dt, double h);

/// Append to plan.warnings the stability risks of its lattice, for every scene: a fluid.tau
/// that is not above 1/2 (column scenes), tau - 1/2 below 0.01 without LES, and a Mach number
/// above 0.3 (with the keys that lower it in this scene).
void addStabilityWarnings(const CaseSpec& spec, Plan& plan);

} // namespace lbdem::solver
