// DEM verification: binary restitution and a disc on a 45-degree incline against analytic values.
#include "solver/core/Constants.h"
#include "solver/verification/VerificationRunners.h"

#include "solver/dem/DemSystem.h"
#include "solver/scene/ColumnScene.h"
#include "solver/scene/Plan.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

namespace lbdem::solver {

namespace {

constexpr int kOnsetPhases = 16;

/// The paper's grain parameters (docs/design.md §5b) for a dry case with restitution e and its DEM
/// step.
CaseSpec demCase(double restitution) {
    CaseSpec spec = defaultCase();
    spec.fluid.enabled = false;
    spec.grains.restitution = restitution;
    spec.grains.rolling_resistance = 0;
    spec.grains.wall_rolling_resistance = 0; // the incline checks free rolling on the wall
    return spec;
}

/// Post/pre normal velocity ratio of a head-on collision of two d_min discs (or a disc and a
/// wall), with the contact onset offset by `phase` of a time step from the step grid.
double collide(const CaseSpec& spec, double dt, bool wall, double phase) {
    dem::DemSystem system(grainMaterial(spec.grains));
    system.setThreads(1);
    const double r = spec.grains.d_min_m / 2, v = 0.1;
    const double gap = phase * (wall ? v : 2 * v) * dt;
    if (wall) {
        system.addWall(Vec2(0, -1), Vec2(0, 1));
        system.addDisc(r + gap, 0, r);
        system.particles().vx[0] = -v;
    } else {
        system.addDisc(0, 0, r);
        system.addDisc(2 * r + gap, 0, r);
        system.particles().vx[0] = v;
        system.particles().vx[1] = -v;
    }
    system.computeForces();
    // The contact lasts 1 / dt_safety steps; run three times that.
    const long long steps = static_cast<long long>(3 / spec.grains.dt_safety) + 10;
    for (long long k = 0; k < steps; ++k)
        system.step(dt);
    const auto& p = system.particles();
    return wall ? p.vx[0] / v : (p.vx[1] - p.vx[0]) / (2 * v);
}

VerificationResult restitutionResult(double e, bool wall) {
    const auto start = std::chrono::steady_clock::now();
    const CaseSpec spec = demCase(e);
    const double dt = makePlan(spec).dem_dt_s; // the step every scene of this case would use
    // In a flow a contact begins at a random phase of the step; the effective restitution of
    // the scheme is the mean over phases. The worst single phase is reported in the quantity.
    double sum = 0, worst = e;
    for (int k = 0; k < kOnsetPhases; ++k) {
        const double value = collide(spec, dt, wall, (k + 0.5) / kOnsetPhases);
        sum += value;
        if (std::abs(value - e) > std::abs(worst - e)) worst = value;
    }
    const double mean = sum / kOnsetPhases;
    char quantity[160];
    std::snprintf(quantity, sizeof quantity,
                  "%s restitution e=%.1f, mean of %d onset phases (worst %.4f)",
                  wall ? "disc-wall" : "disc-disc", e, kOnsetPhases, worst);
    VerificationResult r =
        compareRelative("restitution", quantity, mean, e, 0.005,
                        "linear spring-dashpot: ln e = -pi zeta / sqrt(1 - zeta^2), "
                        "contact ends at zero overlap (Schwager & Poeschel 2007)");
    // The tolerance is absolute on e (the contract: error <= 0.005).
    r.error = std::abs(mean - e);
    r.passed = std::isfinite(mean) && r.error <= r.tolerance;
    r.method = "dt=" + std::to_string(spec.grains.dt_safety) + " t_c";
    r.wall_s = secondsSince(start);
    return r;
}

struct InclineRun {
    double acceleration = 0; ///< downslope acceleration of the centre
    double angular = 0;      ///< angular acceleration (clockwise positive: rolling downslope)
};

/// A d_min disc resting on a frictional floor under gravity tilted by 45 degrees.
InclineRun incline(double wallFriction) {
    CaseSpec spec = demCase(0.5);
    spec.grains.wall_friction = wallFriction;
    const double dt = makePlan(spec).dem_dt_s;
    const double beta = kPi / 4, g = spec.domain.gravity_m_s2, r = spec.grains.d_min_m / 2;
    dem::DemSystem system(grainMaterial(spec.grains));
    system.setThreads(1);
    system.setGravity(Vec2(g * std::sin(beta), -g * std::cos(beta)));
    system.addWall(Vec2(-1, 0), Vec2(100, 0));
    const double mass = dem::discMass(r, spec.grains.density_kg_m3);
    // Start at the static overlap so that no normal oscillation is excited.
    system.addDisc(0, r - mass * g * std::cos(beta) / spec.grains.normal_stiffness_n_m, r);
    system.computeForces();
    const auto& p = system.particles();
    // Let the tangential spring settle (a few hundred contact times), then difference v and omega.
    const long long settle = 20000, measure = 20000;
    for (long long k = 0; k < settle; ++k)
        system.step(dt);
    const double v0 = p.vx[0], w0 = p.omega[0];
    for (long long k = 0; k < measure; ++k)
        system.step(dt);
    const double span = measure * dt;
    return {(p.vx[0] - v0) / span, -(p.omega[0] - w0) / span};
}

} // namespace

std::vector<VerificationResult> verifyIncline(const VerificationOptions&) {
    const double beta = kPi / 4, g = 9.81, r = 0.6e-3;
    const char* source =
        "rigid-body mechanics of a disc on an incline (e.g. Goldstein, Classical Mechanics)";
    std::vector<VerificationResult> out;
    auto timed = [&](auto&& body) {
        const auto start = std::chrono::steady_clock::now();
        body();
        out.back().wall_s = secondsSince(start);
    };
    timed([&] {
        const InclineRun run = incline(0.0);
        out.push_back(compareRelative("incline", "frictionless: a = g sin(beta), beta = 45 deg",
                                      run.acceleration, g * std::sin(beta), 0.005, source));
    });
    timed([&] {
        const InclineRun run = incline(0.5);
        out.push_back(
            compareRelative("incline", "rolling without slip (mu_w = 0.5): a = 2/3 g sin(beta)",
                            run.acceleration, 2.0 / 3.0 * g * std::sin(beta), 0.005, source));
    });
    const double mu = 0.2;
    const InclineRun slip = [&] {
        const auto start = std::chrono::steady_clock::now();
        InclineRun run = incline(mu);
        out.push_back(compareRelative(
            "incline", "slipping (mu_w = 0.2): a = g (sin(beta) - mu cos(beta))", run.acceleration,
            g * (std::sin(beta) - mu * std::cos(beta)), 0.005, source));
        out.back().wall_s = secondsSince(start);
        return run;
    }();
    out.push_back(compareRelative("incline", "slipping (mu_w = 0.2): alpha = 2 mu g cos(beta) / R",
                                  slip.angular, 2 * mu * g * std::cos(beta) / r, 0.005, source));
    return out;
}

std::vector<VerificationResult> verifyRestitution(const VerificationOptions&) {
    std::vector<VerificationResult> out;
    for (bool wall : {false, true})
        for (double e : {0.1, 0.5, 0.9})
            out.push_back(restitutionResult(e, wall));
    return out;
}

} // namespace lbdem::solver
