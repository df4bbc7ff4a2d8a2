// DEM throughput benchmark: particle-steps per second on a settled pile of discs.
#pragma once

#include "solver/core/Real.h"
#include "solver/dem/ContactLaw.h"
#include "solver/dem/Packing.h"

#include <cstddef>
#include <vector>

namespace lbdem::solver::dem {

/// The pile measured by default: 10000 discs of the packing generator's default sizes, in a wide,
/// low pile (a = 0.25) that deposits quickly, deposited once with the material's own friction
/// (any settled pile will do; no search for a packing fraction).
PackingRequest defaultBenchPile();

/// What to measure. The contact law and sizes default to the paper's (docs/design.md §5b).
struct DemBenchConfig {
    PackingRequest pile = defaultBenchPile(); ///< discs, their contact law and the pile's shape
    Real dt_safety = 0.02; ///< step as a fraction of the binary contact time (as in the plan)
    std::vector<int> threads{1, 2}; ///< thread counts to measure
    int steps = 2000;               ///< steps per timed repeat
    int repeats = 3;                ///< timed repeats per thread count (median and best reported)
    PackingOptions packing;         ///< where the pile is cached
};

/// One measured thread count.
struct DemBenchRun {
    int threads = 0;
    std::size_t particles = 0;
    long long steps = 0;
    double seconds = 0;                   ///< of the median repeat
    double particle_steps_per_s = 0;      ///< median over the repeats
    double best_particle_steps_per_s = 0; ///< fastest repeat (least disturbed by other load)
    long long rebuilds = 0;               ///< neighbour-list rebuilds during the timed steps
    std::size_t contacts = 0;             ///< touching contacts at the end
};

/// All runs plus how the pile was obtained.
struct DemBenchResult {
    std::vector<DemBenchRun> runs;
    double pile_seconds = 0; ///< time to build (or read) the pile
    bool pile_from_cache = false;
    Real packing_fraction = 0; ///< of the settled pile
    Real dt = 0;               ///< DEM step used [s]
};

/// Build (or read from the cache) a settled pile, sort it by cell for locality, and time
/// config.steps steps of gravity-loaded contact dynamics for each thread count.
DemBenchResult runDemBench(const DemBenchConfig& config);

} // namespace lbdem::solver::dem
