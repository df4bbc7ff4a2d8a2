// TEST DOUBLE, tests/ui only: a link-time stand-in for solver::Simulation that produces synthetic
// snapshots (a moving column of discs over a swirling fluid) until the real Simulation.cpp is
// part of lbdem::scene. It lets the threading and window tests run; it simulates no physics.
#include "solver/scene/Simulation.h"

#include "solver/core/InputError.h"

#include <chrono>
#include <cmath>
#include <thread>

namespace lbdem::solver {

struct Simulation::State {
    long long step = 0;
    double time = 0;
};

Simulation::Simulation(const CaseSpec& spec, const Plan& plan)
    : m_spec(spec), m_plan(plan), m_state(std::make_unique<State>()) {
    if (plan.column.width_m > spec.domain.width_m || plan.column.height_m > spec.domain.height_m)
        throw InputError("the column of " + std::to_string(spec.grains.count) +
                         " grains does not fit into the domain");
}

Simulation::~Simulation() = default;

void Simulation::step() {
    // About a millisecond of work per step, like a small lattice, so batches hold many steps.
    std::this_thread::sleep_for(std::chrono::microseconds(800));
    ++m_state->step;
    m_state->time += m_plan.dt_s;
}

long long Simulation::stepIndex() const { return m_state->step; }

double Simulation::time() const { return m_state->time; }

bool Simulation::finished() const { return time() >= m_plan.end_time_s - 0.5 * m_plan.dt_s; }

SnapshotPtr Simulation::snapshot() const {
    auto s = std::make_shared<Snapshot>();
    s->case_name = m_spec.name;
    s->step = m_state->step;
    s->time_s = time();
    s->tc_s = m_plan.tc_s;
    const double w = m_spec.domain.width_m, h = m_spec.domain.height_m;
    s->domain_width_m = w;
    s->domain_height_m = h;
    const double phase = 50.0 * time();
    const double radius = 0.5 * m_spec.grains.d_min_m * 1.4;
    const int columns = std::max(1, int(m_plan.column.width_m / (2 * radius)));
    for (int k = 0; k < m_spec.grains.count; ++k) {
        const double x = (k % columns + 0.5) * 2 * radius + 0.2 * radius * std::sin(phase + k);
        const double y = (k / columns + 0.5) * 2 * radius;
        s->grains.x.push_back(float(x));
        s->grains.y.push_back(float(y));
        s->grains.radius.push_back(float(radius * (0.8 + 0.2 * ((k * 7) % 5) / 4.0)));
        s->grains.vx.push_back(float(0.01 * std::cos(phase + k)));
        s->grains.vy.push_back(0.f);
        s->grains.omega.push_back(0.f);
        s->grains.fx.push_back(1.f);
        s->grains.fy.push_back(-1.f);
        if (k >= columns) {
            s->contacts.i.push_back(k);
            s->contacts.j.push_back(k - columns);
            s->contacts.normal_force.push_back(float(1 + (k % 13)));
            s->contacts.tangential_force.push_back(0.1f);
        }
    }
    SnapshotFluid fluid;
    fluid.spacing_m = float(w / 160);
    fluid.nx = 161;
    fluid.ny = int(h / fluid.spacing_m) + 1;
    for (int iy = 0; iy < fluid.ny; ++iy)
        for (int ix = 0; ix < fluid.nx; ++ix) {
            const double x = ix * fluid.spacing_m / w, y = iy * fluid.spacing_m / h;
            fluid.ux.push_back(float(0.05 * std::sin(6.28 * x + phase) * std::cos(3.14 * y)));
            fluid.uy.push_back(float(-0.05 * std::cos(6.28 * x + phase) * std::sin(3.14 * y)));
            fluid.pressure.push_back(float(10 * std::cos(6.28 * (x - y) + phase)));
            fluid.vorticity.push_back(float(std::sin(6.28 * x) * std::sin(6.28 * y)));
            fluid.solid.push_back(0.f);
        }
    s->fluid = std::move(fluid);
    s->walls = {{0, 0, float(w), 0}, {0, 0, 0, float(h)}};
    s->outline = {{0.f, float(m_plan.column.height_m)},
                  {float(m_plan.column.width_m), float(m_plan.column.height_m)},
                  {float(m_plan.column.width_m * 1.5), 0.f}};
    s->metrics = metrics();
    return s;
}

std::map<std::string, double> Simulation::metrics() const {
    const double t = timeOverTc();
    return {{"runout_normalised", 0.5 * (1 - std::exp(-t))},
            {"ke_over_ep0", 0.1 * t * std::exp(-t)},
            {"froude_densimetric", 0.3 * std::sin(t)}};
}

} // namespace lbdem::solver
