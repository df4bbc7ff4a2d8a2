// Packing generator: seeded diameters, a loose lattice, gravity deposition with a searched
// preparation friction, then relaxation with the run's contact law.
#include "solver/dem/Packing.h"
#include "solver/core/Constants.h"

#include "solver/core/InputError.h"
#include "solver/dem/DemSystem.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

namespace lbdem::solver::dem {

namespace {

// Deposition runs with contacts 10 times softer (3.2 times longer contacts, so 3.2 times fewer
// steps); the final relaxation with the real stiffness removes the extra overlap (~0.5 % of d).
constexpr Real kSoften = 10;
constexpr Real kPrepRestitution =
    0.5; // explicit tangential dashpots of many sticking contacts limit the damping
constexpr Real kPrepStepFraction = 0.05;  // deposition step as a fraction of the contact time
constexpr Real kRelaxStepFraction = 0.05; // relaxation step, likewise
// The deposition friction is searched in [0, kMaxPrepFriction], at most kMaxDepositions times.
constexpr Real kMaxPrepFriction = 1.0;
constexpr int kMaxDepositions = 10;
// Rolling resistance during deposition (the run's own applies in the final relaxation).
constexpr Real kPrepRollingResistance = 0.05;
// The relaxation stiffens the contacts back to the run's in kRelaxStages geometric stages of
// kRelaxStageSteps steps each.
constexpr int kRelaxStages = 8;
constexpr int kRelaxStageSteps = 400;

/// Uniform number in [0, 1) from the top 53 bits: identical on every standard library.
Real uniform(std::mt19937_64& rng) {
    return static_cast<Real>(rng() >> 11) * 0x1.0p-53;
}

std::vector<Real> drawRadii(const PackingRequest& req, std::mt19937_64& rng) {
    std::vector<Real> r(req.count);
    for (Real& ri : r)
        ri = 0.5 * req.d_min * (1 + (req.size_ratio - 1) * uniform(rng));
    return r;
}

struct Layout {
    std::vector<Real> x, y, vx, vy;
};

/// A loose lattice of spacing 2.1 R_max (no overlaps), filled row by row, with small random
/// velocities so that the deposit does not keep the lattice order.
Layout looseLattice(const std::vector<Real>& radii, Real width, std::mt19937_64& rng) {
    const Real rmax = *std::max_element(radii.begin(), radii.end());
    const Real spacing = 2.1 * rmax;
    const int perRow = std::max(1, static_cast<int>(std::floor(width / spacing)));
    const Real pitch = width / perRow;
    Layout l;
    for (std::size_t k = 0; k < radii.size(); ++k) {
        const int row = static_cast<int>(k) / perRow, col = static_cast<int>(k) % perRow;
        // Alternate rows shift by half a pitch (staggered), clamped inside the walls.
        const Real shift = (row % 2 ? 0.25 : -0.25) * pitch;
        l.x.push_back(std::clamp((col + 0.5) * pitch + shift, radii[k], width - radii[k]));
        l.y.push_back(rmax + row * spacing);
        l.vx.push_back(0.05 * (2 * uniform(rng) - 1));
        l.vy.push_back(0.05 * (2 * uniform(rng) - 1));
    }
    return l;
}

/// Run the system until the root-mean-square disc speed is below vTol (after at least tMin), or
/// tMax. The mean, not the fastest disc: a lone rattler must not keep a large pile running.
void settle(DemSystem& system, Real dt, Real tMin, Real tMax, Real vTol) {
    const Real t0 = system.time();
    Real totalMass = 0;
    for (Real m : system.particles().mass)
        totalMass += m;
    while (system.time() - t0 < tMax) {
        for (int k = 0; k < 200; ++k)
            system.step(dt);
        const Real rms = std::sqrt(2 * system.kineticEnergy() / totalMass);
        if (system.time() - t0 > tMin && rms < vTol) return;
    }
}

/// Raise the contact stiffness from the deposition value to the run's in geometric stages:
/// a sudden jump would release the soft overlaps' energy at once and loosen the column.
void relaxToRunStiffness(DemSystem& system, const PackingRequest& req, const Material& prep,
                         Real fall, Real vTol) {
    const Real lightest = discMass(req.d_min / 2, prep.density);
    // The floor and torque options act from the release on: the column is prepared with the
    // grains' own rolling resistance on the walls and torque-carrying contacts whatever they are,
    // so that a cached column stays the one the generator makes.
    Material stage = req.material;
    stage.wall_rolling_resistance = stage.rolling_resistance;
    stage.contact_torque = true;
    for (int k = 1; k <= kRelaxStages; ++k) {
        const Real scale = std::pow(kSoften, Real(k) / kRelaxStages) / kSoften;
        stage.normal_stiffness = req.material.normal_stiffness * scale;
        stage.tangential_stiffness = req.material.tangential_stiffness * scale;
        system.setMaterial(stage);
        const Real dt = kRelaxStepFraction *
                        contactDuration(stage.normal_stiffness, lightest / 2, stage.restitution);
        for (int s = 0; s < kRelaxStageSteps; ++s)
            system.step(dt);
    }
    const Real dt = kRelaxStepFraction *
                    contactDuration(stage.normal_stiffness, lightest / 2, stage.restitution);
    settle(system, dt, 0, 2 * fall, vTol);
}

struct Deposit {
    std::vector<Real> x, y;
    Real fraction = 0, height = 0;
};

Deposit deposit(const PackingRequest& req, const std::vector<Real>& radii, const Layout& start,
                Real width, Real friction, bool relax) {
    Material prep = req.material;
    prep.normal_stiffness /= kSoften;
    prep.tangential_stiffness /= kSoften;
    prep.restitution = kPrepRestitution;
    prep.friction = prep.wall_friction = friction;
    // Some rolling resistance stops discs from rolling for ever on the free surface.
    prep.rolling_resistance = prep.wall_rolling_resistance = kPrepRollingResistance;
    prep.contact_torque = true;
    DemSystem system(prep);
    system.setThreads(1); // the column must not depend on the thread count (generatePacking)
    system.reserve(radii.size());
    const Real top = start.y.back() + 4 * req.d_min * req.size_ratio;
    system.addWall(Vec2(0, 0), Vec2(width, 0));
    system.addWall(Vec2(0, 0), Vec2(0, top));
    system.addWall(Vec2(width, 0), Vec2(width, top));
    for (std::size_t k = 0; k < radii.size(); ++k) {
        system.addDisc(start.x[k], start.y[k], radii[k]);
        system.particles().vx[k] = start.vx[k];
        system.particles().vy[k] = start.vy[k];
    }
    system.setGravity(Vec2(0, -req.gravity));
    system.computeForces();
    const Real lightest = discMass(req.d_min / 2, prep.density);
    const Real dt =
        kPrepStepFraction * contactDuration(prep.normal_stiffness, lightest / 2, prep.restitution);
    const Real vTol = 1e-3 * std::sqrt(req.gravity * req.d_min);
    const Real fall = std::sqrt(2 * top / req.gravity);
    settle(system, dt, fall, 20 * fall, vTol);
    if (relax) relaxToRunStiffness(system, req, prep, fall, vTol);
    Deposit d;
    d.x = system.particles().x;
    d.y = system.particles().y;
    d.fraction = packingFraction(d.y, radii, width, d.height);
    return d;
}

/// Deposition friction whose soft deposit is closest to aim (bracketed by the two end deposits).
Real searchFriction(const PackingRequest& req, Packing& packing, const Layout& lattice, Real aim,
                    Deposit dLo, Deposit dHi) {
    Real lo = 0, hi = kMaxPrepFriction, mu = 0;
    Real bestError = std::abs(dLo.fraction - aim);
    if (std::abs(dHi.fraction - aim) < bestError) {
        bestError = std::abs(dHi.fraction - aim);
        mu = hi;
    }
    if (dLo.fraction < aim || dHi.fraction > aim) return mu; // out of reach: the closest end
    const Real searchTol = 0.4 * req.tolerance; // leave room for the shift on relaxation
    while (bestError > searchTol && packing.depositions < kMaxDepositions) {
        const Real t = std::clamp((dLo.fraction - aim) / (dLo.fraction - dHi.fraction), Real(0.15),
                                  Real(0.85));
        const Real m = lo + t * (hi - lo);
        const Deposit d = deposit(req, packing.radius, lattice, packing.width, m, false);
        ++packing.depositions;
        if (std::abs(d.fraction - aim) < bestError) {
            bestError = std::abs(d.fraction - aim);
            mu = m;
        }
        if (d.fraction > aim) {
            lo = m;
            dLo = d;
        } else {
            hi = m;
            dHi = d;
        }
    }
    return mu;
}

/// Complete a packing from its final deposit, time it and cache it when asked.
Packing finish(Packing& packing, const Deposit& final, Real mu, int depositions,
               std::chrono::steady_clock::time_point start, bool cache, const std::string& path,
               bool converged) {
    packing.x = final.x;
    packing.y = final.y;
    packing.fraction = final.fraction;
    packing.height = final.height;
    packing.prep_friction = mu;
    packing.depositions = depositions;
    packing.converged = converged;
    packing.wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (cache) writeCachedPacking(path, packing);
    return packing;
}

} // namespace

Real packingFraction(const std::vector<Real>& y, const std::vector<Real>& r, Real width,
                     Real& height) {
    Real area = 0, moment = 0;
    for (std::size_t k = 0; k < r.size(); ++k) {
        const Real a = kPi * r[k] * r[k];
        area += a;
        moment += a * y[k];
    }
    height = area > 0 ? 2 * moment / area : 0;
    return height > 0 ? area / (width * height) : 0;
}

Packing generatePacking(const PackingRequest& req, const PackingOptions& options) {
    if (req.count < 1 || req.d_min <= 0 || req.size_ratio < 1 || req.target <= 0 ||
        req.target >= 0.9)
        throw InputError("cannot generate a packing of " + std::to_string(req.count) +
                         " discs at fraction " + std::to_string(req.target));
    const std::string dir =
        options.cache_dir.empty() ? defaultPackingCacheDir() : options.cache_dir;
    const std::string path = dir + "/packing-" + packingCacheKey(req) + ".txt";
    Packing packing;
    if (options.use_cache && readCachedPacking(path, packing)) {
        packing.from_cache = true;
        return packing;
    }
    const auto start = std::chrono::steady_clock::now();
    std::mt19937_64 rng(req.seed);
    packing.radius = drawRadii(req, rng);
    Real area = 0;
    for (Real r : packing.radius)
        area += kPi * r * r;
    packing.width = std::sqrt(area / (req.aspect_ratio * req.target));
    packing.target = req.target;
    const Layout lattice = looseLattice(packing.radius, packing.width, rng);

    if (req.fixed_friction) {
        const Deposit once =
            deposit(req, packing.radius, lattice, packing.width, req.material.friction, true);
        return finish(packing, once, req.material.friction, 1, start, options.use_cache, path,
                      true);
    }
    // Regula falsi on the deposition friction (the settled fraction falls as friction rises),
    // on the soft deposits; the stiff relaxation shifts the fraction a little, so a second
    // round aims at the target corrected by that shift.
    Real lo = 0, hi = kMaxPrepFriction;
    const Deposit dLo0 = deposit(req, packing.radius, lattice, packing.width, lo, false);
    const Deposit dHi0 = deposit(req, packing.radius, lattice, packing.width, hi, false);
    packing.depositions = 2;
    Real aim = req.target, mu = lo;
    Deposit final;
    for (int round = 0; round < 2; ++round) {
        mu = searchFriction(req, packing, lattice, aim, dLo0, dHi0);
        final = deposit(req, packing.radius, lattice, packing.width, mu, true);
        ++packing.depositions;
        if (std::abs(final.fraction - req.target) <= req.tolerance) break;
        aim += req.target - final.fraction;
    }
    const bool converged = std::abs(final.fraction - req.target) <= req.tolerance;
    return finish(packing, final, mu, packing.depositions, start, options.use_cache && converged,
                  path, converged);
}

} // namespace lbdem::solver::dem
