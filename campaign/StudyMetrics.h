// Which key of summary.json a study reads, its default per scene, and how it is judged.
#pragma once

#include "solver/scene/CaseSpec.h"

#include <string>

namespace lbdem::campaign {

/// A metric a study reads from each run's summary.json, resolved before any run starts.
struct StudyMetric {
    std::string name;      ///< a top-level number of summary.json or a key of its "final" object
    bool analytic = false; ///< the runs report an analytic or published reference for it
    bool isError = false;  ///< the metric is itself an error against that reference
};

/// The metric a study of spec reads when --metric is not given: the one its scene declares
/// (solver::sceneDecl), or the scene's fallback when the run would not report that one.
std::string defaultStudyMetric(const solver::CaseSpec& spec);

/// Resolve name (optionally written final.NAME) for a run of spec; throws InputError naming the
/// nearest known metric when the run's summary.json would not hold it.
StudyMetric resolveStudyMetric(const solver::CaseSpec& spec, const std::string& name);

} // namespace lbdem::campaign
