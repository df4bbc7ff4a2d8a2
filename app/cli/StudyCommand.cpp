// `lbdem study`: the options, and the lines it prints while the campaign library plans the
// study, runs each setting as a separate process and tabulates them.
#include "app/cli/CaseOptions.h"
#include "app/cli/Cli.h"
#include "app/cli/Commands.h"
#include "campaign/JobRunner.h"
#include "campaign/RunJobs.h"
#include "campaign/StudyPlan.h"
#include "campaign/figures/StudyPlot.h"
#include "solver/io/SafeFile.h"
#include "solver/scene/SceneKind.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

namespace lbdem::cli {

namespace fs = std::filesystem;

namespace {

using campaign::StudySpec;

struct StudyOptions {
    CaseOptions caseOptions;
    std::vector<std::string> vary;
    std::string metric;
    std::string reference;
    std::string out;
    int jobs = 1;
    bool quiet = false;
};

/// "column_collapse runout_final, poiseuille l2_error, ...": each studied scene's default metric.
std::string sceneDefaultMetrics() {
    std::string text;
    for (const auto& decl : solver::sceneDecls())
        if (!decl.studyMetric.empty())
            text += std::string(text.empty() ? "" : ", ") + solver::enumWord(decl.kind) + " " +
                    decl.studyMetric;
    return text;
}

std::string formatNumber(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", value);
    return buffer;
}

/// Tabulate the finished study and say what was written.
void writeStudyOutputs(const StudySpec& study, const StudyOptions& options) {
    const campaign::StudyPlotter plot = campaign::studyPlotAvailable()
                                            ? campaign::StudyPlotter(campaign::writeStudyPlot)
                                            : campaign::StudyPlotter();
    const auto result = campaign::writeStudyReport(study, options.out, plot);
    if (!result.plotNote.empty() && !options.quiet)
        std::cerr << "note: " << result.plotNote << "\n";
    if (!options.quiet)
        for (const auto& path : result.files)
            std::cout << "wrote " << path << "\n";
}

/// The line printed when a study's run ends.
void reportRun(const StudySpec& study, const campaign::StudySetting& setting,
               const campaign::JobResult& result, int done, int total,
               const std::optional<std::string>& unstable) {
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
    const auto value = campaign::readStudyMetric(study, setting);
    std::cout << " finished in " << formatNumber(result.wall_s) << " s: " << study.metric.name
              << " = " << (value ? formatNumber(*value) : "(missing)") << "\n"
              << std::flush;
}

int runStudy(const StudyOptions& options) {
    const campaign::StudyRequest request{options.caseOptions.path,
                                         options.caseOptions.overrides,
                                         options.vary,
                                         options.metric,
                                         options.reference,
                                         options.out};
    // Bad input fails here, before any run.
    campaign::StudyPlan plan = campaign::planStudy(request, campaign::selfExecutable());
    const StudySpec& study = plan.study;
    io::requireWritableFolder(request.out); // exit 2, as for every command's output folder
    fs::create_directories(request.out);
    if (!campaign::studyPlotAvailable() && !options.quiet)
        std::cerr << "note: this build has no VTK (LBDEM_GUI=OFF): study.png is not drawn\n";
    std::vector<campaign::Job> jobs;
    std::vector<std::size_t> settingOf;
    for (std::size_t k = 0; k < plan.jobs.size(); ++k) {
        const fs::path& dir = study.settings[k].dir;
        const auto action = campaign::prepareRunJob(plan.jobs[k], dir, true);
        if (!options.quiet)
            std::cout << (action == campaign::RunAction::Skip     ? "skip    "
                          : action == campaign::RunAction::Resume ? "resume  "
                                                                  : "run     ")
                      << plan.jobs[k].label
                      << (action != campaign::RunAction::Skip ? "\n"
                          : campaign::runUnstable(dir)        ? " (unstable)\n"
                                                              : " (finished)\n");
        if (action == campaign::RunAction::Skip) continue;
        jobs.push_back(plan.jobs[k]);
        settingOf.push_back(k);
    }
    std::cout.flush();
    campaign::shareCoresBetweenJobs(options.jobs);
    int failures = 0;
    const auto onFinished = [&](const campaign::JobResult& result, int done, int total) {
        const auto& setting = study.settings[settingOf[result.index]];
        // A run the stability guard stopped is a result of the study, not a failure.
        const auto unstable =
            result.exit_code != 0 ? campaign::runUnstable(setting.dir) : std::nullopt;
        failures += result.exit_code != 0 && !unstable;
        if (!options.quiet) reportRun(study, setting, result, done, total, unstable);
    };
    campaign::runJobs(jobs, options.jobs, onFinished);
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
    command->add_option("--metric", options->metric,
                        "Number of summary.json to compare (default: the scene's natural "
                        "metric: " +
                            sceneDefaultMetrics() + ")");
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
