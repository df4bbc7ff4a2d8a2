// The registry of verification cases: each module contributes its list here.
#include "solver/verification/Verification.h"

#include "solver/verification/ColumnPermeability.h"
#include "solver/verification/CouplingVerification.h"
#include "solver/verification/DemVerification.h"
#include "solver/verification/FluidVerification.h"

#include "solver/core/OpenMp.h"

#include <cmath>
#include <cstdio>

namespace lbdem::solver {

namespace {

/// Functions returning each module's cases; a module adds its provider here.
using Provider = std::vector<VerificationCase> (*)();
const Provider kProviders[] = {fluidVerificationCases, demVerificationCases,
                               couplingVerificationCases, couplingRestCases,
                               columnPermeabilityCases};

} // namespace

const std::vector<VerificationCase>& verificationCases() {
    static const std::vector<VerificationCase> cases = [] {
        std::vector<VerificationCase> all;
        for (Provider provider : kProviders) {
            if (!provider) continue;
            for (VerificationCase c : provider()) {
                auto run = std::move(c.run);
                c.run = [run](const VerificationOptions& options) {
                    ompSetThreads(options.threads);
                    return run(options);
                };
                all.push_back(std::move(c));
            }
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

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string formatQuantity(const char* pattern, double a, double b, double c) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, pattern, a, b, c);
    return buffer;
}

} // namespace lbdem::solver
