// A sweep as a SLURM job array: one task per run (case x seed), resumable, gathered afterwards
// with `lbdem sweep FILE --out DIR --report`.
#pragma once

#include "campaign/SweepEnsemble.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lbdem::campaign {

/// The resources each task of the job array asks for; empty strings leave SLURM's defaults.
struct SlurmOptions {
    std::string partition;
    std::string time; ///< wall-time limit of each task: [D-]HH:MM:SS
    int cpusPerTask = 1;
};

/// Whether text is a SLURM time limit of the form HH:MM:SS or D-HH:MM:SS.
bool validSlurmTime(const std::string& text);

/// The text of the job-array script: task k runs runs[k] with `lbdem run` into its folder (a
/// folder left without a checkpoint is started afresh), or `lbdem resume` when the folder holds a
/// checkpoint, and does nothing for a run that has finished; so the script can be resubmitted.
/// Paths are made absolute; lbdem is the executable the tasks start.
std::string slurmScript(const std::string& sweepName, const std::vector<SweepRun>& runs,
                        const std::filesystem::path& out, const std::string& lbdem,
                        const SlurmOptions& options);

/// What submitSlurmSweep did.
struct SlurmSubmission {
    std::string script;       ///< OUT/sweep.sbatch
    bool sbatchFound = false; ///< sbatch is on PATH: the script was handed to it
    int status = 0;           ///< sbatch's exit status (0: submitted)
    std::string jobId;        ///< the job id sbatch gave it
    std::string output;       ///< what sbatch said when it failed
};

/// Writes OUT/sweep.sbatch (tasks start this executable) and submits it with sbatch when sbatch
/// is on PATH.
SlurmSubmission submitSlurmSweep(const std::string& sweepName, const std::vector<SweepRun>& runs,
                                 const std::filesystem::path& out, const SlurmOptions& options);

} // namespace lbdem::campaign
