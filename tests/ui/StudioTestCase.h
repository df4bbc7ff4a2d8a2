// A small collapse case shared by the studio tests: the default case, shrunk to run fast.
#pragma once

#include "solver/io/CaseLoader.h"

#include <string>
#include <vector>

namespace lbdem::studio::test {

/// sample_cases/default.toml with fewer grains on a smaller, coarser lattice, so that a step
/// takes milliseconds; extra overrides are applied after these.
inline solver::CaseSpec smallCase(std::vector<std::string> extra = {}) {
    // The loose packing: the generator cannot reach the dense 0.83 with so few grains.
    std::vector<std::string> overrides = {"grains.count=150",    "grains.packing=0.79",
                                          "fluid.resolution=4",  "fluid.tau=0.506",
                                          "domain.width_m=0.08", "domain.height_m=0.04"};
    overrides.insert(overrides.end(), extra.begin(), extra.end());
    return io::loadCase(LBDEM_SOURCE_DIR "/sample_cases/default.toml", overrides);
}

} // namespace lbdem::studio::test
