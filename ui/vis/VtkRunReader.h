// Reads back what VtkRunWriter wrote, so a finished (or killed) run can be rendered again.
#pragma once

#include "solver/scene/Snapshot.h"
#include "ui/vis/PvdSeries.h"

#include <string>
#include <vector>

namespace lbdem::vis {

/// The frames of RUN_DIR/vtk, listed by particles.pvd (written last for each frame, so every
/// listed frame is complete); contacts, fluid and outline files of the same number are read
/// when present.
class VtkRunReader {
public:
    /// Opens `runDir` (or `runDir`/vtk itself); throws solver::InputError when there is no
    /// particles.pvd.
    explicit VtkRunReader(const std::string& runDir);

    /// Number of complete frames.
    int frameCount() const { return static_cast<int>(m_frames.size()); }
    /// Time [s] of frame `frame`.
    double frameTime(int frame) const {
        return m_frames.at(static_cast<std::size_t>(frame)).time_s;
    }
    /// The frame whose time is nearest to `time_s`; throws solver::InputError when there is none.
    int frameNearestTime(double time_s) const;
    /// Rebuilds the Snapshot of frame `frame` from its files.
    solver::Snapshot read(int frame) const;
    /// The folder holding the .pvd files.
    const std::string& directory() const { return m_dir; }

private:
    std::string m_dir;
    std::vector<PvdEntry> m_frames;
};

} // namespace lbdem::vis
