// Planning of `lbdem study`: one case over several values of one or more keys (their cartesian
// product), every setting loaded, planned and checked before any run starts.
#include "campaign/StudyPlan.h"

#include "solver/core/InputError.h"
#include "solver/core/TextDistance.h"
#include "solver/io/CaseLoader.h"
#include "solver/scene/CaseSchema.h"
#include "solver/scene/Plan.h"
#include "solver/scene/SceneKind.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace lbdem::campaign {

namespace {

/// Why value is not acceptable for decl ("" when it is): numbers must parse whole.
std::string checkValue(const solver::ParamDecl& decl, const std::string& value) {
    char* end = nullptr;
    solver::ParamValue parsed = value;
    switch (decl.type) {
    case solver::ParamType::Integer: {
        const long long number = std::strtoll(value.c_str(), &end, 10);
        if (value.empty() || *end != '\0') return "'" + value + "' is not a whole number";
        parsed = number;
        break;
    }
    case solver::ParamType::Real: {
        const double number = std::strtod(value.c_str(), &end);
        if (value.empty() || *end != '\0' || !std::isfinite(number))
            return "'" + value + "' is not a number";
        parsed = number;
        break;
    }
    case solver::ParamType::Bool:
        if (value != "true" && value != "false") return "'" + value + "' is not true or false";
        parsed = value == "true";
        break;
    default:
        break;
    }
    return decl.check(parsed); // range and choice problems name the value
}

/// Split and check --vary KEY=V1,V2,... against the schema.
std::pair<std::string, std::vector<std::string>> parseVary(const std::string& vary) {
    const std::string where = "--vary " + vary;
    const auto equals = vary.find('=');
    if (equals == std::string::npos || equals == 0)
        throw solver::InputError(where + ": expected KEY=V1,V2,... (e.g. flow.nodes=8,16,32)");
    const std::string key = vary.substr(0, equals);
    const auto& schema = solver::CaseSchema::instance();
    const solver::ParamDecl* decl = schema.find(key);
    if (!decl) {
        const std::string nearest = solver::nearestWord(key, schema.paths());
        throw solver::InputError(where, 0, key,
                                 "unknown key" +
                                     (nearest.empty() ? "" : "; did you mean '" + nearest + "'?"));
    }
    if (key == "schema" || key == "name" || key == "scene")
        throw solver::InputError(where, 0, key,
                                 "a study varies a setting of one case, not its " + key);
    std::vector<std::string> values;
    std::string rest = vary.substr(equals + 1);
    for (std::size_t start = 0; start <= rest.size();) {
        const auto comma = std::min(rest.find(',', start), rest.size());
        values.push_back(rest.substr(start, comma - start));
        start = comma + 1;
    }
    for (const auto& value : values) {
        if (std::count(values.begin(), values.end(), value) > 1)
            throw solver::InputError(where, 0, key, "the value '" + value + "' is given twice");
        if (value.find('/') != std::string::npos)
            throw solver::InputError(where, 0, key, "'" + value + "' cannot name a run folder");
        if (const std::string problem = checkValue(*decl, value); !problem.empty())
            throw solver::InputError(where, 0, key, problem);
    }
    if (values.size() < 2)
        throw solver::InputError(where, 0, key, "give at least two values, separated by commas");
    return {key, values};
}

/// Check every --vary and refuse a key given twice.
std::vector<std::pair<std::string, std::vector<std::string>>>
parseVaries(const std::vector<std::string>& varies) {
    std::vector<std::pair<std::string, std::vector<std::string>>> axes;
    for (const auto& vary : varies) {
        auto axis = parseVary(vary);
        for (const auto& [key, values] : axes)
            if (key == axis.first)
                throw solver::InputError("--vary " + vary, 0, key,
                                         "the key is varied twice; give its values in one --vary");
        axes.push_back(std::move(axis));
    }
    return axes;
}

/// The cartesian product of the axes' values, the first key slowest.
std::vector<std::vector<std::string>>
product(const std::vector<std::pair<std::string, std::vector<std::string>>>& axes) {
    std::vector<std::vector<std::string>> settings{{}};
    for (const auto& [key, values] : axes) {
        std::vector<std::vector<std::string>> longer;
        for (const auto& setting : settings)
            for (const auto& value : values) {
                longer.push_back(setting);
                longer.back().push_back(value);
            }
        settings = std::move(longer);
    }
    return settings;
}

} // namespace

StudyPlan planStudy(const StudyRequest& request, const std::string& lbdem) {
    StudyPlan plan;
    StudySpec& study = plan.study;
    const auto axes = parseVaries(request.varies);
    for (const auto& axis : axes)
        study.keys.push_back(axis.first);
    for (const auto& values : product(axes)) {
        StudySetting setting{values, {}};
        const std::string label = settingLabel(study, setting);
        auto overrides = request.overrides;
        for (std::size_t k = 0; k < values.size(); ++k)
            overrides.push_back(study.keys[k] + "=" + values[k]);
        // VTK series are not needed for a study, and writing them would count in wall_s.
        if (std::find(study.keys.begin(), study.keys.end(), "output.vtk") == study.keys.end())
            overrides.push_back("output.vtk=false");
        const solver::CaseSpec spec = io::loadCase(request.casePath, overrides);
        const auto kind = spec.scene;
        if (solver::sceneDecl(kind).studyMetric.empty())
            throw solver::InputError(
                request.casePath, 0, "scene",
                std::string("'") + solver::enumWord(kind) +
                    "' is run by `lbdem verify` only, so it cannot be studied");
        solver::makePlan(spec);
        const std::string metricName =
            request.metric.empty() ? defaultStudyMetric(spec) : request.metric;
        const StudyMetric metric = resolveStudyMetric(spec, metricName);
        if (study.settings.empty()) {
            study.caseName = spec.name;
            study.metric = metric;
            // The scene cannot be varied: its resolution key is that of every setting.
            const auto resolution = std::find(study.keys.begin(), study.keys.end(),
                                              solver::sceneDecl(kind).resolutionKey);
            if (resolution != study.keys.end())
                study.resolutionKey = static_cast<int>(resolution - study.keys.begin());
        } else if (metric.name != study.metric.name) {
            throw solver::InputError("--vary: the settings have different default metrics (" +
                                     study.metric.name + ", " + metric.name +
                                     "); choose one with --metric");
        }
        if (request.reference == "analytic" && !metric.analytic)
            throw solver::InputError(std::string("--reference analytic: a run of scene '") +
                                     solver::enumWord(spec.scene) + "' with " + label +
                                     " reports no analytic or published value for " + metric.name +
                                     "; use --reference finest");
        study.metric.analytic = study.metric.analytic && metric.analytic;
        setting.dir = request.out / label;
        study.settings.push_back(setting);
        Job job{label,
                {lbdem, "run", request.casePath, "--out", setting.dir.string(), "--quiet"},
                (setting.dir / "log.txt").string()};
        for (const auto& assignment : overrides)
            job.argv.insert(job.argv.end(), {"--set", assignment});
        plan.jobs.push_back(std::move(job));
    }
    const bool analytic =
        request.reference == "analytic" || (request.reference.empty() && study.metric.analytic);
    study.reference = analytic ? StudyReference::Analytic : StudyReference::Finest;
    return plan;
}

} // namespace lbdem::campaign
