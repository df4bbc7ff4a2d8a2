// `lbdem sweep`: many cases as separate processes; skips finished runs, resumes interrupted ones.
#include "app/cli/Cli.h"
#include "app/cli/Commands.h"
#include "app/cli/JobRunner.h"
#include "app/cli/RunFolder.h"
#include "app/cli/SweepEnsemble.h"
#include "app/cli/SweepProgress.h"
#include "app/cli/SweepReport.h"
#include "app/cli/SweepSlurm.h"
#include "solver/core/InputError.h"
#include "solver/io/CaseLoader.h"
#include "solver/io/SweepFile.h"
#include "solver/scene/Plan.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
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
    int seeds = 0; ///< --seeds N: seeds 1..N instead of the sweep file's `seeds`
    bool slurm = false, report = false;
    SlurmOptions slurmOptions;
};

/// Writes the sweep's tables, figures and findings and says what it wrote.
void report(const std::string& name, const std::vector<SweepEntry>& entries,
            const SweepOptions& options) {
    const auto result = writeSweepReport(name, entries, options.out);
    if (!options.quiet)
        for (const auto& path : result.files)
            std::cout << "wrote " << path << "\n";
    if (!result.note.empty() && !options.quiet)
        std::cerr << "note: no sweep figures: " << result.note << "\n";
}

/// The command that gathers the report of this sweep.
std::string reportCommand(const SweepOptions& options) {
    return "lbdem sweep " + options.file + " --out " + options.out + " --report" +
           (options.seeds > 0 ? " --seeds " + std::to_string(options.seeds) : "");
}

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
    // Each case once, or once per packing seed; bad input fails before any run.
    const auto runs =
        planSweepRuns(sweep, options.seeds > 0 ? firstSeeds(options.seeds) : sweep.seeds, out);
    std::vector<SweepEntry> entries;
    for (const auto& run : runs)
        entries.push_back(run.entry);
    if (options.slurm)
        return submitSlurmSweep(sweep.name, runs, out, options.slurmOptions,
                                reportCommand(options));
    if (options.report) {
        report(sweep.name, entries, options);
        return kExitOk;
    }
    fs::create_directories(out);
    const std::string self = selfExecutable();
    std::vector<Job> jobs;
    std::vector<SweepEntry> toRun;
    for (const auto& [entry, casePath, overrides] : runs) {
        const auto& [spec, dir, seed] = entry;
        const std::string label = dir.filename().string(); // the case, or the case and its seed
        if (finishedRun(dir)) {
            if (!options.quiet) std::cout << "skip    " << label << " (finished)\n";
            continue;
        }
        Job job{label, {self}, (dir / "log.txt").string()};
        const bool resumable = fs::exists(dir / "checkpoint.h5");
        const bool stale = !resumable && holdsRun(dir); // a start that failed: nothing to continue
        fs::create_directories(dir);
        if (resumable) {
            job.argv.insert(job.argv.end(), {"resume", dir.string(), "--quiet"});
            if (!options.quiet) std::cout << "resume  " << label << "\n";
        } else {
            job.argv.insert(job.argv.end(), {"run", casePath, "--out", dir.string(), "--quiet"});
            if (stale) job.argv.push_back("--force");
            for (const auto& assignment : overrides)
                job.argv.insert(job.argv.end(), {"--set", assignment});
            if (!options.quiet) std::cout << "run     " << label << "\n";
        }
        jobs.push_back(std::move(job));
        toRun.push_back(entry);
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
                      << (result.exit_code == 0
                              ? ""
                              : ": " + firstErrorLine(fs::path(jobs[result.index].log_path)))
                      << "\n"
                      << std::flush;
    };
    JobTick onTick;
    if (!options.quiet && options.progressEveryS > 0)
        onTick = [&](const std::vector<RunningJob>& running) {
            std::cout << "sweep: " << progress.line(running) << "\n" << std::flush;
        };
    runJobs(jobs, options.jobs, onFinished, onTick, options.progressEveryS);
    report(sweep.name, entries, options);
    return failures == 0 ? kExitOk : kExitFailure;
}

} // namespace

void addSweepCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<SweepOptions>();
    auto* command =
        app.add_subcommand("sweep", "Run the cases of a sweep file as separate processes "
                                    "and write a combined table and figures");
    command->add_option("file", options->file, "Sweep file (TOML: sweep = 1, cases = [...])")
        ->required();
    command->add_option("--out", options->out, "Output folder, one sub-folder per case")
        ->required();
    command->add_option("--jobs", options->jobs, "Cases run at the same time")
        ->check(CLI::Range(1, 256));
    command
        ->add_option("--progress-every", options->progressEveryS,
                     "Seconds between progress lines (each running case's t/tau_c, ETA); 0: none")
        ->check(CLI::NonNegativeNumber);
    command->add_flag("--quiet", options->quiet, "Print nothing but errors");
    command
        ->add_option("--seeds", options->seeds,
                     "Run each case once per packing seed 1..N (grains.seed), each into CASE_sK; "
                     "replaces the sweep file's seeds")
        ->check(CLI::Range(1, 1000));
    auto* slurm =
        command->add_flag("--slurm", options->slurm,
                          "Write OUT/sweep.sbatch (a SLURM job array, one task per case and seed) "
                          "and submit it with sbatch when sbatch is on PATH; runs nothing here");
    command
        ->add_option("--partition", options->slurmOptions.partition, "SLURM partition of the tasks")
        ->needs(slurm);
    command
        ->add_option("--time", options->slurmOptions.time,
                     "SLURM time limit of each task, [D-]HH:MM:SS")
        ->needs(slurm)
        ->check(CLI::Validator(
            [](std::string& text) {
                return validSlurmTime(text) ? "" : "expected [D-]HH:MM:SS, got " + text;
            },
            "TIME"));
    command
        ->add_option("--cpus-per-task", options->slurmOptions.cpusPerTask,
                     "Cores of each SLURM task")
        ->needs(slurm)
        ->check(CLI::Range(1, 1024));
    command
        ->add_flag(
            "--report", options->report,
            "Run nothing: gather the runs that have finished in OUT into the tables, figures "
            "and findings")
        ->excludes(slurm);
    command->callback([options, &exitCode] { exitCode = runSweep(*options); });
}

} // namespace lbdem::cli
