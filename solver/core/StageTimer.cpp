// Stage names and totals of the step timer.
#include "solver/core/StageTimer.h"

#include <numeric>

namespace lbdem::solver {

std::string_view stageName(Stage stage) {
    switch (stage) {
    case Stage::MapGrains:
        return "map grains";
    case Stage::StreamCollide:
        return "stream-collide";
    case Stage::Boundaries:
        return "boundaries";
    case Stage::HydrodynamicForces:
        return "hydrodynamic forces";
    case Stage::DemSubsteps:
        return "DEM sub-steps";
    case Stage::Diagnostics:
        return "diagnostics";
    case Stage::Count:
        break;
    }
    return "?";
}

double StageTimer::total() const {
    return std::accumulate(m_seconds.begin(), m_seconds.end(), 0.0);
}

} // namespace lbdem::solver
