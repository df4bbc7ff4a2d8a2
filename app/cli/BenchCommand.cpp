// `lbdem bench`: memory bandwidth and lattice-kernel throughput as a fraction of the roofline.
#include "app/cli/CaseBench.h"
#include "app/cli/Cli.h"
#include "app/cli/Commands.h"
#include "solver/core/InputError.h"
#include "solver/dem/DemBench.h"
#include "solver/lattice/Lattice.h"
#include "solver/lattice/MemoryBandwidth.h"
#include "solver/scene/ColumnScene.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace lbdem::cli {

namespace {

namespace lat = solver::lattice;

struct BenchOptions {
    bool json = false;
    int threads = 0;
    std::string size = "2000x1000";
    bool dem = false;
};

struct KernelResult {
    std::string name, precision;
    double mlups = 0, bytesPerUpdate = 0, rooflineMlups = 0, fraction = 0;
};

// Bytes moved per fluid-node update by the in-place (AA) kernel: 9 stored values read and the
// same 9 written back (8 bytes each for double storage, 4 for float). Flags are not read by the
// bulk kernel; link passes touch only boundary nodes.
double bytesPerUpdate(lat::PopulationStorage storage) {
    return 2.0 * 9 * (storage == lat::PopulationStorage::Float ? sizeof(float) : sizeof(double));
}
constexpr int kRepeats = 3; // the reported figure is the median of this many timed runs

void parseSize(const std::string& text, int& nx, int& ny) {
    const auto x = text.find_first_of("xX");
    try {
        if (x == std::string::npos) throw std::invalid_argument(text);
        nx = std::stoi(text.substr(0, x));
        ny = std::stoi(text.substr(x + 1));
    } catch (const std::exception&) {
        throw solver::InputError("--size '" + text + "' is not of the form NXxNY, e.g. 2000x1000");
    }
    if (nx < 8 || ny < 8 || static_cast<double>(nx) * ny > 1e9)
        throw solver::InputError("--size " + text + " is outside 8x8 .. 1e9 nodes");
}

// Million lattice updates per second of one collision model and population storage on an
// nx x ny box walled on all sides, median of kRepeats timed runs of about a second each.
double measureKernel(lat::CollisionModel model, lat::PopulationStorage storage, int nx, int ny) {
    lat::LatticeSetup setup;
    setup.storage = storage;
    setup.nx = nx;
    setup.ny = ny;
    setup.top.ux = 0.05; // a moving lid, so the flow is not at rest
    setup.collision.model = model;
    setup.collision.tau = 0.506;
    lat::Lattice lattice(setup);
    for (int s = 0; s < 3; ++s)
        lattice.step(); // warm up caches, pages and threads
    const double updatesPerStep = static_cast<double>(nx) * ny;
    const int steps = std::max(5, static_cast<int>(150e6 / updatesPerStep));
    std::vector<double> runs;
    for (int r = 0; r < kRepeats; ++r) {
        const auto start = std::chrono::steady_clock::now();
        for (int s = 0; s < steps; ++s)
            lattice.step();
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        runs.push_back(updatesPerStep * steps / seconds / 1e6);
    }
    std::sort(runs.begin(), runs.end());
    return runs[runs.size() / 2];
}

int runFluidBench(const BenchOptions& options) {
    int nx = 0, ny = 0;
    parseSize(options.size, nx, ny);
#ifdef _OPENMP
    if (options.threads > 0) omp_set_num_threads(options.threads);
    const int threads = omp_get_max_threads();
#else
    const int threads = 1;
#endif
    // The probe runs before and after the kernels; the roofline uses the median of all its
    // passes, the same statistic as the kernels' MLUPS (a shared machine's memory bandwidth
    // drifts: the best pass would be an outlier, a single probe a moment).
    std::vector<double> passes = lat::measureBandwidthPassesGBs();
    std::vector<KernelResult> results;
    // Double rows first (as before float storage existed), then the same models on float.
    for (auto storage : {lat::PopulationStorage::Double, lat::PopulationStorage::Float})
        for (auto model :
             {lat::CollisionModel::Bgk, lat::CollisionModel::Mrt, lat::CollisionModel::MrtLes}) {
            KernelResult r;
            r.name = solver::enumWord(model);
            r.precision = solver::enumWord(storage);
            r.mlups = measureKernel(model, storage, nx, ny);
            r.bytesPerUpdate = bytesPerUpdate(storage);
            results.push_back(r);
        }
    for (double rate : lat::measureBandwidthPassesGBs())
        passes.push_back(rate);
    std::sort(passes.begin(), passes.end());
    const double bandwidth = 0.5 * (passes[(passes.size() - 1) / 2] + passes[passes.size() / 2]);
    for (auto& r : results) {
        r.rooflineMlups = bandwidth * 1e9 / r.bytesPerUpdate / 1e6;
        r.fraction = r.mlups / r.rooflineMlups;
    }
    if (options.json) {
        nlohmann::json kernels = nlohmann::json::array();
        for (const auto& r : results)
            kernels.push_back({{"name", r.name},
                               {"precision", r.precision},
                               {"mlups", r.mlups},
                               {"bytes_per_update", r.bytesPerUpdate},
                               {"roofline_mlups", r.rooflineMlups},
                               {"fraction", r.fraction}});
        const nlohmann::json doc = {{"bandwidth_gbs", bandwidth},
                                    {"threads", threads},
                                    {"nx", nx},
                                    {"ny", ny},
                                    {"kernels", kernels}};
        std::cout << doc.dump(2) << "\n";
        return kExitOk;
    }
    std::printf(
        "memory bandwidth %.2f GB/s (in-place read-modify-write), %d threads, %d x %d nodes\n",
        bandwidth, threads, nx, ny);
    for (const auto& r : results)
        std::printf("%-8s %-6s %8.1f MLUPS  %4.0f B/update  roofline %7.1f MLUPS  fraction %.3f\n",
                    r.name.c_str(), r.precision.c_str(), r.mlups, r.bytesPerUpdate, r.rooflineMlups,
                    r.fraction);
    return kExitOk;
}

// Particle-steps per second on a settled pile with the paper's grains (docs/design.md §5b), for one
// thread and for the requested (or all) threads.
int runDemBench(const BenchOptions& options) {
    const solver::CaseSpec defaults = solver::defaultCase();
    solver::dem::DemBenchConfig config;
    config.pile.material = solver::grainMaterial(defaults.grains);
    config.pile.d_min = defaults.grains.d_min_m;
    config.pile.size_ratio = defaults.grains.size_ratio;
    config.dt_safety = defaults.grains.dt_safety;
#ifdef _OPENMP
    const int most = options.threads > 0 ? options.threads : omp_get_max_threads();
#else
    const int most = 1;
#endif
    config.threads = {1};
    if (most > 1) config.threads.push_back(most);
    if (!options.json)
        std::printf("building (or reading) a settled %d-disc pile...\n", config.pile.count);
    const solver::dem::DemBenchResult result = solver::dem::runDemBench(config);
    if (options.json) {
        nlohmann::json runs = nlohmann::json::array();
        for (const auto& r : result.runs)
            runs.push_back({{"threads", r.threads},
                            {"particles", r.particles},
                            {"steps", r.steps},
                            {"seconds", r.seconds},
                            {"particle_steps_per_s", r.particle_steps_per_s},
                            {"best_particle_steps_per_s", r.best_particle_steps_per_s},
                            {"rebuilds", r.rebuilds},
                            {"contacts", r.contacts}});
        const nlohmann::json doc = {{"dem", runs},
                                    {"dt_s", result.dt},
                                    {"packing_fraction", result.packing_fraction},
                                    {"pile_seconds", result.pile_seconds},
                                    {"pile_from_cache", result.pile_from_cache}};
        std::cout << doc.dump(2) << "\n";
        return kExitOk;
    }
    std::printf("pile: fraction %.4f, %s in %.1f s; dt %.3g s\n", result.packing_fraction,
                result.pile_from_cache ? "read from cache" : "generated", result.pile_seconds,
                result.dt);
    for (const auto& r : result.runs)
        std::printf("threads %d  %zu discs  %lld steps  %.2f s  %.2f M particle-steps/s (median; "
                    "best %.2f)  "
                    "(%lld rebuilds, %zu contacts)\n",
                    r.threads, r.particles, r.steps, r.seconds, r.particle_steps_per_s / 1e6,
                    r.best_particle_steps_per_s / 1e6, r.rebuilds, r.contacts);
    return kExitOk;
}

} // namespace

void addBenchCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<BenchOptions>();
    auto* command = app.add_subcommand("bench", "Measure memory bandwidth and lattice kernel "
                                                "throughput (MLUPS) against the roofline");
    command->add_flag("--json", options->json,
                      "Print {bandwidth_gbs, threads, nx, ny, kernels: [{name, precision, mlups, "
                      "bytes_per_update, roofline_mlups, fraction}]}; precision is the population "
                      "storage, double or float (the same collision names appear once for each)");
    command->add_option("--threads", options->threads, "OpenMP threads (0 = all cores)")
        ->check(CLI::Range(0, 1024));
    command->add_option("--size", options->size, "Lattice size NXxNY (default 2000x1000)");
    command->add_flag("--dem", options->dem, "Benchmark the DEM instead of the lattice");
    auto caseOptions = std::make_shared<CaseBenchOptions>();
    command->add_option(
        "--case", caseOptions->path,
        "Run this case for --tc and print per stage the time per step and its share, "
        "effective MLUPS, the bandwidth roofline and the projected time to the case's end; "
        "--json: {bandwidth_gbs, roofline_mlups, effective_mlups, stages: {name: s per "
        "step}, projected_end_s, threads, storage, ...}");
    command->add_option("--tc", caseOptions->tc, "Span of the --case run in tau_c (default 0.5)");
    command->add_option("--set", caseOptions->overrides,
                        "With --case: override a case key, key=value (repeatable)");
    command->callback([options, caseOptions, &exitCode] {
        if (!caseOptions->path.empty()) {
            caseOptions->json = options->json;
            caseOptions->threads = options->threads;
            exitCode = runCaseBench(*caseOptions);
            return;
        }
        exitCode = options->dem ? runDemBench(*options) : runFluidBench(*options);
    });
}

} // namespace lbdem::cli
