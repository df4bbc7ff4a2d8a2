// `lbdem study`: one case over several values of a key, each run as a separate process, then a
// table and a figure of the metric's error against wall time.
#include "app/cli/CaseOptions.h"
#include "app/cli/Cli.h"
#include "app/cli/Commands.h"
#include "app/cli/JobRunner.h"
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
    std::string vary;
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

/// Load, plan and check every setting before any run starts; fills study and the runs' argv.
std::vector<Job> prepare(const StudyOptions& options, StudySpec& study) {
    const auto [key, values] = parseVary(options.vary);
    study.key = key;
    study.resolution = isResolutionKey(key);
    const fs::path out = options.out;
    const std::string self = selfExecutable();
    std::vector<Job> jobs;
    for (const auto& value : values) {
        auto overrides = options.caseOptions.overrides;
        overrides.push_back(key + "=" + value);
        // VTK series are not needed for a study, and writing them would count in wall_s.
        if (key != "output.vtk") overrides.push_back("output.vtk=false");
        const solver::CaseSpec spec = io::loadCase(options.caseOptions.path, overrides);
        const auto kind = solver::sceneFromName(spec.scene);
        if (!solver::isFlowScene(kind) && kind != solver::SceneKind::ColumnCollapse)
            throw solver::InputError(
                options.caseOptions.path, 0, "scene",
                "'" + spec.scene + "' is run by `lbdem verify` only, so it cannot be studied");
        solver::makePlan(spec);
        const std::string metricName =
            options.metric.empty() ? defaultStudyMetric(spec) : options.metric;
        const StudyMetric metric = resolveStudyMetric(spec, metricName);
        if (study.settings.empty()) {
            study.caseName = spec.name;
            study.metric = metric;
        } else if (metric.name != study.metric.name) {
            throw solver::InputError(
                "--vary " + options.vary + ": the settings have different default metrics (" +
                study.metric.name + ", " + metric.name + "); choose one with --metric");
        }
        if (options.reference == "analytic" && !metric.analytic)
            throw solver::InputError("--reference analytic: a run of scene '" + spec.scene +
                                     "' with " + key + "=" + value +
                                     " reports no analytic or published value for " + metric.name +
                                     "; use --reference finest");
        study.metric.analytic = study.metric.analytic && metric.analytic;
        const fs::path dir = out / (key + "=" + value);
        study.settings.push_back({value, dir});
        Job job{key + "=" + value,
                {self, "run", options.caseOptions.path, "--out", dir.string(), "--quiet"},
                (dir / "log.txt").string()};
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
        if (runFinished(dir)) {
            if (!options.quiet) std::cout << "skip    " << planned[k].label << " (finished)\n";
            continue;
        }
        fs::create_directories(dir);
        if (fs::exists(dir / "checkpoint.h5")) {
            planned[k].argv = {planned[k].argv.front(), "resume", dir.string(), "--quiet"};
            if (!options.quiet) std::cout << "resume  " << planned[k].label << "\n";
        } else if (!options.quiet) {
            std::cout << "run     " << planned[k].label << "\n";
        }
        jobs.push_back(planned[k]);
        settingOf.push_back(k);
    }
    std::cout.flush();
    // Share the cores between the runs that go at once instead of oversubscribing them.
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    if (options.jobs > 1 && !std::getenv("OMP_NUM_THREADS"))
        ::setenv("OMP_NUM_THREADS", std::to_string(std::max(1u, cores / options.jobs)).c_str(), 1);
    int failures = 0;
    runJobs(jobs, options.jobs, [&](const JobResult& result, int done, int total) {
        failures += result.exit_code != 0;
        if (options.quiet) return;
        std::cout << "[" << done << "/" << total << "] " << result.label;
        if (result.exit_code != 0) {
            std::cout << " FAILED (see its log.txt)\n" << std::flush;
            return;
        }
        std::size_t k = 0;
        while (k < jobs.size() && jobs[k].label != result.label)
            ++k;
        const auto value = readStudyMetric(study, study.settings[settingOf[k]]);
        std::cout << " finished in " << formatNumber(result.wall_s) << " s: " << study.metric.name
                  << " = " << (value ? formatNumber(*value) : "(missing)") << "\n"
                  << std::flush;
    });
    const auto rows = tabulateStudy(study);
    const bool plotted = writeStudyPlot(study, rows, (out / "study.png").string());
    if (studyPlotAvailable() && !plotted && !options.quiet)
        std::cerr
            << "note: no setting has a positive error and wall time: study.png is not drawn\n";
    const auto written = writeStudyTables(study, rows, out, plotted);
    if (!options.quiet)
        for (const auto& path : written)
            std::cout << "wrote " << path << "\n";
    return failures == 0 ? kExitOk : kExitFailure;
}

} // namespace

void addStudyCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<StudyOptions>();
    auto* command = app.add_subcommand(
        "study", "Run a case over several values of one key (separate processes) "
                 "and tabulate a metric's error against wall time");
    options->caseOptions.addTo(*command);
    command
        ->add_option("--vary", options->vary,
                     "KEY=V1,V2,...: the key and its values, e.g. flow.nodes=8,16,32")
        ->required();
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
                     "Output folder: one run folder per value, study.csv/.md/.png")
        ->required();
    command
        ->add_option("--jobs", options->jobs, "Runs at the same time (timings are fairest with 1)")
        ->check(CLI::Range(1, 256));
    command->add_flag("--quiet", options->quiet, "Print nothing but errors");
    command->callback([options, &exitCode] { exitCode = runStudy(*options); });
}

} // namespace lbdem::cli
