// Checkpoint state of a column scene: discs, contact history, clock and the wall switches.
#pragma once

#include "solver/core/StateArchive.h"
#include "solver/scene/ColumnScene.h"

namespace lbdem::solver {

/// Save everything needed to continue the column's DEM bit for bit into archive ("dem/...").
void saveColumnState(const ColumnScene& column, StateArchive& archive);

/// Restore a state saved by saveColumnState into a column built from the same case.
void restoreColumnState(const StateArchive& archive, ColumnScene& column);

} // namespace lbdem::solver
