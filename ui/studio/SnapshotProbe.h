// What lies under a point of the view: the fluid there and the grain covering it, if any.
#pragma once

#include "solver/scene/Snapshot.h"

#include <QString>

#include <optional>

namespace lbdem::studio {

/// Values of a snapshot at one point [m].
struct ProbeResult {
    double x = 0, y = 0;
    bool inDomain = false;
    std::optional<float> ux, uy, pressure, vorticity, solid; ///< nearest fluid node
    std::optional<std::size_t> grain; ///< index of the disc covering the point
    float grainSpeed = 0, grainRadius = 0, grainOmega = 0, grainForce = 0;
};

/// Look up the point (x, y) in snapshot.
ProbeResult probeSnapshot(const solver::Snapshot& snapshot, double x, double y);

/// One line for the status bar, e.g. "x 0.012 m, y 0.004 m | u 0.03 m/s, p 12 Pa | grain 17 ...".
QString describeProbe(const ProbeResult& result);

} // namespace lbdem::studio
