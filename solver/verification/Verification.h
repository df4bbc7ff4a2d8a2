// Verification cases: named checks of the solver against analytic or published values.
#pragma once

#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace lbdem::solver {

/// One compared quantity of a verification case (the `lbdem verify --json` record).
struct VerificationResult {
    std::string name;     ///< case name, e.g. "poiseuille"
    std::string quantity; ///< what was compared, e.g. "L2 relative error (16 nodes)"
    double value = 0;     ///< computed value
    double reference = 0; ///< analytic or published value
    double error = 0;     ///< the measure compared with tolerance (relative unless stated)
    double tolerance = 0; ///< pass when error <= tolerance
    bool passed = false;
    double wall_s = 0;  ///< wall time spent on this quantity
    std::string method; ///< variant, e.g. coupling method or collision model; may be empty
    std::string source; ///< citation of the reference value
};

/// How a verification case should run.
struct VerificationOptions {
    bool long_run = false; ///< the `--long` variant: finer grids, tighter tolerances
    int threads = 0;       ///< OpenMP threads, 0 = all
};

/// A registered verification case.
struct VerificationCase {
    std::string name;        ///< the name `lbdem verify NAME` takes
    std::string description; ///< one line for `lbdem verify --list`
    std::function<std::vector<VerificationResult>(const VerificationOptions&)> run;
    bool slow = false; ///< minutes even in its quick form (or empty): the default test suite leaves
                       ///< it to `long`
};

/// Every verification case of this build, in a stable order; each run first applies
/// options.threads.
const std::vector<VerificationCase>& verificationCases();

/// Helper for case authors: fill error and passed from value, reference and tolerance
/// (relative error |value - reference| / |reference|).
VerificationResult compareRelative(std::string name, std::string quantity, double value,
                                   double reference, double tolerance, std::string source);

/// Seconds of wall time since start (the wall_s of a result).
double secondsSince(std::chrono::steady_clock::time_point start);

/// printf-style formatting of up to three numbers into a quantity's description.
std::string formatQuantity(const char* pattern, double a, double b = 0, double c = 0);

} // namespace lbdem::solver
