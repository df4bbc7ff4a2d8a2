// The small dry column of the DEM scene tests: 150 grains, no fluid, one thread, its packing
// generated into a temporary cache folder.
#pragma once

#include "solver/dem/Packing.h"
#include "solver/scene/CaseSpec.h"

#include <QTemporaryDir>

namespace lbdem::support {

/// The default case with the fluid off, 150 grains at `packing`, one thread.
inline solver::CaseSpec smallDryColumn(double packing) {
    solver::CaseSpec spec = solver::defaultCase();
    spec.fluid.enabled = false;
    spec.grains.count = 150;
    spec.grains.packing = packing;
    spec.run.threads = 1;
    return spec;
}

/// Packing options that generate into (and cache in) `dir` rather than the shared cache.
inline solver::dem::PackingOptions packingIn(const QTemporaryDir& dir) {
    solver::dem::PackingOptions options;
    options.cache_dir = dir.path().toStdString();
    return options;
}

} // namespace lbdem::support
