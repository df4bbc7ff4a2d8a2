// Ensembles over packing seeds: the runs of a sweep (each case once per seed) and the spread of
// each case's figures over its seeds.
#pragma once

#include "campaign/SweepReport.h"
#include "solver/io/SweepFile.h"

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace lbdem::campaign {

/// One run of a sweep: its case, seed and folder, and how `lbdem run` starts it.
struct SweepRun {
    SweepEntry entry;                   ///< the case as run (seed applied) and its output folder
    std::string casePath;               ///< the case file
    std::vector<std::string> overrides; ///< the sweep's `set` plus grains.seed=K in an ensemble
};

/// Seeds 1, 2, ..., count (`lbdem sweep --seeds N`).
std::vector<int> firstSeeds(int count);

/// Every run of the sweep, variants in order (the reference first), then cases, then seeds: one
/// run per case in OUT/NAME when `seeds` is empty, else one per seed in OUT/NAME_sK with
/// grains.seed = K; with variants NAME is CASE__VARIANT (the run's case name too).
/// Loads and plans each case, and refuses two cases of one name (one output folder): throws
/// InputError before anything runs.
std::vector<SweepRun> planSweepRuns(const io::SweepSpec& sweep, const std::vector<int>& seeds,
                                    const std::filesystem::path& out);

/// The figures compared over seeds, in table order.
enum class EnsembleMetric : std::size_t {
    RunoutFinal,  ///< (L_f - L_i)/L_i at the end of the run
    KePeak,       ///< peak E_k/E_p0
    TKePeak,      ///< t/tau_c of that peak
    RunoutAt3Tc,  ///< (L - L_i)/L_i at t = 3 tau_c
    FroudeAt3Tc,  ///< densimetric Froude number of the front at 3 tau_c (submerged cases)
    PackingFinal, ///< packing fraction at the end
    PoreAt1Tc,    ///< excess pore pressure on the failure plane at 1 tau_c [Pa] (submerged cases)
    Count
};
constexpr std::size_t kEnsembleMetrics = static_cast<std::size_t>(EnsembleMetric::Count);

/// Column name (CSV), heading (Markdown) and printf pattern (Markdown cells) of a metric.
const char* metricKey(EnsembleMetric metric);
const char* metricHeading(EnsembleMetric metric);
const char* metricPattern(EnsembleMetric metric);

/// value printed with a printf pattern; "" when it is not finite.
std::string number(double value, const char* pattern);

/// Mean, sample standard deviation (NaN below two values), min and max of the finite values.
struct Spread {
    int count = 0;
    double mean = 0, sd = 0, min = 0, max = 0;
};
Spread spreadOf(const std::vector<double>& values);

/// "mean ± sd", the one value of a single run, or "-" when no run gave one (Markdown cells).
std::string meanCell(const Spread& s, const char* pattern);

/// What one run of an ensemble left on disk.
struct EnsembleRun {
    int seed = 0;
    std::string status; ///< finished, unstable (stopped by the stability guard), unfinished,
                        ///< missing, unreadable
    std::array<double, kEnsembleMetrics> values{}; ///< NaN where the run has no value
    bool endReached = false; ///< its front reached the domain's end: the runout is a lower bound
};

/// One case over its seeds: the runs and the spread of each metric over the finished ones.
struct EnsembleCase {
    std::string name;
    double packing = 0, slope_deg = 0;
    bool submerged = false;
    std::vector<EnsembleRun> runs;
    int finished = 0, unstable = 0, endReached = 0; ///< how many runs (endReached: of the finished)
    std::array<Spread, kEnsembleMetrics> spread{};
    std::string variant; ///< its variant in a controlled-experiment sweep; empty outside one
};

/// y at x = at, linear between the points (x increasing); NaN outside them or where y is not
/// finite.
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at);

/// The value of a column of timeseries.csv at t/tau_c = tc, linear between rows; NaN when the
/// file, the column or that time is missing.
double valueAtTc(const std::filesystem::path& series, const std::string& column, double tc);

/// Reads each run of entries (summary.json, timeseries.csv) and groups them by case name, cases
/// in the order of their first run.
std::vector<EnsembleCase> gatherEnsemble(const std::vector<SweepEntry>& entries);

/// The per-case table: CSV (mean, sd, min, max of each metric) and Markdown (mean ± sd, min-max).
std::string ensembleCsv(const std::vector<EnsembleCase>& cases);
std::string ensembleMarkdown(const std::vector<EnsembleCase>& cases);

} // namespace lbdem::campaign
