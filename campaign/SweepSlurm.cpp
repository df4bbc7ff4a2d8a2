// The SLURM job-array script of a sweep and its submission with sbatch.
#include "campaign/SweepSlurm.h"

#include "campaign/JobRunner.h"
#include "solver/io/CaseWriter.h"

#include <cstdio>
#include <cstdlib>
#include <regex>
#include <sstream>
#include <unistd.h>

namespace lbdem::campaign {

namespace fs = std::filesystem;

namespace {

/// text in single quotes for bash (a quote inside becomes '\'').
std::string quoted(const std::string& text) {
    std::string result = "'";
    for (const char c : text)
        result += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return result + "'";
}

/// The path of program in one of PATH's folders; empty when it is in none.
std::string onPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    std::stringstream folders(path ? path : "");
    for (std::string folder; std::getline(folders, folder, ':');) {
        const fs::path candidate = fs::path(folder.empty() ? "." : folder) / program;
        if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
    }
    return "";
}

/// The output of a shell command (stdout and stderr) and its exit status.
std::pair<std::string, int> capture(const std::string& command) {
    std::string output;
    FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return {"cannot start: " + command, -1};
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, pipe))
        output += buffer;
    const int status = ::pclose(pipe);
    return {output, WIFEXITED(status) ? WEXITSTATUS(status) : -1};
}

/// The #SBATCH header of the job array.
std::string header(const std::string& sweepName, std::size_t tasks, const fs::path& out,
                   const SlurmOptions& options) {
    std::string text = "#!/bin/bash\n";
    text += "#SBATCH --job-name=" + quoted("lbdem-" + sweepName) + "\n";
    text += "#SBATCH --array=0-" + std::to_string(tasks - 1) + "\n";
    text += "#SBATCH --output=" + quoted((out / "slurm" / "task_%a.out").string()) + "\n";
    text +=
        "#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=" + std::to_string(options.cpusPerTask) + "\n";
    if (!options.partition.empty())
        text += "#SBATCH --partition=" + quoted(options.partition) + "\n";
    if (!options.time.empty()) text += "#SBATCH --time=" + options.time + "\n";
    return text;
}

} // namespace

bool validSlurmTime(const std::string& text) {
    static const std::regex pattern(R"(^([0-9]+-)?[0-9]{1,2}:[0-5][0-9]:[0-5][0-9]$)");
    return std::regex_match(text, pattern);
}

std::string slurmScript(const std::string& sweepName, const std::vector<SweepRun>& runs,
                        const fs::path& out, const std::string& lbdem,
                        const SlurmOptions& options) {
    const fs::path folder = fs::absolute(out);
    std::string text = header(sweepName, runs.size(), folder, options);
    text += "# Written by `lbdem sweep --slurm`: task k runs one case with one packing seed into "
            "its own folder,\n"
            "# continues it from its checkpoint, or does nothing once it has finished; resubmit to "
            "go on.\n"
            "# Gather the finished runs with `lbdem sweep FILE --out DIR --report`.\n"
            "set -u\n"
            "export OMP_NUM_THREADS=\"${SLURM_CPUS_PER_TASK:-1}\"\n"
            "lbdem=" +
            quoted(lbdem) +
            "\n"
            "case \"${SLURM_ARRAY_TASK_ID:?run this script with sbatch}\" in\n";
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const auto& run = runs[k];
        text += std::to_string(k) + ") dir=" + quoted(fs::absolute(run.entry.dir).string()) +
                "; set -- run " + quoted(fs::absolute(run.casePath).string());
        for (const auto& assignment : run.overrides)
            text += " --set " + quoted(assignment);
        text += " ;;\n";
    }
    text += "*) echo \"no task $SLURM_ARRAY_TASK_ID in this array\" >&2; exit 2 ;;\nesac\n"
            "if grep -qs '\"finished\": true' \"$dir/summary.json\"; then echo \"$dir: finished\"; "
            "exit 0; fi\n"
            "if [ -f \"$dir/checkpoint.h5\" ]; then\n"
            "    set -- resume \"$dir\"\n"
            "else\n"
            "    rm -rf -- \"$dir\" # a start that left no checkpoint: nothing to continue\n"
            "    set -- \"$@\" --out \"$dir\"\n"
            "fi\n"
            "mkdir -p \"$dir\"\n"
            "echo \"task $SLURM_ARRAY_TASK_ID on $(hostname): lbdem $1 $dir\"\n"
            "exec \"$lbdem\" \"$@\" --quiet >>\"$dir/log.txt\" 2>&1\n";
    return text;
}

SlurmSubmission submitSlurmSweep(const std::string& sweepName, const std::vector<SweepRun>& runs,
                                 const fs::path& out, const SlurmOptions& options) {
    fs::create_directories(out / "slurm");
    SlurmSubmission submission;
    const fs::path script = out / "sweep.sbatch";
    submission.script = script.string();
    io::writeFileAtomically(script.string(),
                            slurmScript(sweepName, runs, out, selfExecutable(), options));
    fs::permissions(script, fs::perms::owner_exec, fs::perm_options::add);
    const std::string sbatch = onPath("sbatch");
    if (sbatch.empty()) return submission;
    submission.sbatchFound = true;
    const auto [output, status] =
        capture(quoted(sbatch) + " --parsable " + quoted(script.string()));
    submission.status = status;
    if (status != 0)
        submission.output = output;
    else
        submission.jobId = output.substr(0, output.find_first_of(";\n"));
    return submission;
}

} // namespace lbdem::campaign
