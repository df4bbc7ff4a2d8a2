// Checkpoint state of a lattice.
#include "solver/scene/LatticeState.h"

#include <stdexcept>

namespace lbdem::solver {

namespace {

/// Layout of "lattice/f": 1 = in place, AA pattern (where a value sits depends on the step
/// parity). Checkpoints without it were written by the two-lattice solver and cannot be read.
constexpr long long kInPlaceLayout = 1;

} // namespace

void saveLatticeState(const lattice::Lattice& lattice, StateArchive& archive) {
    archive.reals["lattice/f"] = lattice.populations();
    archive.integers["lattice/step"] = {lattice.stepCount()};
    archive.integers["lattice/layout"] = {kInPlaceLayout};
}

void restoreLatticeState(const StateArchive& archive, lattice::Lattice& lattice) {
    if (!archive.integers.count("lattice/layout") || archive.integer("lattice/layout").at(0) != kInPlaceLayout)
        throw std::runtime_error("the checkpoint was written by an older lbdem with another population "
                                 "layout; run the case again from the start");
    const auto& saved = archive.real("lattice/f");
    if (saved.size() != lattice.populations().size())
        throw std::runtime_error("the checkpoint's lattice does not match the case's plan");
    lattice.populations() = saved;
    lattice.setStepCount(archive.integer("lattice/step").at(0));
}

} // namespace lbdem::solver
