// Child processes with posix_spawn, output redirected to a log file per job.
#include "campaign/JobRunner.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fcntl.h>
#include <map>
#include <spawn.h>
#include <stdexcept>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

#ifdef __linux__
#include <csignal>
#include <sys/prctl.h>
#endif

extern char** environ;

namespace lbdem::campaign {

namespace {

using Clock = std::chrono::steady_clock;

// Names the process that started a job, so that the job can end when it does.
constexpr const char* kParentVariable = "LBDEM_PARENT_PID";

/// This process's environment, with kParentVariable set to its pid, for its children.
std::vector<std::string> childEnvironment() {
    const std::string prefix = std::string(kParentVariable) + "=";
    std::vector<std::string> environment;
    for (char** entry = environ; *entry; ++entry)
        if (std::string(*entry).rfind(prefix, 0) != 0) environment.emplace_back(*entry);
    environment.push_back(prefix + std::to_string(::getpid()));
    return environment;
}

pid_t spawnJob(const Job& job) {
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, job.log_path.c_str(),
                                     O_WRONLY | O_CREAT | O_APPEND, 0644);
    posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    std::vector<char*> argv;
    for (const auto& arg : job.argv)
        argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    const std::vector<std::string> environment = childEnvironment();
    std::vector<char*> envp;
    for (const auto& entry : environment)
        envp.push_back(const_cast<char*>(entry.c_str()));
    envp.push_back(nullptr);
    pid_t pid = 0;
    const int error = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
    posix_spawn_file_actions_destroy(&actions);
    if (error != 0)
        throw std::runtime_error("cannot start " + job.argv.front() + " for " + job.label);
    return pid;
}

} // namespace

std::vector<JobResult> runJobs(const std::vector<Job>& jobs, int maxParallel,
                               const std::function<void(const JobResult&, int, int)>& onFinished,
                               const JobTick& onTick, double tickPeriodS) {
    constexpr auto kPollPeriod = std::chrono::milliseconds(200);
    std::vector<JobResult> results(jobs.size());
    std::map<pid_t, std::pair<std::size_t, Clock::time_point>> running;
    std::size_t next = 0;
    int done = 0;
    const int total = static_cast<int>(jobs.size());
    const auto tickPeriod =
        std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(tickPeriodS));
    auto nextTick = Clock::now() + tickPeriod;
    while (next < jobs.size() || !running.empty()) {
        while (next < jobs.size() && static_cast<int>(running.size()) < std::max(1, maxParallel)) {
            running[spawnJob(jobs[next])] = {next, Clock::now()};
            ++next;
        }
        int status = 0;
        const pid_t pid = ::waitpid(-1, &status, onTick ? WNOHANG : 0);
        if (pid < 0) break;
        if (pid == 0) { // nothing ended yet (only when ticking)
            if (Clock::now() >= nextTick) {
                std::vector<RunningJob> going;
                for (const auto& [child, job] : running)
                    going.push_back(
                        {job.first,
                         std::chrono::duration<double>(Clock::now() - job.second).count()});
                std::sort(going.begin(), going.end(), [](const RunningJob& a, const RunningJob& b) {
                    return a.index < b.index;
                });
                onTick(going);
                nextTick = Clock::now() + tickPeriod;
            }
            std::this_thread::sleep_for(kPollPeriod);
            continue;
        }
        const auto found = running.find(pid);
        if (found == running.end()) continue;
        auto& result = results[found->second.first];
        result.label = jobs[found->second.first].label;
        result.index = found->second.first;
        result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        result.wall_s = std::chrono::duration<double>(Clock::now() - found->second.second).count();
        running.erase(found);
        ++done;
        if (onFinished) onFinished(result, done, total);
    }
    return results;
}

void endWithParent() {
    const char* parent = std::getenv(kParentVariable);
    if (!parent || !*parent) return;
    const long parentPid = std::strtol(parent, nullptr, 10);
    ::unsetenv(kParentVariable); // not for this process's own children
#ifdef __linux__
    // SIGTERM, not SIGKILL: a run that catches it can stop between steps with a checkpoint.
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
#endif
    // The parent may have died before prctl took effect: then no signal comes, so end now.
    if (::getppid() != static_cast<pid_t>(parentPid)) std::_Exit(143);
}

std::string selfExecutable() {
    std::string path(4096, '\0');
    const ssize_t length = ::readlink("/proc/self/exe", path.data(), path.size() - 1);
    if (length <= 0) throw std::runtime_error("cannot find the lbdem executable (/proc/self/exe)");
    path.resize(static_cast<std::size_t>(length));
    return path;
}

void shareCoresBetweenJobs(int maxParallel) {
    // Oversubscribed cores slow every job down (busy-waiting OpenMP threads most of all).
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    if (maxParallel > 1 && !std::getenv("OMP_NUM_THREADS"))
        ::setenv("OMP_NUM_THREADS",
                 std::to_string(std::max(1u, cores / static_cast<unsigned>(maxParallel))).c_str(),
                 1);
}

} // namespace lbdem::campaign
