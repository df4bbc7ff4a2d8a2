// Checkpoint state of a lattice.
#include "solver/scene/LatticeState.h"

#include "solver/core/InputError.h"

#include <stdexcept>
#include <string>

namespace lbdem::solver {

namespace {

/// Layout of "lattice/f": 1 = in place, AA pattern (where a value sits depends on the step
/// parity). Checkpoints without it were written by the two-lattice solver and cannot be read.
constexpr long long kInPlaceLayout = 1;

/// "lattice/storage": what "lattice/f" holds. 0 = f_i (double storage; checkpoints without the
/// entry), 1 = f_i - w_i of float storage, widened to double without loss.
long long storageCode(lattice::PopulationStorage storage) {
    return storage == lattice::PopulationStorage::Float ? 1 : 0;
}

} // namespace

void saveLatticeState(const lattice::Lattice& lattice, StateArchive& archive) {
    archive.reals["lattice/f"] = lattice.exportStoredValues();
    archive.integers["lattice/step"] = {lattice.stepCount()};
    archive.integers["lattice/layout"] = {kInPlaceLayout};
    archive.integers["lattice/storage"] = {storageCode(lattice.storage())};
}

void restoreLatticeState(const StateArchive& archive, lattice::Lattice& lattice) {
    if (!archive.integers.count("lattice/layout") ||
        archive.integer("lattice/layout").at(0) != kInPlaceLayout)
        throw std::runtime_error(
            "the checkpoint was written by an older lbdem with another population "
            "layout; run the case again from the start");
    const long long saved =
        archive.integers.count("lattice/storage") ? archive.integer("lattice/storage").at(0) : 0;
    if (saved != storageCode(lattice.storage())) {
        const char* savedName = enumWord(saved == 1 ? lattice::PopulationStorage::Float
                                                    : lattice::PopulationStorage::Double);
        throw InputError(std::string("the checkpoint holds fluid populations stored as ") +
                         savedName + " but the case sets fluid.storage = \"" +
                         enumWord(lattice.storage()) + "\"; resume with fluid.storage = \"" +
                         savedName + "\"");
    }
    const auto& values = archive.real("lattice/f");
    if (values.size() != static_cast<std::size_t>(lattice::kQ * lattice.cells()))
        throw std::runtime_error("the checkpoint's lattice does not match the case's plan");
    lattice.importStoredValues(values);
    lattice.setStepCount(archive.integer("lattice/step").at(0));
}

} // namespace lbdem::solver
