// checkpoint.h5: the resolved case and the complete solver state, written atomically.
#pragma once

#include "solver/core/StateArchive.h"

#include <string>

namespace lbdem::io {

/// What a checkpoint file holds.
struct CheckpointData {
    std::string case_toml;        ///< the resolved case (io::formatCase), to rebuild the Simulation
    solver::StateArchive state;   ///< the solver state (Simulation::saveState)
};

/// Write data to path as HDF5 through a temporary file renamed over path, so that a run killed
/// at any moment leaves either the previous or the new checkpoint, never a torn one.
void writeCheckpoint(const std::string& path, const CheckpointData& data);

/// Read a checkpoint written by writeCheckpoint; throws std::runtime_error naming the file.
CheckpointData readCheckpoint(const std::string& path);

} // namespace lbdem::io
