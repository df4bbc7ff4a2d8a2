// `lbdem sweep`: many cases as separate processes; skips finished runs, resumes interrupted ones.
#include "app/cli/Cli.h"
#include "app/cli/Commands.h"
#include "app/cli/JobRunner.h"
#include "app/cli/SweepProgress.h"
#include "app/cli/SweepReport.h"
#include "solver/io/CaseLoader.h"
#include "solver/io/SweepFile.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
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

int runSweep(const SweepOptions& options) {
    const io::SweepSpec sweep = io::loadSweep(options.file);
    const fs::path out = options.out;
    fs::create_directories(out);
    const std::string self = selfExecutable();
    std::vector<Job> jobs;
    std::vector<SweepEntry> entries, toRun;
    for (const auto& casePath : sweep.cases) {
        const auto spec = io::loadCase(casePath, sweep.overrides); // bad input fails before any run
        const fs::path dir = out / spec.name;
        entries.push_back({spec, dir});
        if (finishedRun(dir)) {
            if (!options.quiet) std::cout << "skip    " << spec.name << " (finished)\n";
            continue;
        }
        Job job{spec.name, {self}, (dir / "log.txt").string()};
        fs::create_directories(dir);
        if (fs::exists(dir / "checkpoint.h5")) {
            job.argv.insert(job.argv.end(), {"resume", dir.string(), "--quiet"});
            if (!options.quiet) std::cout << "resume  " << spec.name << "\n";
        } else {
            job.argv.insert(job.argv.end(), {"run", casePath, "--out", dir.string(), "--quiet"});
            for (const auto& assignment : sweep.overrides) job.argv.insert(job.argv.end(), {"--set", assignment});
            if (!options.quiet) std::cout << "run     " << spec.name << "\n";
        }
        jobs.push_back(std::move(job));
        toRun.push_back(entries.back());
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
                      << (result.exit_code == 0 ? " finished" : " FAILED (see its log.txt)") << " in "
                      << static_cast<long long>(result.wall_s) << " s\n"
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
