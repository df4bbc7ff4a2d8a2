// The metric declarations of every scene; tests/unit/SceneMetricsTest.cpp keeps them in step
// with what the flow scenes really report.
#include "solver/scene/SceneMetrics.h"

#include "solver/scene/SceneKind.h"

#include <cmath>

namespace lbdem::solver {

namespace {

using R = MetricReference;

std::vector<MetricDecl> flowMetrics(const CaseSpec& spec, SceneKind kind) {
    std::vector<MetricDecl> m{{"fluid_grid_noise"}, {"max_mach"}, {"mass_lattice"}, {"time_s"}};
    switch (kind) {
    case SceneKind::Poiseuille:
        m.insert(m.end(), {{"l2_error", R::IsError}, {"u_max_m_s"}});
        break;
    case SceneKind::TaylorGreen:
        m.insert(m.end(), {{"decay_rate_1_s", R::Field},
                           {"decay_rate_1_s_reference"},
                           {"decay_rate_analytic_1_s"},
                           {"decay_rate_error", R::IsError}});
        break;
    case SceneKind::Cavity:
        if (ghiaReferenceApplies(spec)) m.push_back({"ghia_max_deviation", R::IsError});
        break;
    case SceneKind::Cylinder: {
        const R known = schaeferTurekApplies(spec) ? R::Field : R::None;
        m.insert(m.end(),
                 {{"drag_coefficient", known}, {"lift_coefficient"}, {"pressure_drop_pa", known}});
        if (known == R::Field)
            m.insert(m.end(), {{"drag_coefficient_reference"}, {"pressure_drop_pa_reference"}});
        break;
    }
    default:
        break;
    }
    return m;
}

std::vector<MetricDecl> columnMetrics(const CaseSpec& spec) {
    std::vector<MetricDecl> m{
        {"runout_m"},          {"runout_normalised"},   {"height_m"},
        {"height_normalised"}, {"kinetic_energy_j_m"},  {"ke_over_ep0"},
        {"packing_fraction"},  {"front_velocity_m_s"},  {"front_thickness_m"},
        {"main_mass_grains"},  {"max_grain_speed_m_s"}, {"base_normal_stress_front_pa"}};
    if (spec.fluid.enabled)
        m.insert(
            m.end(),
            {{"froude_densimetric"}, {"pore_pressure_failure_plane_pa"}, {"fluid_grid_noise"}});
    return m;
}

} // namespace

std::vector<MetricDecl> sceneMetrics(const CaseSpec& spec) {
    const SceneKind kind = spec.scene;
    if (kind == SceneKind::ColumnCollapse) return columnMetrics(spec);
    if (kind == SceneKind::SettlingDisc) return {};
    return flowMetrics(spec, kind);
}

bool ghiaReferenceApplies(const CaseSpec& spec) {
    // Ghia et al. tabulate Re = 100 only; an imposed flow.tau changes the lid velocity instead.
    return std::abs(spec.flow.reynolds - 100.0) < 1e-9 && spec.flow.tau <= 0.5;
}

bool schaeferTurekApplies(const CaseSpec& spec) {
    const double aspect = spec.domain.width_m / spec.domain.height_m;
    return std::abs(spec.flow.reynolds - 20.0) < 1e-9 &&
           std::abs(aspect - 2.2 / 0.41) < 1e-6 * aspect;
}

} // namespace lbdem::solver
