// The Simulation: a scene runner plus step counting, snapshots and state archiving.
#include "solver/scene/Simulation.h"

#include "solver/scene/SceneRunner.h"

#include <cmath>

namespace lbdem::solver {

struct Simulation::State {
    std::unique_ptr<SceneRunner> runner;
    long long step = 0;
};

Simulation::Simulation(const CaseSpec& spec, const Plan& plan)
    : m_spec(spec), m_plan(plan), m_state(std::make_unique<State>()) {
    m_state->runner = makeSceneRunner(m_spec, m_plan);
}

Simulation::~Simulation() = default;

void Simulation::step() {
    m_state->runner->step(m_timer);
    ++m_state->step;
}

long long Simulation::stepIndex() const {
    return m_state->step;
}

double Simulation::time() const {
    return m_state->runner->time();
}

bool Simulation::finished() const {
    return time() >= m_plan.end_time_s - 0.5 * m_plan.dt_s;
}

SnapshotPtr Simulation::snapshot() const {
    auto snapshot = std::make_shared<Snapshot>();
    snapshot->case_name = m_spec.name;
    snapshot->time_s = time();
    snapshot->tc_s = m_plan.tc_s;
    snapshot->domain_width_m = m_spec.domain.width_m;
    snapshot->domain_height_m = m_spec.domain.height_m;
    snapshot->slope_deg = m_spec.domain.slope_deg;
    m_state->runner->fillSnapshot(*snapshot, std::max(1, m_spec.output.fluid_downsample));
    snapshot->step = m_state->step; // the simulation's step, whatever count the scene keeps
    snapshot->metrics = metrics();
    return snapshot;
}

std::map<std::string, double> Simulation::metrics() const {
    std::map<std::string, double> metrics;
    m_state->runner->addMetrics(metrics);
    return metrics;
}

StateArchive Simulation::saveState() const {
    StateArchive archive;
    archive.integers["simulation/step"] = {m_state->step};
    m_state->runner->save(archive);
    m_diagnostics.save(archive);
    return archive;
}

void Simulation::restoreState(const StateArchive& archive) {
    m_state->step = archive.integer("simulation/step").at(0);
    m_state->runner->restore(archive);
    m_diagnostics.restore(archive);
}

} // namespace lbdem::solver
