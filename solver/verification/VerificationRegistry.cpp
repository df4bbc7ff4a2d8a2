// The registry of verification cases: one table of every case, each run by its module.
#include "solver/verification/Verification.h"

#include "solver/verification/VerificationRunners.h"

#include "solver/core/OpenMp.h"

#include <cmath>
#include <cstdio>

namespace lbdem::solver {

namespace {

/// Every case: its name, its line for `lbdem verify --list`, the function that runs it, and
/// whether it is slow (left to the `long` label).
std::vector<VerificationCase> allCases() {
    return {
        {"poiseuille", "body-force channel: L2 error <= 1e-3 at 16 nodes, order >= 1.8",
         verifyPoiseuille},
        {"taylor-green",
         "decaying vortex: decay rate within 0.5 % at 32 nodes, order >= 1.8, LES within 2 %",
         verifyTaylorGreen},
        {"cavity-re100",
         "lid-driven cavity at Re = 100, 128^2: centreline u within 0.01 of Ghia et al.",
         verifyCavity},
        {"cylinder-2d1",
         "Schäfer-Turek 2D-1 (Re = 20): C_D within 2 % of 5.58 (D = 20), dp within 2 %",
         verifyCylinder},
        {"stability",
         "cavity at tau - 0.5 = 1e-4: MRT+LES stays bounded 20,000 steps, BGK is stopped",
         verifyStability},
        {"grid-noise",
         "cylinder wake at Re = 100 (D = 20): grid-scale share of vorticity <= 0.10 throughout",
         verifyGridNoise},
        {"restitution",
         "binary disc-disc and disc-wall collisions reach e = 0.1, 0.5, 0.9 (|error| <= 0.005)",
         verifyRestitution},
        {"incline",
         "disc on a 45-degree slope: frictionless, rolling and slipping accelerations (0.5 %)",
         verifyIncline},
        {"packing",
         "packing generator meets the dense (0.83) and loose (0.79) targets within 0.005",
         packingResults},
        {"dry-collapse-scaling",
         "dry column collapse: normalised runout grows linearly with a (a <= 1.5)",
         dryCollapseScalingResults, true},
        {"settling-disc",
         "disc settling in a 4 d channel at Re 259.5 (Wachs 2009), both coupling methods",
         verifySettlingDisc},
        {"gebart-square",
         "permeability of a square cylinder array at solid fraction 0.5 (Gebart 1992)",
         verifyGebartSquare},
        {"disc-shear", "free disc in simple shear rotates at half the vorticity", verifyDiscShear},
        {"permeability",
         "random disc packing: K falls with the hydrodynamic radius; vs Carman-Kozeny",
         verifyPermeability},
        {"near-contact",
         "discs at rest in still water at gaps of 0-1.5 nodes, and above the floor, feel no force",
         verifyNearContact},
        {"column-at-rest",
         "the dense paper column held in still water puts its buoyant weight on the floor",
         verifyColumnAtRest, true},
        {"column-permeability",
         "K of the dense and loose paper columns (window, grains fixed, pressure drop) at "
         "d_min/h = 6-12 (16 with --long) against Carman-Kozeny",
         verifyColumnPermeability, true},
    };
}

} // namespace

const std::vector<VerificationCase>& verificationCases() {
    static const std::vector<VerificationCase> cases = [] {
        std::vector<VerificationCase> all;
        for (VerificationCase c : allCases()) {
            auto run = std::move(c.run);
            c.run = [run](const VerificationOptions& options) {
                ompSetThreads(options.threads);
                return run(options);
            };
            all.push_back(std::move(c));
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
