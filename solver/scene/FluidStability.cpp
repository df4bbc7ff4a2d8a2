// The relaxation-time rule and the stability warnings shared by the column and flow plans.
#include "solver/scene/FluidStability.h"

#include "solver/scene/FlowPlan.h"

#include <cstdio>
#include <string>

namespace lbdem::solver {

namespace {

/// Below this tau - 1/2 the shear modes of BGK and plain MRT are likely unstable.
constexpr double kMinTauExcessWithoutLes = 0.01;
/// Above this lattice Mach number compressibility errors grow and the lattice becomes unstable.
constexpr double kMaxMach = 0.3;

std::string format(const char* pattern, double value) {
    char text[256];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

} // namespace

bool imposesTau(double caseTau) {
    return caseTau > 0.5;
}

double relaxationTime(double caseTau, double viscosity, double dt, double h) {
    return imposesTau(caseTau) ? caseTau : 0.5 + 3.0 * viscosity * dt / (h * h);
}

void addStabilityWarnings(const CaseSpec& spec, Plan& plan) {
    const bool flow = isFlowScene(spec.scene);
    const double tau = spec.fluid.tau;
    if (!flow && tau != 0 && tau <= 0.5)
        plan.warnings.push_back(
            format("tau = %.6g must exceed 0.5; set fluid.tau above 0.5 or to 0", tau));
    if (plan.tau - 0.5 < kMinTauExcessWithoutLes &&
        spec.fluid.collision != lattice::CollisionModel::MrtLes)
        plan.warnings.push_back(format("tau - 0.5 = %.3g is below 0.01 without LES: the run is "
                                       "likely unstable; use collision = \"mrt_les\"",
                                       plan.tau - 0.5));
    if (plan.mach > kMaxMach)
        plan.warnings.push_back(
            format(flow ? "peak lattice Mach number %.3g is above 0.3: lower "
                          "flow.lattice_velocity or raise flow.nodes"
                        : "expected Mach number %.3g is above 0.3: compressibility errors and "
                          "instability; lower tau or raise resolution",
                   plan.mach));
}

} // namespace lbdem::solver
