// The Simulation: owns all solver state of one case and advances it; knows nothing of viewers.
#pragma once

#include "solver/core/StageTimer.h"
#include "solver/core/StateArchive.h"
#include "solver/scene/CaseSpec.h"
#include "solver/scene/Plan.h"
#include "solver/scene/RunDiagnostics.h"
#include "solver/scene/Snapshot.h"

#include <map>
#include <memory>
#include <string>

namespace lbdem::solver {

/// One running case: lattice (only when the scene has fluid), grains (only when it has grains),
/// their coupling and the diagnostics. Not thread-safe: drive it from one thread.
class Simulation {
public:
    /// Build the scene of spec with the given plan (from makePlan(spec)); throws InputError
    /// when the scene cannot be built from these parameters.
    Simulation(const CaseSpec& spec, const Plan& plan);
    ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    /// Advance one fluid step with its DEM sub-steps, or one DEM step in a dry scene.
    /// Throws SimulationError with a diagnosis when the run becomes unstable.
    void step();

    /// Steps taken since the start.
    long long stepIndex() const;
    /// Physical time [s].
    double time() const;
    /// Time in units of tau_c = sqrt(H_i / g).
    double timeOverTc() const { return m_plan.tc_s > 0 ? time() / m_plan.tc_s : time(); }
    /// True once the end time of the case is reached.
    bool finished() const;

    /// A copy of the current state for viewing and export (fluid down-sampled per the case).
    SnapshotPtr snapshot() const;
    /// The scalar diagnostics at the current time (timeseries.csv columns, SI units).
    std::map<std::string, double> metrics() const;

    const CaseSpec& spec() const { return m_spec; }
    const Plan& plan() const { return m_plan; }
    /// The running diagnostics (peak, averaging window, work totals); fed by whoever drives the
    /// run, saved and restored with the state.
    RunDiagnostics& runDiagnostics() { return m_diagnostics; }
    const RunDiagnostics& runDiagnostics() const { return m_diagnostics; }

    /// The complete state (time, step, lattice, grains, contact history, running diagnostics)
    /// for a checkpoint.
    StateArchive saveState() const;
    /// Restore a state saved by saveState() of a Simulation built from the same case and plan;
    /// continuing then gives bit-for-bit the same results as never having stopped.
    void restoreState(const StateArchive& archive);

    /// Wall time spent per stage of step().
    const StageTimer& timer() const { return m_timer; }

    /// Scene-specific state, defined in the implementation (kept out of this header so that
    /// consumers such as the studio do not depend on the lattice or DEM headers).
    struct State;
    /// The scene state, for checkpoint writers and verification drivers in the solver.
    State& state() { return *m_state; }
    const State& state() const { return *m_state; }

private:
    CaseSpec m_spec;
    Plan m_plan;
    StageTimer m_timer;
    RunDiagnostics m_diagnostics;
    std::unique_ptr<State> m_state;
};

} // namespace lbdem::solver
