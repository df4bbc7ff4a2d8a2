// Runs commands as child processes, a bounded number at a time (sweeps and studies).
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace lbdem::campaign {

/// One command to run: argv (argv[0] is the program path) and a file for its output.
struct Job {
    std::string label;
    std::vector<std::string> argv;
    std::string log_path; ///< stdout and stderr go here
};

/// The outcome of one job.
struct JobResult {
    std::string label;
    std::size_t index = 0; ///< position in the job list
    int exit_code = -1;    ///< process exit code, or 128 + signal
    double wall_s = 0;
};

/// A job still going: its index in the job list and its wall time so far.
struct RunningJob {
    std::size_t index = 0;
    double wall_s = 0;
};

/// Called every tickPeriodS while jobs run, with the running jobs in the order they started.
using JobTick = std::function<void(const std::vector<RunningJob>& running)>;

/// Run jobs with at most maxParallel at once; onFinished is called as each ends and onTick (if
/// set) every tickPeriodS, both in the caller's thread. Returns the results in the order of jobs.
std::vector<JobResult>
runJobs(const std::vector<Job>& jobs, int maxParallel,
        const std::function<void(const JobResult&, int done, int total)>& onFinished,
        const JobTick& onTick = {}, double tickPeriodS = 60);

/// Share the cores between maxParallel jobs going at once (OMP_NUM_THREADS for the children),
/// unless the user set OMP_NUM_THREADS.
void shareCoresBetweenJobs(int maxParallel);

/// In a process started by runJobs: end when the process that started it ends (a killed sweep
/// or study leaves no run going, which a restarted one would race); SIGTERM is delivered then,
/// on Linux. Elsewhere, and outside runJobs, it does nothing.
void endWithParent();

/// Path of the running executable (to start lbdem itself as a child).
std::string selfExecutable();

} // namespace lbdem::campaign
