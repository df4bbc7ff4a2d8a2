// `lbdem sweep`: the options, and the lines it prints while the campaign library runs many cases
// as separate processes (skipping finished runs, resuming interrupted ones) and reports them.
#include "app/cli/Cli.h"
#include "app/cli/Commands.h"
#include "campaign/JobRunner.h"
#include "campaign/RunJobs.h"
#include "campaign/SweepEnsemble.h"
#include "campaign/SweepProgress.h"
#include "campaign/SweepReport.h"
#include "campaign/SweepSlurm.h"
#include "campaign/figures/SweepFigures.h"
#include "solver/core/InputError.h"
#include "solver/io/RunLock.h"
#include "solver/io/SafeFile.h"
#include "solver/io/SweepFile.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <memory>

namespace lbdem::cli {

namespace fs = std::filesystem;

namespace {

using namespace campaign;

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
    const auto result = writeSweepReport(name, entries, options.out, writeSweepFigures);
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

/// Writes the SLURM job array of the sweep, submits it when sbatch is there, and says so.
int submitToSlurm(const io::SweepSpec& sweep, const std::vector<SweepRun>& runs,
                  const SweepOptions& options) {
    const auto submission = submitSlurmSweep(sweep.name, runs, options.out, options.slurmOptions);
    std::cout << "wrote " << submission.script << " (" << runs.size() << " tasks)\n";
    if (!submission.sbatchFound) {
        std::cout << "sbatch is not on PATH: submit it on the cluster with: sbatch "
                  << submission.script << "\n"
                  << "then gather the finished runs with: " << reportCommand(options) << "\n";
        return kExitOk;
    }
    if (submission.status != 0) {
        std::cerr << "lbdem: sbatch " << submission.script << " failed (" << submission.status
                  << "): " << submission.output;
        return kExitFailure;
    }
    std::cout << "submitted job " << submission.jobId << " (" << runs.size()
              << " tasks); gather the finished runs with: " << reportCommand(options) << "\n";
    return kExitOk;
}

/// The job of each run left to do (skipping finished ones, resuming interrupted ones), saying
/// which; toRun receives their entries in job order.
std::vector<Job> jobsToRun(const std::vector<SweepRun>& runs, const SweepOptions& options,
                           std::vector<SweepEntry>& toRun) {
    const std::string self = selfExecutable();
    std::vector<Job> jobs;
    for (const auto& [entry, casePath, overrides] : runs) {
        const auto& dir = entry.dir;
        const std::string label = dir.filename().string(); // case, variant and seed
        Job job{label,
                {self, "run", casePath, "--out", dir.string(), "--quiet"},
                (dir / "log.txt").string()};
        for (const auto& assignment : overrides)
            job.argv.insert(job.argv.end(), {"--set", assignment});
        const RunAction action = prepareRunJob(job, dir, false);
        if (!options.quiet)
            std::cout << (action == RunAction::Skip     ? "skip    "
                          : action == RunAction::Resume ? "resume  "
                                                        : "run     ")
                      << label << (action == RunAction::Skip ? " (finished)\n" : "\n");
        if (action == RunAction::Skip) continue;
        jobs.push_back(std::move(job));
        toRun.push_back(entry);
    }
    return jobs;
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
    if (options.slurm) return submitToSlurm(sweep, runs, options);
    if (options.report) {
        if (!fs::is_directory(out))
            throw solver::InputError("--out " + options.out +
                                     " is not a folder: there is nothing to gather (run the "
                                     "sweep into it first)");
        const io::RunLock lock(out); // not while a sweep runs into it
        report(sweep.name, entries, options);
        return kExitOk;
    }
    io::requireWritableFolder(out.string()); // exit 2, as for every command's output folder
    // One sweep at a time in a folder; each run locks its own folder too, so that a run left
    // going by an earlier sweep is never written twice.
    const io::RunLock lock(out);
    std::vector<SweepEntry> toRun;
    const std::vector<Job> jobs = jobsToRun(runs, options, toRun);
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
