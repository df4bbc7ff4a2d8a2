// Study metrics: the scenes' declared metrics plus the numbers RunDriver writes into summary.json.
#include "app/cli/StudyMetrics.h"

#include "solver/core/InputError.h"
#include "solver/core/TextDistance.h"
#include "solver/scene/SceneKind.h"
#include "solver/scene/SceneMetrics.h"

#include <vector>

namespace lbdem::cli {

namespace {

using solver::SceneKind;

/// The numbers RunDriver::writeSummary puts at the top level of summary.json, and those it adds
/// to "final" beside the scene's metrics.
std::vector<std::string> driverNumbers(const solver::CaseSpec& spec) {
    std::vector<std::string> names{"steps", "t_over_tc", "wall_s", "mlups", "t_s", "step"};
    if (spec.scene == SceneKind::ColumnCollapse)
        names.insert(names.end(),
                     {"runout_final", "packing_final", "ke_peak", "t_ke_peak_over_tc"});
    return names;
}

} // namespace

std::string defaultStudyMetric(const solver::CaseSpec& spec) {
    switch (spec.scene) {
    case SceneKind::Poiseuille:
        return "l2_error";
    case SceneKind::TaylorGreen:
        return "decay_rate_1_s";
    case SceneKind::Cavity:
        return solver::ghiaReferenceApplies(spec) ? "ghia_max_deviation" : "max_mach";
    case SceneKind::Cylinder:
        return "drag_coefficient";
    default:
        return "runout_final";
    }
}

StudyMetric resolveStudyMetric(const solver::CaseSpec& spec, const std::string& name) {
    const std::string bare = name.rfind("final.", 0) == 0 ? name.substr(6) : name;
    std::vector<std::string> known = driverNumbers(spec);
    for (const auto& candidate : known)
        if (candidate == bare) return {bare, false, false};
    for (const auto& decl : solver::sceneMetrics(spec)) {
        if (decl.name == bare)
            return {bare, decl.reference != solver::MetricReference::None,
                    decl.reference == solver::MetricReference::IsError};
        known.push_back(decl.name);
    }
    const std::string nearest = solver::nearestWord(bare, known);
    throw solver::InputError("--metric " + name + ": a run of scene '" +
                             solver::enumWord(spec.scene) +
                             "' reports no such number in summary.json" +
                             (nearest.empty() ? "" : "; did you mean '" + nearest + "'?"));
}

bool isResolutionKey(const std::string& key) {
    return key == "flow.nodes" || key == "fluid.resolution";
}

} // namespace lbdem::cli
