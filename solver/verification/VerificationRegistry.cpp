// The registry of verification cases: each module contributes its list here.
#include "solver/verification/Verification.h"

#include "solver/verification/CouplingVerification.h"
#include "solver/verification/DemVerification.h"
#include "solver/verification/FluidVerification.h"

#include <cmath>

namespace lbdem::solver {

namespace {

/// Functions returning each module's cases; a module adds its provider here.
using Provider = std::vector<VerificationCase> (*)();
const Provider kProviders[] = {fluidVerificationCases, demVerificationCases, couplingVerificationCases,
                              couplingRestCases};

} // namespace

const std::vector<VerificationCase>& verificationCases() {
    static const std::vector<VerificationCase> cases = [] {
        std::vector<VerificationCase> all;
        for (Provider provider : kProviders) {
            if (!provider) continue;
            auto some = provider();
            all.insert(all.end(), some.begin(), some.end());
        }
        return all;
    }();
    return cases;
}

VerificationResult compareRelative(std::string name, std::string quantity, double value,
                                   double reference, double tolerance, std::string source) {
    VerificationResult result;
    result.name = std::move(name);
    result.quantity = std::move(quantity);
    result.value = value;
    result.reference = reference;
    result.error = std::abs(value - reference) / std::abs(reference);
    result.tolerance = tolerance;
    result.passed = std::isfinite(value) && result.error <= tolerance;
    result.source = std::move(source);
    return result;
}

} // namespace lbdem::solver
