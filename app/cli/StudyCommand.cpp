// `lbdem study`: one case over several values of one or more keys (their cartesian product), each
// run as a separate process, then a table, a figure of the metric's error against wall time and,
// over two or more keys, a map of the bounded and unstable settings.
#include "app/cli/CaseOptions.h"
#include "app/cli/Cli.h"
#include "app/cli/Commands.h"
#include "app/cli/JobRunner.h"
#include "app/cli/RunFolder.h"
#include "app/cli/StudyMap.h"
#include "app/cli/StudyMetrics.h"
#include "app/cli/StudyPlot.h"
#include "app/cli/StudyReport.h"
#include "solver/core/InputError.h"
#include "solver/core/TextDistance.h"
#include "solver/io/CaseLoader.h"
#include "solver/scene/CaseSchema.h"
#include "solver/scene/FlowPlan.h"
#include "solver/scene/Plan.h"
#include "solver/scene/SceneKind.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <thread>

namespace lbdem::cli {

namespace fs = std::filesystem;

namespace {

struct StudyOptions {
    CaseOptions caseOptions;
    std::vector<std::string> vary;
    std::string metric;
    std::string reference;
    std::string out;
    int jobs = 1;
    bool quiet = false;
};

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

/// Load, plan and check every setting before any run starts; fills study and the runs' argv.
std::vector<Job> prepare(const StudyOptions& options, StudySpec& study) {
    const auto axes = parseVaries(options.vary);
    for (const auto& axis : axes) {
        if (study.resolutionKey < 0 && isResolutionKey(axis.first))
            study.resolutionKey = static_cast<int>(study.keys.size());
        study.keys.push_back(axis.first);
    }
    const fs::path out = options.out;
    const std::string self = selfExecutable();
    std::vector<Job> jobs;
    for (const auto& values : product(axes)) {
        StudySetting setting{values, {}};
        const std::string label = settingLabel(study, setting);
        auto overrides = options.caseOptions.overrides;
        for (std::size_t k = 0; k < values.size(); ++k)
            overrides.push_back(study.keys[k] + "=" + values[k]);
        // VTK series are not needed for a study, and writing them would count in wall_s.
        if (std::find(study.keys.begin(), study.keys.end(), "output.vtk") == study.keys.end())
            overrides.push_back("output.vtk=false");
        const solver::CaseSpec spec = io::loadCase(options.caseOptions.path, overrides);
        const auto kind = spec.scene;
        if (!solver::isFlowScene(kind) && kind != solver::SceneKind::ColumnCollapse)
            throw solver::InputError(
                options.caseOptions.path, 0, "scene",
                std::string("'") + solver::enumWord(kind) +
                    "' is run by `lbdem verify` only, so it cannot be studied");
        solver::makePlan(spec);
        const std::string metricName =
            options.metric.empty() ? defaultStudyMetric(spec) : options.metric;
        const StudyMetric metric = resolveStudyMetric(spec, metricName);
        if (study.settings.empty()) {
            study.caseName = spec.name;
            study.metric = metric;
        } else if (metric.name != study.metric.name) {
            throw solver::InputError("--vary: the settings have different default metrics (" +
                                     study.metric.name + ", " + metric.name +
                                     "); choose one with --metric");
        }
        if (options.reference == "analytic" && !metric.analytic)
            throw solver::InputError(std::string("--reference analytic: a run of scene '") +
                                     solver::enumWord(spec.scene) + "' with " + label +
                                     " reports no analytic or published value for " + metric.name +
                                     "; use --reference finest");
        study.metric.analytic = study.metric.analytic && metric.analytic;
        setting.dir = out / label;
        study.settings.push_back(setting);
        Job job{label,
                {self, "run", options.caseOptions.path, "--out", setting.dir.string(), "--quiet"},
                (setting.dir / "log.txt").string()};
        for (const auto& assignment : overrides)
            job.argv.insert(job.argv.end(), {"--set", assignment});
        jobs.push_back(std::move(job));
    }
    const bool analytic =
        options.reference == "analytic" || (options.reference.empty() && study.metric.analytic);
    study.reference = analytic ? StudyReference::Analytic : StudyReference::Finest;
    return jobs;
}

std::string formatNumber(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", value);
    return buffer;
}

/// Tabulate the finished study: study.csv/.md, study.png when it has an error scale, and
/// study_map.md over two or more keys.
void writeStudyOutputs(const StudySpec& study, const StudyOptions& options) {
    const fs::path out = options.out;
    const auto rows = tabulateStudy(study);
    // Over several keys with neither an analytic value nor a resolution key, the "error" is a
    // difference from the last value of a key: tabulated, but not worth a figure.
    const bool noErrorScale = study.keys.size() > 1 && study.resolutionKey < 0 &&
                              study.reference == StudyReference::Finest;
    const bool plotted = !noErrorScale && writeStudyPlot(study, rows, (out / "study.png").string());
    std::string plotNote;
    if (noErrorScale && studyPlotAvailable())
        plotNote = "The errors are differences from the last value of " + study.keys.back() +
                   ", neither an analytic value nor a finer resolution, so study.png is not drawn.";
    else if (studyPlotAvailable() && !plotted)
        plotNote = "No setting has a positive error and wall time, so study.png is not drawn.";
    if (!plotNote.empty() && !options.quiet) std::cerr << "note: " << plotNote << "\n";
    auto written = writeStudyTables(study, rows, out, plotted, plotNote);
    if (study.keys.size() > 1) written.push_back(writeStudyMap(study, rows, out));
    if (!options.quiet)
        for (const auto& path : written)
            std::cout << "wrote " << path << "\n";
}

int runStudy(const StudyOptions& options) {
    StudySpec study;
    std::vector<Job> planned = prepare(options, study); // bad input fails here, before any run
    const fs::path out = options.out;
    fs::create_directories(out);
    if (!studyPlotAvailable() && !options.quiet)
        std::cerr << "note: this build has no VTK (LBDEM_GUI=OFF): study.png is not drawn\n";
    std::vector<Job> jobs;
    std::vector<std::size_t> settingOf;
    for (std::size_t k = 0; k < planned.size(); ++k) {
        const fs::path& dir = study.settings[k].dir;
        if (runFinished(dir) || runUnstable(dir)) {
            if (!options.quiet)
                std::cout << "skip    " << planned[k].label
                          << (runUnstable(dir) ? " (unstable)\n" : " (finished)\n");
            continue;
        }
        fs::create_directories(dir);
        if (fs::exists(dir / "checkpoint.h5")) {
            planned[k].argv = {planned[k].argv.front(), "resume", dir.string(), "--quiet"};
            if (!options.quiet) std::cout << "resume  " << planned[k].label << "\n";
        } else {
            if (holdsRun(dir))
                planned[k].argv.push_back("--force"); // a start that failed: nothing to continue
            if (!options.quiet) std::cout << "run     " << planned[k].label << "\n";
        }
        jobs.push_back(planned[k]);
        settingOf.push_back(k);
    }
    std::cout.flush();
    shareCoresBetweenJobs(options.jobs);
    int failures = 0;
    runJobs(jobs, options.jobs, [&](const JobResult& result, int done, int total) {
        std::size_t k = 0;
        while (k < jobs.size() && jobs[k].label != result.label)
            ++k;
        const StudySetting& setting = study.settings[settingOf[k]];
        // A run the stability guard stopped is a result of the study, not a failure.
        const auto unstable = result.exit_code != 0 ? runUnstable(setting.dir) : std::nullopt;
        failures += result.exit_code != 0 && !unstable;
        if (options.quiet) return;
        std::cout << "[" << done << "/" << total << "] " << result.label;
        if (unstable) {
            std::cout << " unstable after " << formatNumber(result.wall_s) << " s: " << *unstable
                      << "\n"
                      << std::flush;
            return;
        }
        if (result.exit_code != 0) {
            std::cout << " FAILED (see its log.txt)\n" << std::flush;
            return;
        }
        const auto value = readStudyMetric(study, setting);
        std::cout << " finished in " << formatNumber(result.wall_s) << " s: " << study.metric.name
                  << " = " << (value ? formatNumber(*value) : "(missing)") << "\n"
                  << std::flush;
    });
    writeStudyOutputs(study, options);
    return failures == 0 ? kExitOk : kExitFailure;
}

} // namespace

void addStudyCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<StudyOptions>();
    auto* command = app.add_subcommand(
        "study", "Run a case over several values of one or more keys (their product, separate "
                 "processes) and tabulate a metric's error against wall time");
    options->caseOptions.addTo(*command);
    command
        ->add_option("--vary", options->vary,
                     "KEY=V1,V2,...: a key and its values, e.g. flow.nodes=8,16,32; repeat it to "
                     "run the cartesian product of several keys (also writes study_map.md)")
        ->required()
        ->allow_extra_args(false);
    command->add_option(
        "--metric", options->metric,
        "Number of summary.json to compare (default: the scene's natural metric: poiseuille "
        "l2_error, taylor_green decay_rate_1_s, cavity ghia_max_deviation, cylinder "
        "drag_coefficient, column_collapse runout_final)");
    command
        ->add_option(
            "--reference", options->reference,
            "What the error is measured against: analytic (the analytic or published value) or "
            "finest (the finest setting); default analytic when the metric has one")
        ->check(CLI::IsMember({"analytic", "finest"}));
    command
        ->add_option("--out", options->out,
                     "Output folder: one run folder per setting, study.csv/.md/.png")
        ->required();
    command
        ->add_option("--jobs", options->jobs, "Runs at the same time (timings are fairest with 1)")
        ->check(CLI::Range(1, 256));
    command->add_flag("--quiet", options->quiet, "Print nothing but errors");
    command->callback([options, &exitCode] { exitCode = runStudy(*options); });
}

} // namespace lbdem::cli
