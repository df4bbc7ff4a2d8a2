// The snapshot writers of a run that need VTK: VTU/VTI/PVD series and PNG frames.
#pragma once

#include "app/cli/RunDriver.h"

#include <memory>
#include <string>
#include <vector>

namespace lbdem::cli {

/// What `lbdem run` should write besides the CSV, JSON and checkpoint.
struct SinkOptions {
    bool vtk = true;            ///< VTU/VTI/PVD series (case key output.vtk)
    int vtk_every = 1;          ///< every n-th output (case key output.vtk_every)
    double render_every_tc = 0; ///< PNG frame every this many tau_c (0: none)
    double output_interval_tc = 0.25;
    bool resumed = false;
    double keep_until_s = 1e300; ///< a resumed run keeps the VTK frames up to this time [s]
};

/// Whether this build can write VTK files and PNG frames.
bool sinksAvailable();

/// The sinks for a run into dir; throws InputError when PNG frames are asked of a build without
/// VTK.
std::vector<std::unique_ptr<SnapshotSink>> makeRunSinks(const std::string& dir,
                                                        const SinkOptions& options);

} // namespace lbdem::cli
