// Stage names and totals of the step timer.
#include "solver/core/StageTimer.h"

#include <cstddef>
#include <iterator>
#include <numeric>

namespace lbdem::solver {

namespace {

/// The name of each stage, in the order of Stage.
constexpr std::string_view kStageNames[] = {"map grains",          "stream-collide", "boundaries",
                                            "hydrodynamic forces", "DEM sub-steps",  "diagnostics"};
static_assert(std::size(kStageNames) == static_cast<std::size_t>(Stage::Count),
              "one name per stage");

} // namespace

std::string_view stageName(Stage stage) {
    const auto k = static_cast<std::size_t>(stage);
    return k < std::size(kStageNames) ? kStageNames[k] : "?";
}

double StageTimer::total() const {
    return std::accumulate(m_seconds.begin(), m_seconds.end(), 0.0);
}

} // namespace lbdem::solver
