// DEM verification cases: restitution, incline, packing and dry-collapse scaling.
#pragma once

#include "solver/verification/Verification.h"

#include <vector>

namespace lbdem::solver {

/// The DEM cases for the verification registry.
std::vector<VerificationCase> demVerificationCases();

/// `packing`: the generator meets the dense and loose targets (DemVerificationPacking.cpp).
std::vector<VerificationResult> packingResults(const VerificationOptions& options);

/// `dry-collapse-scaling`: runout against aspect ratio; empty in the quick run.
std::vector<VerificationResult> dryCollapseScalingResults(const VerificationOptions& options);

} // namespace lbdem::solver
