// Controlled experiments: the cases of a sweep with variants compared variant by variant with
// its first (reference) variant.
#pragma once

#include "campaign/SweepEnsemble.h"

#include <string>
#include <vector>

namespace lbdem::campaign {

/// Per case (the name before "__"), a row per variant: status, then each metric (mean ± sd over
/// seeds, or the one value) and, where both are finite and the reference's is not zero, its
/// ratio to the reference variant's ("x1.23"). CSV: the values and ratios, one row per variant.
std::string variantsMarkdown(const std::vector<EnsembleCase>& cases);
std::string variantsCsv(const std::vector<EnsembleCase>& cases);

} // namespace lbdem::campaign
