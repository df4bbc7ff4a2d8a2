// Runs commands as child processes, a bounded number at a time (sweeps and studies).
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace lbdem::cli {

/// One command to run: argv (argv[0] is the program path) and a file for its output.
struct Job {
    std::string label;
    std::vector<std::string> argv;
    std::string log_path; ///< stdout and stderr go here
};

/// The outcome of one job.
struct JobResult {
    std::string label;
    int exit_code = -1; ///< process exit code, or 128 + signal
    double wall_s = 0;
};

/// Run jobs with at most maxParallel at once; onFinished is called as each ends (in the caller's
/// thread). Returns the results in the order of jobs.
std::vector<JobResult> runJobs(const std::vector<Job>& jobs, int maxParallel,
                               const std::function<void(const JobResult&, int done, int total)>& onFinished);

/// Share the cores between maxParallel jobs going at once (OMP_NUM_THREADS for the children),
/// unless the user set OMP_NUM_THREADS.
void shareCoresBetweenJobs(int maxParallel);

/// Path of the running executable (to start lbdem itself as a child).
std::string selfExecutable();

} // namespace lbdem::cli
