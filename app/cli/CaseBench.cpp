// `lbdem bench --case`: a case run for a short span, its stage times, MLUPS and the roofline.
#include "app/cli/CaseBench.h"

#include "app/cli/CaseOptions.h"
#include "app/cli/Cli.h"
#include "solver/core/InputError.h"
#include "solver/lattice/MemoryBandwidth.h"
#include "solver/lattice/PopulationStorage.h"
#include "solver/scene/Plan.h"
#include "solver/scene/Simulation.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace lbdem::cli {

namespace {

/// Median of the passes (the mean of the middle two for an even count).
double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return 0.5 * (values[(values.size() - 1) / 2] + values[values.size() / 2]);
}

/// Bytes moved per node update by the in-place (AA) bulk kernel: nine values read, nine written.
double bytesPerUpdate(solver::lattice::PopulationStorage storage) {
    return 2.0 * 9 * (storage == solver::lattice::PopulationStorage::Float ? 4 : 8);
}

} // namespace

int runCaseBench(const CaseBenchOptions& options) {
    if (!(options.tc > 0)) throw solver::InputError("--tc must be a positive span in tau_c");
    const solver::CaseSpec spec = CaseOptions{options.path, options.overrides}.load();
    const solver::Plan plan = solver::makePlan(spec);
#ifdef _OPENMP
    if (options.threads > 0)
        omp_set_num_threads(options.threads);
    else if (spec.run.threads > 0)
        omp_set_num_threads(spec.run.threads);
    const int threads = omp_get_max_threads();
#else
    const int threads = 1;
#endif
    std::vector<double> passes = solver::lattice::measureBandwidthPassesGBs();
    solver::Simulation simulation(spec, plan); // set-up (packing, lattice) is not timed
    const double endS = std::min(options.tc * plan.tc_s, plan.end_time_s);
    const auto start = std::chrono::steady_clock::now();
    long long steps = 0;
    while (simulation.time() < endS - 0.5 * plan.dt_s) {
        simulation.step();
        ++steps;
    }
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (double rate : solver::lattice::measureBandwidthPassesGBs())
        passes.push_back(rate);
    const double bandwidth = median(passes);
    const double nodes = static_cast<double>(plan.nx) * plan.ny;
    const double perStep = steps > 0 ? wall / steps : 0;
    const double roofline = bandwidth * 1e9 / bytesPerUpdate(spec.fluid.storage) / 1e6;
    const double effective = wall > 0 ? nodes * steps / wall / 1e6 : 0;
    const double projected = plan.end_time_s / plan.dt_s * perStep;
    const auto& timer = simulation.timer();
    if (options.json) {
        nlohmann::json stages = nlohmann::json::object();
        for (std::size_t k = 0; k < static_cast<std::size_t>(solver::Stage::Count); ++k) {
            const auto stage = static_cast<solver::Stage>(k);
            stages[std::string(solver::stageName(stage))] =
                steps > 0 ? timer.seconds(stage) / steps : 0.0;
        }
        const nlohmann::json doc = {{"case", spec.name},
                                    {"tc", options.tc},
                                    {"steps", steps},
                                    {"wall_s", wall},
                                    {"nx", plan.nx},
                                    {"ny", plan.ny},
                                    {"bandwidth_gbs", bandwidth},
                                    {"roofline_mlups", roofline},
                                    {"effective_mlups", effective},
                                    {"stages", stages},
                                    {"projected_end_s", projected},
                                    {"end_tc", plan.end_time_s / plan.tc_s},
                                    {"threads", threads},
                                    {"storage", solver::enumWord(spec.fluid.storage)}};
        std::cout << doc.dump(2) << "\n";
        return kExitOk;
    }
    std::printf(
        "%s: %lld steps (%.3g tau_c) of %d x %d nodes in %.2f s on %d threads, %s storage\n",
        spec.name.c_str(), steps, options.tc, plan.nx, plan.ny, wall, threads,
        solver::enumWord(spec.fluid.storage));
    const double staged = std::max(timer.total(), 1e-300);
    for (std::size_t k = 0; k < static_cast<std::size_t>(solver::Stage::Count); ++k) {
        const auto stage = static_cast<solver::Stage>(k);
        std::printf("  %-20s %9.3f ms/step  %5.1f %%\n",
                    std::string(solver::stageName(stage)).c_str(),
                    steps > 0 ? 1e3 * timer.seconds(stage) / steps : 0.0,
                    100 * timer.seconds(stage) / staged);
    }
    std::printf(
        "effective %.1f MLUPS; roofline %.1f MLUPS (memory bandwidth %.2f GB/s, %.0f B/update)\n",
        effective, roofline, bandwidth, bytesPerUpdate(spec.fluid.storage));
    std::printf("projected to the case's end (%.3g tau_c, %.0f steps): %.0f s\n",
                plan.end_time_s / plan.tc_s, plan.end_time_s / plan.dt_s, projected);
    return kExitOk;
}

} // namespace lbdem::cli
