// Test data rows shared by the lattice tests: every collision model, without and with a force.
#pragma once

#include "solver/lattice/Collision.h"

#include <QtTest>
#include <string>

namespace lbdem::support {

/// Add the columns "model" (a CollisionModel as int) and "force" (a body force, 0 or 2e-3) and
/// one row per model and force, named "bgk", "bgk, forced", ...
inline void addCollisionModelRows() {
    using solver::lattice::CollisionModel;
    QTest::addColumn<int>("model");
    QTest::addColumn<double>("force");
    for (auto model : {CollisionModel::Bgk, CollisionModel::Mrt, CollisionModel::MrtLes})
        for (double force : {0.0, 2e-3}) {
            const std::string name =
                std::string(solver::enumWord(model)) + (force ? ", forced" : "");
            QTest::newRow(name.c_str()) << int(model) << force;
        }
}

} // namespace lbdem::support
