// Lattice scales of the verification flows (poiseuille, taylor_green, cavity, cylinder).
#pragma once

#include "solver/scene/CaseSpec.h"
#include "solver/scene/Plan.h"
#include "solver/scene/SceneKind.h"

namespace lbdem::solver {

/// True for the pure-fluid verification scenes planned by planFlow.
bool isFlowScene(SceneKind kind);

/// Lattice numbers of a flow scene: sizes, scales and the velocity the Reynolds number uses.
struct FlowScales {
    int nx = 0, ny = 0;       ///< fluid nodes (without ghost layers)
    double length_m = 0;      ///< characteristic length L
    double h_m = 0, dt_s = 0; ///< lattice spacing and time step
    double tau = 0;           ///< relaxation time
    double nu_lattice = 0;    ///< (tau - 1/2) / 3
    double u_peak = 0;        ///< peak velocity, lattice units (lid, centreline, amplitude, inflow)
    double u_ref = 0;         ///< velocity of the Reynolds number, lattice units
    long long steps = 0;      ///< steps to run (the scene default when flow.steps = 0)
};

/// Scales of a flow case: L from the domain, U from Re and the viscosity (docs/design.md §4); with
/// flow.reynolds = 0 tau and U are imposed and Re follows. Throws InputError for Re = 0 without
/// tau.
FlowScales flowScales(const CaseSpec& spec);

/// Fill the fluid part of a plan for a flow scene (lattice size, h, dt, tau, Mach, steps).
void planFlow(const CaseSpec& spec, Plan& plan);

} // namespace lbdem::solver
