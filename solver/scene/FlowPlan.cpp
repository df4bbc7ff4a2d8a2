// Planning of the verification flows: characteristic length, Reynolds number, lattice velocity.
#include "solver/scene/FlowPlan.h"
#include "solver/core/Constants.h"

#include "solver/core/InputError.h"
#include "solver/scene/FluidStability.h"

#include <algorithm>
#include <cmath>

namespace lbdem::solver {

namespace {

// Schäfer & Turek (1996) 2D-1: channel height H = 4.1 D; Re uses the mean inflow 2/3 U_max.
constexpr double kCylinderHeightOverD = 4.1;
constexpr double kMeanOverPeakInflow = 2.0 / 3.0;

// Steps to a steady state or a clear decay when the case does not say (flow.steps = 0).
long long defaultSteps(SceneKind kind, const FlowScales& s) {
    const double n = s.length_m / s.h_m;
    switch (kind) {
    case SceneKind::Poiseuille: // slowest mode decays as exp(-pi^2 nu t / H^2): to ~1e-8
        return std::llround(1.9 * n * n / s.nu_lattice);
    case SceneKind::TaylorGreen: // amplitude decays as exp(-2 nu k^2 t): to exp(-1)
        return std::llround(1.0 / (2.0 * s.nu_lattice * std::pow(2 * kPi / n, 2)));
    case SceneKind::Cavity: // 25 lid passages: at Re = 100, 128^2 the centreline is steady
        return std::llround(25.0 * n / s.u_peak); // from 20 on (measured, change < 1e-5)
    case SceneKind::Cylinder: // 3 flow-throughs at the mean inflow: C_D steady to ~1e-4
        return std::llround(3.0 * s.nx / s.u_ref);
    default:
        return 1000;
    }
}

} // namespace

bool isFlowScene(SceneKind kind) {
    return kind == SceneKind::Poiseuille || kind == SceneKind::TaylorGreen ||
           kind == SceneKind::Cavity || kind == SceneKind::Cylinder;
}

FlowScales flowScales(const CaseSpec& spec) {
    const SceneKind kind = spec.scene;
    const FlowSpec& f = spec.flow;
    FlowScales s;
    const bool cylinder = kind == SceneKind::Cylinder;
    s.length_m = cylinder ? spec.domain.height_m / kCylinderHeightOverD : spec.domain.height_m;
    s.h_m = s.length_m / f.nodes;
    const double refOverPeak = cylinder ? kMeanOverPeakInflow : 1.0;
    const bool imposed = imposesTau(f.tau);
    if (!imposed && !(f.reynolds > 0))
        throw InputError("", 0, "flow.reynolds",
                         "0 derives the Reynolds number from flow.tau and "
                         "flow.lattice_velocity, so it needs flow.tau above 0.5");
    s.u_peak = f.lattice_velocity;
    s.u_ref = s.u_peak * refOverPeak;
    // Lattice viscosity: from an imposed tau, else from the velocity and Re (lattice units).
    s.nu_lattice = imposed ? (f.tau - 0.5) / 3.0 : s.u_ref * f.nodes / f.reynolds;
    s.tau = relaxationTime(f.tau, s.nu_lattice, 1.0, 1.0);
    if (imposed && f.reynolds > 0) { // diffusive scaling: tau fixed, velocity from Re
        s.u_ref = f.reynolds * s.nu_lattice / f.nodes;
        s.u_peak = s.u_ref / refOverPeak;
    }
    // dt from the physical viscosity: nu = nu_lattice h^2 / dt.
    s.dt_s = s.nu_lattice * s.h_m * s.h_m / spec.fluid.viscosity_m2_s;
    s.ny = static_cast<int>(std::lround(spec.domain.height_m / s.h_m));
    s.nx = static_cast<int>(std::lround(spec.domain.width_m / s.h_m));
    if (kind == SceneKind::Cavity || kind == SceneKind::TaylorGreen) s.nx = s.ny = f.nodes;
    if (cylinder) s.nx += 1; // Zou-He columns sit on x = 0 and x = width
    s.nx = std::max(s.nx, 4);
    s.steps = f.steps > 0 ? f.steps : std::max<long long>(defaultSteps(kind, s), 1);
    return s;
}

void planFlow(const CaseSpec& spec, Plan& plan) {
    const FlowScales s = flowScales(spec);
    plan.has_fluid = true;
    plan.nx = s.nx;
    plan.ny = s.ny;
    plan.h_m = s.h_m;
    plan.dt_s = s.dt_s;
    plan.tau = s.tau;
    plan.nu_lattice = s.nu_lattice;
    plan.u_expected_m_s = s.u_peak * s.h_m / s.dt_s;
    planAcoustics(spec.fluid.density_kg_m3, plan);
    plan.substeps = 1;
    plan.steps = s.steps;
    plan.end_time_s = static_cast<double>(s.steps) * s.dt_s;
    plan.tc_s = s.length_m / std::max(s.u_ref * s.h_m / s.dt_s, 1e-300); // L / U
    addStabilityWarnings(spec, plan);
}

} // namespace lbdem::solver
