// `lbdem sweep`: many cases as separate processes; skips finished runs, resumes interrupted ones.
#include "app/cli/Cli.h"
#include "app/cli/Commands.h"
#include "app/cli/JobRunner.h"
#include "app/cli/RunFolder.h"
#include "app/cli/SweepProgress.h"
#include "app/cli/SweepReport.h"
#include "solver/io/CaseLoader.h"
#include "solver/io/SweepFile.h"
#include "solver/core/InputError.h"
#include "solver/scene/Plan.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <cstdlib>
#include <thread>

namespace lbdem::cli {

namespace fs = std::filesystem;

namespace {

struct SweepOptions {
    std::string file;
    std::string out;
    int jobs = 1;
    double progressEveryS = 60;
    bool quiet = false;
};

bool finishedRun(const fs::path& dir) {
    std::ifstream file(dir / "summary.json");
    if (!file) return false;
    try {
        return nlohmann::json::parse(file).value("finished", false);
    } catch (const nlohmann::json::exception&) {
        return false;
    }
}

/// Parse and plan every case of a sweep, so that bad input is reported before anything is created
/// or run; two cases with one name (one output folder) are refused, naming both files.
std::vector<SweepEntry> loadEntries(const io::SweepSpec& sweep, const fs::path& out) {
    std::vector<SweepEntry> entries;
    std::map<std::string, std::string> fileOfName;
    for (const auto& casePath : sweep.cases) {
        const auto spec = io::loadCase(casePath, sweep.overrides);
        (void)solver::makePlan(spec); // the planner's refusals (an unstable DEM step) come now too
        const auto [first, fresh] = fileOfName.emplace(spec.name, casePath);
        if (!fresh)
            throw solver::InputError(casePath + ": the case name '" + spec.name + "' is also that of " +
                                     first->second + "; each case of a sweep needs its own name (it names "
                                     "the output folder)");
        entries.push_back({spec, out / spec.name});
    }
    return entries;
}

int runSweep(const SweepOptions& options) {
    const io::SweepSpec sweep = io::loadSweep(options.file);
    const fs::path out = options.out;
    const std::vector<SweepEntry> entries = loadEntries(sweep, out);
    fs::create_directories(out);
    const std::string self = selfExecutable();
    std::vector<Job> jobs;
    std::vector<SweepEntry> toRun;
    for (std::size_t k = 0; k < entries.size(); ++k) {
        const auto& [spec, dir] = entries[k];
        if (finishedRun(dir)) {
            if (!options.quiet) std::cout << "skip    " << spec.name << " (finished)\n";
            continue;
        }
        Job job{spec.name, {self}, (dir / "log.txt").string()};
        const bool resumable = fs::exists(dir / "checkpoint.h5");
        const bool stale = !resumable && holdsRun(dir); // a start that failed: nothing to continue
        fs::create_directories(dir);
        if (resumable) {
            job.argv.insert(job.argv.end(), {"resume", dir.string(), "--quiet"});
            if (!options.quiet) std::cout << "resume  " << spec.name << "\n";
        } else {
            job.argv.insert(job.argv.end(), {"run", sweep.cases[k], "--out", dir.string(), "--quiet"});
            if (stale) job.argv.push_back("--force");
            for (const auto& assignment : sweep.overrides) job.argv.insert(job.argv.end(), {"--set", assignment});
            if (!options.quiet) std::cout << "run     " << spec.name << "\n";
        }
        jobs.push_back(std::move(job));
        toRun.push_back(entries[k]);
    }
    std::cout.flush();
    shareCoresBetweenJobs(options.jobs);
    int failures = 0;
    SweepProgress progress(toRun, options.jobs, static_cast<int>(entries.size() - toRun.size()));
    const auto onFinished = [&](const JobResult& result, int done, int total) {
        failures += result.exit_code != 0;
        progress.finished(result.index, result.wall_s);
        if (!options.quiet)
            std::cout << "[" << done << "/" << total << "] " << result.label
                      << (result.exit_code == 0 ? " finished" : " FAILED") << " in "
                      << static_cast<long long>(result.wall_s) << " s"
                      << (result.exit_code == 0 ? "" : ": " + firstErrorLine(fs::path(jobs[result.index].log_path)))
                      << "\n"
                      << std::flush;
    };
    JobTick onTick;
    if (!options.quiet && options.progressEveryS > 0)
        onTick = [&](const std::vector<RunningJob>& running) {
            std::cout << "sweep: " << progress.line(running) << "\n" << std::flush;
        };
    runJobs(jobs, options.jobs, onFinished, onTick, options.progressEveryS);
    const auto report = writeSweepReport(sweep.name, entries, out);
    if (!options.quiet)
        for (const auto& path : report.files) std::cout << "wrote " << path << "\n";
    if (!report.note.empty() && !options.quiet) std::cerr << "note: no sweep figures: " << report.note << "\n";
    return failures == 0 ? kExitOk : kExitFailure;
}

} // namespace

void addSweepCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<SweepOptions>();
    auto* command = app.add_subcommand("sweep", "Run the cases of a sweep file as separate processes "
                                                "and write a combined table and figures");
    command->add_option("file", options->file, "Sweep file (TOML: sweep = 1, cases = [...])")->required();
    command->add_option("--out", options->out, "Output folder, one sub-folder per case")->required();
    command->add_option("--jobs", options->jobs, "Cases run at the same time")->check(CLI::Range(1, 256));
    command->add_option("--progress-every", options->progressEveryS,
                        "Seconds between progress lines (each running case's t/tau_c, ETA); 0: none")
        ->check(CLI::NonNegativeNumber);
    command->add_flag("--quiet", options->quiet, "Print nothing but errors");
    command->callback([options, &exitCode] { exitCode = runSweep(*options); });
}

} // namespace lbdem::cli
