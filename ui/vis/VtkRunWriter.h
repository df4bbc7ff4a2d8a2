// Writes a run's snapshots as VTK XML files plus one .pvd per series into RUN_DIR/vtk/.
#pragma once

#include "solver/scene/Snapshot.h"
#include "ui/vis/PvdSeries.h"

#include <optional>
#include <string>

namespace lbdem::vis {

/// particles_NNNNNN.vtu, contacts_NNNNNN.vtu, fluid_NNNNNN.vti (wet scenes) and
/// outline_NNNNNN.vtu per snapshot, zlib-compressed raw appended data (ParaView reads it), and
/// particles.pvd, contacts.pvd, fluid.pvd, outline.pvd with timestep = t [s]. Each file is written
/// under a temporary name and renamed, and a .pvd is rewritten only after its file is complete, so
/// a killed run leaves a valid series. Needs no display.
class VtkRunWriter {
public:
    /// Writes into `runDir`/vtk (created if needed); `resume` keeps the existing .pvd entries up
    /// to time `keepUntilS` (those after it were written after the checkpoint the run resumes
    /// from, and are written again) and continues the frame numbering after them.
    explicit VtkRunWriter(const std::string& runDir, bool resume = false,
                          double keepUntilS = 1e300);

    /// Writes one frame numbered after the previous one; returns its number (NNNNNN in the names).
    int write(const solver::Snapshot& snapshot);
    /// Writes one frame with the given number (a run's output index, so that VTK files, profiles
    /// and timeseries.csv rows share numbers); returns it.
    int write(const solver::Snapshot& snapshot, int frame);
    /// The folder the files go to (RUN_DIR/vtk).
    const std::string& directory() const { return m_dir; }
    /// Frames written so far (including resumed ones).
    int frameCount() const { return m_frame; }

private:
    std::string m_dir;
    PvdSeries m_particles, m_contacts, m_fluid, m_outline;
    int m_frame = 0;
};

/// The file name of frame `frame` of `series` with extension `extension`, e.g.
/// particles_000012.vtu.
std::string vtkFrameFileName(const std::string& series, int frame, const std::string& extension);

} // namespace lbdem::vis
