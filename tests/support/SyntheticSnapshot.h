// A deterministic synthetic Snapshot (a slumping grain column, a vortex, contacts, an outline)
// for the export, render and CLI tests while no simulation produces real ones.
#pragma once

#include "solver/scene/Snapshot.h"

#include <string>

namespace lbdem::support {

/// Frame `frame` of a synthetic run: about 300 discs in a column that spreads to the right as
/// `frame` grows, a Lamb-Oseen vortex ahead of the front, lattice-neighbour contacts with
/// depth-dependent forces (plus bed and left-wall contacts), the outline and the domain walls.
/// `wet` = false leaves out the fluid (a dry scene).
solver::Snapshot syntheticSnapshot(int frame, bool wet = true);

/// Writes `frames` synthetic frames into `runDir`/vtk with VtkRunWriter.
void writeSyntheticRun(const std::string& runDir, int frames, bool wet = true);

} // namespace lbdem::support
