// DEM throughput benchmark on a settled pile (reported, never pass/fail).
#include "solver/dem/DemBench.h"

#include "solver/dem/DemSystem.h"

#include <algorithm>
#include <chrono>

namespace lbdem::solver::dem {

namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

} // namespace

PackingRequest defaultBenchPile() {
    PackingRequest request;
    request.count = 10000;
    request.aspect_ratio = 0.25;
    request.fixed_friction = true;
    return request;
}

DemBenchResult runDemBench(const DemBenchConfig& config) {
    DemBenchResult result;
    const Material& material = config.pile.material;
    const auto pileStart = Clock::now();
    const Packing pile = generatePacking(config.pile, config.packing);
    result.pile_seconds = since(pileStart);
    result.pile_from_cache = pile.from_cache;
    result.packing_fraction = pile.fraction;
    const Real lightest = discMass(config.pile.d_min / 2, material.density);
    // The same step rule as the plan: dt_safety times the binary contact time of the lightest pair.
    result.dt = config.dt_safety *
                contactDuration(material.normal_stiffness, lightest / 2, material.restitution);
    for (int threads : config.threads) {
        DemSystem system(material);
        system.reserve(pile.x.size());
        system.addWall(Vec2(0, 0), Vec2(pile.width, 0));
        system.addWall(Vec2(0, 0), Vec2(0, 4 * pile.height));
        system.addWall(Vec2(pile.width, 0), Vec2(pile.width, 4 * pile.height));
        for (std::size_t k = 0; k < pile.x.size(); ++k)
            system.addDisc(pile.x[k], pile.y[k], pile.radius[k]);
        system.setGravity(Vec2(0, -9.81));
        system.setThreads(threads);
        system.sortSpatially();
        system.computeForces();
        for (int s = 0; s < 200; ++s)
            system.step(result.dt); // warm caches and threads
        const long long rebuilds0 = system.rebuilds();
        std::vector<double> seconds;
        for (int r = 0; r < std::max(config.repeats, 1); ++r) {
            const auto start = Clock::now();
            for (int s = 0; s < config.steps; ++s)
                system.step(result.dt);
            seconds.push_back(since(start));
        }
        std::sort(seconds.begin(), seconds.end());
        DemBenchRun run;
        run.seconds = seconds[seconds.size() / 2];
        run.threads = threads;
        run.particles = pile.x.size();
        run.steps = config.steps;
        const double work = static_cast<double>(run.particles) * run.steps;
        run.particle_steps_per_s = work / run.seconds;
        run.best_particle_steps_per_s = work / seconds.front();
        run.rebuilds = system.rebuilds() - rebuilds0;
        run.contacts = system.contacts().size();
        result.runs.push_back(run);
    }
    return result;
}

} // namespace lbdem::solver::dem
