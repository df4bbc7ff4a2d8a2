// run.json: which run a folder holds (a run id and the hash of its case), so that a checkpoint
// copied in from another run's folder is told apart from the folder's own.
#pragma once

#include "solver/io/Checkpoint.h"

#include <filesystem>
#include <optional>
#include <string>

namespace lbdem::io {

/// The identity of one run: drawn when `lbdem run` starts it, kept by every resume.
struct RunIdentity {
    std::string run_id;    ///< 32 random hex digits
    std::string case_hash; ///< solver::checksumOf the resolved case text (case.toml)
};

/// A fresh identity for a run of the resolved case text caseToml.
RunIdentity newRunIdentity(const std::string& caseToml);

/// Write dir/run.json atomically.
void writeRunIdentity(const std::filesystem::path& dir, const RunIdentity& identity);

/// The identity in dir/run.json; none when the file is absent (a folder of an older lbdem).
/// Throws InputError naming the file when it is there but unreadable.
std::optional<RunIdentity> readRunIdentity(const std::filesystem::path& dir);

/// Refuse (InputError naming both) a checkpoint at path that another run wrote than the one
/// whose identity folder holds: a different run id or case, or no run id where the folder has
/// one. A folder and checkpoint that both predate run ids pass.
void checkCheckpointBelongs(const std::string& path, const CheckpointData& checkpoint,
                            const std::optional<RunIdentity>& folder);

} // namespace lbdem::io
