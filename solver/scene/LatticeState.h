// Checkpoint state of a lattice: its populations, their layout and the step count.
#pragma once

#include "solver/core/StateArchive.h"
#include "solver/lattice/Lattice.h"

namespace lbdem::solver {

/// Save the stored populations (exactly), their storage and the step count into archive
/// ("lattice/...").
void saveLatticeState(const lattice::Lattice& lattice, StateArchive& archive);

/// Restore a state saved by saveLatticeState into a lattice built from the same case; throws
/// std::runtime_error when the sizes or the population layout do not match, InputError when
/// the population storage (fluid.storage) does not.
void restoreLatticeState(const StateArchive& archive, lattice::Lattice& lattice);

} // namespace lbdem::solver
