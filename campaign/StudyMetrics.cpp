// Study metrics: the scenes' declared metrics plus the numbers io writes into summary.json.
#include "campaign/StudyMetrics.h"

#include "solver/core/InputError.h"
#include "solver/core/TextDistance.h"
#include "solver/io/RunSummary.h"
#include "solver/scene/SceneKind.h"
#include "solver/scene/SceneMetrics.h"

namespace lbdem::campaign {

namespace {

/// True when a run of spec reports name in its summary.json.
bool reported(const solver::CaseSpec& spec, const std::string& name) {
    for (const auto& number : io::runSummaryNumbers(spec))
        if (number == name) return true;
    for (const auto& decl : solver::sceneMetrics(spec))
        if (decl.name == name) return true;
    return false;
}

} // namespace

std::string defaultStudyMetric(const solver::CaseSpec& spec) {
    const auto& decl = solver::sceneDecl(spec.scene);
    return decl.studyFallback.empty() || reported(spec, decl.studyMetric) ? decl.studyMetric
                                                                          : decl.studyFallback;
}

StudyMetric resolveStudyMetric(const solver::CaseSpec& spec, const std::string& name) {
    const std::string bare = name.rfind("final.", 0) == 0 ? name.substr(6) : name;
    std::vector<std::string> known = io::runSummaryNumbers(spec);
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

} // namespace lbdem::campaign
