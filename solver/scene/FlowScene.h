// The verification flows as scenes: Poiseuille, Taylor-Green, lid-driven cavity, cylinder.
#pragma once

#include "solver/lattice/Lattice.h"
#include "solver/lattice/StabilityGuard.h"
#include "solver/scene/CaseSpec.h"
#include "solver/scene/FlowPlan.h"
#include "solver/scene/Plan.h"
#include "solver/scene/SceneKind.h"
#include "solver/scene/Snapshot.h"

#include <map>
#include <string>

namespace lbdem::solver {

/// A pure-fluid scene built from a case: owns the lattice, steps it under the stability guard
/// and reports SI metrics. The Simulation wraps it for `lbdem run`; `lbdem verify` runs the
/// same builders.
class FlowScene {
public:
    /// Build the lattice of a flow case (scene poiseuille, taylor_green, cavity or cylinder).
    FlowScene(const CaseSpec& spec, const Plan& plan);

    /// One lattice step; the stability guard runs every StabilityGuard::interval() steps.
    void step();
    /// Run n steps.
    void advance(long long n);
    /// Run to the planned number of steps (plan.steps).
    void runToEnd();
    long long stepCount() const { return m_lattice.stepCount(); }
    double timeS() const { return static_cast<double>(stepCount()) * m_scales.dt_s; }
    SceneKind kind() const { return m_kind; }
    const FlowScales& scales() const { return m_scales; }
    const lattice::Lattice& lattice() const { return m_lattice; }
    lattice::Lattice& lattice() { return m_lattice; }

    /// Throw SimulationError if the current state has diverged (call before writing output).
    void checkStability() const { m_guard.check(m_lattice); }
    /// Copy the fluid fields in SI units, every `downsample`-th node (checks stability first).
    void fillSnapshot(SnapshotFluid& out, int downsample = 1) const;
    /// Named SI quantities of the current state: mass, max Mach and the scene's own
    /// (poiseuille: l2_error; taylor_green: decay_rate_1_s, decay_rate_error; cavity:
    /// ghia_max_deviation at Re = 100; cylinder: drag_coefficient, lift_coefficient,
    /// pressure_drop_pa), with NAME_reference where an analytic or published value applies;
    /// the full list is declared in SceneMetrics.h.
    std::map<std::string, double> metrics() const;

    /// Lattice velocity at the domain point (x, y) in lattice units, bilinear between nodes.
    void velocityAt(double x, double y, double& ux, double& uy) const;
    /// Lattice density at the domain point (x, y), bilinear between nodes.
    double densityAt(double x, double y) const;

private:
    void metricsPoiseuille(std::map<std::string, double>& m) const;
    void metricsTaylorGreen(std::map<std::string, double>& m) const;
    void metricsCavity(std::map<std::string, double>& m) const;
    void metricsCylinder(std::map<std::string, double>& m) const;
    double taylorGreenAmplitude() const;

    CaseSpec m_spec;
    SceneKind m_kind;
    FlowScales m_scales;
    lattice::Lattice m_lattice;
    lattice::StabilityGuard m_guard;
    int m_obstacle = -1;           // cylinder owner id
    long long m_referenceStep = 0; // Taylor-Green: amplitude recorded at this step
    double m_referenceAmplitude = 0;
};

/// Ghia, Ghia & Shin (1982), Table I, Re = 100: u / U_lid along the vertical centreline.
struct GhiaPoint {
    double y, u;
};
/// The Re = 100 column of Ghia et al.'s Table I (17 points, y from the bottom wall).
const std::vector<GhiaPoint>& ghiaRe100();

} // namespace lbdem::solver
