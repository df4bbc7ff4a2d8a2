// checkpoint.h5: the resolved case and the complete solver state, written atomically.
#pragma once

#include "solver/core/StateArchive.h"

#include <string>

namespace lbdem::io {

/// What a checkpoint file holds.
struct CheckpointData {
    std::string case_toml;      ///< the resolved case (io::formatCase), to rebuild the Simulation
    solver::StateArchive state; ///< the solver state (Simulation::saveState)
    std::string run_id{};    ///< the run that wrote it (run.json of its folder); "" before format 3
    std::string case_hash{}; ///< checksum of case_toml, as run.json gives it; "" before format 3
    bool verified = true;    ///< read back with its checksum (false only when accepted without)
};

/// Write data to path as HDF5 through a temporary file renamed over path, so that a run killed
/// at any moment leaves either the previous or the new checkpoint, never a torn one; a checksum of
/// the case and the arrays goes with them. Throws std::runtime_error with one sentence naming the
/// file and the cause (a full disk) when it cannot be written.
void writeCheckpoint(const std::string& path, const CheckpointData& data);

/// Read a checkpoint written by writeCheckpoint. Throws InputError naming the file when it is not
/// a readable checkpoint, carries no checksum (unless acceptUnverified), its case and arrays fail
/// the checksum written with them, or an array holds a value that is not finite.
CheckpointData readCheckpoint(const std::string& path, bool acceptUnverified = false);

} // namespace lbdem::io
