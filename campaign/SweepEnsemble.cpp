// Ensemble runs of a sweep and the spread of each case's figures over its packing seeds.
#include "campaign/SweepEnsemble.h"

#include "solver/core/InputError.h"
#include "solver/io/CaseLoader.h"
#include "solver/io/TimeSeriesWriter.h"
#include "solver/scene/Plan.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <stdexcept>

namespace lbdem::campaign {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct MetricText {
    const char* key;
    const char* heading;
    const char* pattern; ///< printf pattern of its Markdown cells
};
constexpr MetricText kMetricText[kEnsembleMetrics] = {
    {"runout_final", "(L_f - L_i)/L_i", "%.3f"},
    {"ke_peak", "peak E_k/E_p0", "%.4f"},
    {"t_ke_peak_over_tc", "t_peak/tau_c", "%.2f"},
    {"runout_at_3tc", "(L - L_i)/L_i at 3 tau_c", "%.3f"},
    {"froude_at_3tc", "Fr_d at 3 tau_c", "%.3f"},
    {"packing_final", "final packing", "%.3f"},
    {"pore_pressure_at_1tc_pa", "pore pressure on the failure plane at 1 tau_c (Pa)", "%.0f"},
};

double numberIn(const nlohmann::json& json, const char* key) {
    const auto found = json.find(key);
    return found != json.end() && found->is_number() ? found->get<double>() : kNaN;
}

/// What one run left: status and the metrics (those at 3 tau_c from its timeseries.csv).
EnsembleRun readRun(const SweepEntry& entry) {
    EnsembleRun run;
    run.seed = entry.seed;
    run.values.fill(kNaN);
    std::ifstream file(entry.dir / "summary.json");
    if (!file) {
        run.status = "missing";
        return run;
    }
    nlohmann::json summary;
    try {
        summary = nlohmann::json::parse(file);
    } catch (const nlohmann::json::exception&) {
        run.status = "unreadable";
        return run;
    }
    const bool finished = summary.value("finished", false);
    run.status = finished                          ? "finished"
                 : summary.contains("stop_reason") ? "unstable"
                                                   : "unfinished";
    if (!finished) return run;
    auto set = [&](EnsembleMetric metric, double value) {
        run.values[static_cast<std::size_t>(metric)] = value;
    };
    set(EnsembleMetric::RunoutFinal, numberIn(summary, "runout_final"));
    set(EnsembleMetric::KePeak, numberIn(summary, "ke_peak"));
    set(EnsembleMetric::TKePeak, numberIn(summary, "t_ke_peak_over_tc"));
    set(EnsembleMetric::PackingFinal, numberIn(summary, "packing_final"));
    const auto series = entry.dir / "timeseries.csv";
    set(EnsembleMetric::RunoutAt3Tc, valueAtTc(series, "runout_normalised", 3.0));
    if (entry.spec.fluid.enabled) {
        set(EnsembleMetric::FroudeAt3Tc, valueAtTc(series, "froude_densimetric", 3.0));
        set(EnsembleMetric::PoreAt1Tc, valueAtTc(series, "pore_pressure_failure_plane_pa", 1.0));
    }
    run.endReached = std::isfinite(endReachedTc(entry));
    return run;
}

/// "min-max" of a spread for Markdown; "-" below two values.
std::string rangeCell(const Spread& s, const char* pattern) {
    return s.count < 2 ? "-" : number(s.min, pattern) + "–" + number(s.max, pattern);
}

} // namespace

std::vector<int> firstSeeds(int count) {
    std::vector<int> seeds;
    for (int seed = 1; seed <= count; ++seed)
        seeds.push_back(seed);
    return seeds;
}

std::vector<SweepRun> planSweepRuns(const io::SweepSpec& sweep, const std::vector<int>& seeds,
                                    const std::filesystem::path& out) {
    std::map<std::string, std::string> fileOfName;
    std::vector<solver::CaseSpec> specs; // each case as the sweep's `set` leaves it, in order
    for (const auto& casePath : sweep.cases) {
        const auto spec = io::loadCase(casePath, sweep.overrides);
        (void)solver::makePlan(spec); // the planner's refusals come before anything runs too
        const auto [first, fresh] = fileOfName.emplace(spec.name, casePath);
        if (!fresh)
            throw solver::InputError(casePath + ": the case name '" + spec.name +
                                     "' is also that of " + first->second +
                                     "; each case of a sweep needs its own name (it names "
                                     "the output folder)");
        specs.push_back(spec);
    }
    // Without variants each case runs as it is: one variant with no name and no overrides.
    const auto variants =
        sweep.variants.empty() ? std::vector<io::SweepVariant>{{}} : sweep.variants;
    std::vector<SweepRun> runs;
    for (const auto& variant : variants) {
        for (std::size_t c = 0; c < sweep.cases.size(); ++c) {
            const auto& casePath = sweep.cases[c];
            auto overrides = sweep.overrides;
            overrides.insert(overrides.end(), variant.overrides.begin(), variant.overrides.end());
            auto variantSpec = specs[c];
            if (!variant.name.empty()) { // the variant's own case, checked by the planner too
                overrides.push_back("name=" + specs[c].name + "__" + variant.name);
                variantSpec = io::loadCase(casePath, overrides);
                (void)solver::makePlan(variantSpec);
            }
            if (seeds.empty()) {
                runs.push_back(
                    {{variantSpec, out / variantSpec.name, 0, variant.name}, casePath, overrides});
                continue;
            }
            for (const int seed : seeds) {
                auto seeded = overrides;
                seeded.push_back("grains.seed=" + std::to_string(seed));
                const auto seededSpec = io::loadCase(casePath, seeded);
                const std::string folder = seededSpec.name + "_s" + std::to_string(seed);
                runs.push_back({{seededSpec, out / folder, seed, variant.name}, casePath, seeded});
            }
        }
    }
    return runs;
}

std::string number(double value, const char* pattern) {
    if (!std::isfinite(value)) return "";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, pattern, value);
    return buffer;
}

std::string meanCell(const Spread& s, const char* pattern) {
    if (s.count == 0) return "-";
    if (s.count == 1) return number(s.mean, pattern);
    return number(s.mean, pattern) + " ± " + number(s.sd, pattern);
}

const char* metricKey(EnsembleMetric metric) {
    return kMetricText[static_cast<std::size_t>(metric)].key;
}

const char* metricHeading(EnsembleMetric metric) {
    return kMetricText[static_cast<std::size_t>(metric)].heading;
}

const char* metricPattern(EnsembleMetric metric) {
    return kMetricText[static_cast<std::size_t>(metric)].pattern;
}

Spread spreadOf(const std::vector<double>& values) {
    Spread s;
    double sum = 0;
    s.min = std::numeric_limits<double>::infinity(), s.max = -s.min;
    for (const double v : values)
        if (std::isfinite(v))
            ++s.count, sum += v, s.min = std::min(s.min, v), s.max = std::max(s.max, v);
    if (s.count == 0) return Spread{};
    s.mean = sum / s.count;
    double squares = 0;
    for (const double v : values)
        if (std::isfinite(v)) squares += (v - s.mean) * (v - s.mean);
    s.sd = s.count > 1 ? std::sqrt(squares / (s.count - 1)) : kNaN;
    return s;
}

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
    for (std::size_t k = 0; k < std::min(x.size(), y.size()); ++k) {
        if (x[k] == at) return y[k];
        if (k > 0 && x[k - 1] < at && at < x[k])
            return y[k - 1] + (y[k] - y[k - 1]) * (at - x[k - 1]) / (x[k] - x[k - 1]);
    }
    return kNaN;
}

double valueAtTc(const std::filesystem::path& series, const std::string& column, double tc) {
    try {
        const auto table = io::readTimeSeries(series.string());
        return interpolate(table.column("t_over_tc"), table.column(column), tc);
    } catch (const std::exception&) {
        return kNaN;
    }
}

std::vector<EnsembleCase> gatherEnsemble(const std::vector<SweepEntry>& entries) {
    std::vector<EnsembleCase> cases;
    std::map<std::string, std::size_t> index;
    for (const auto& entry : entries) {
        const auto [at, fresh] = index.emplace(entry.spec.name, cases.size());
        if (fresh)
            cases.push_back({entry.spec.name,
                             entry.spec.grains.packing,
                             entry.spec.domain.slope_deg,
                             entry.spec.fluid.enabled,
                             {},
                             0,
                             0,
                             0,
                             {},
                             entry.variant});
        auto& c = cases[at->second];
        c.runs.push_back(readRun(entry));
        c.finished += c.runs.back().status == "finished";
        c.unstable += c.runs.back().status == "unstable";
        c.endReached += c.runs.back().endReached;
    }
    for (auto& c : cases)
        for (std::size_t m = 0; m < kEnsembleMetrics; ++m) {
            std::vector<double> values;
            for (const auto& run : c.runs)
                values.push_back(run.values[m]);
            c.spread[m] = spreadOf(values);
        }
    return cases;
}

std::string ensembleCsv(const std::vector<EnsembleCase>& cases) {
    std::string csv = "case,packing,slope_deg,medium,seeds,finished,unstable,front_at_end";
    for (std::size_t m = 0; m < kEnsembleMetrics; ++m)
        for (const char* stat : {"_mean", "_sd", "_min", "_max"})
            csv += std::string(",") + kMetricText[m].key + stat;
    csv += "\n";
    for (const auto& c : cases) {
        csv += c.name + "," + number(c.packing, "%.2f") + "," + number(c.slope_deg, "%.1f") + "," +
               (c.submerged ? "submerged" : "dry") + "," + std::to_string(c.runs.size()) + "," +
               std::to_string(c.finished) + "," + std::to_string(c.unstable) + "," +
               std::to_string(c.endReached);
        for (const auto& s : c.spread)
            for (const double v : {s.mean, s.sd, s.min, s.max})
                csv += "," + (s.count ? number(v, "%.6g") : "");
        csv += "\n";
    }
    return csv;
}

std::string ensembleMarkdown(const std::vector<EnsembleCase>& cases) {
    std::string md = "| case | seeds | finished | unstable |";
    std::string rule = "|---|---|---|---|";
    for (std::size_t m = 0; m < kEnsembleMetrics; ++m) {
        md += std::string(" ") + kMetricText[m].heading + ": mean ± sd | min–max |";
        rule += "---|---|";
    }
    md += "\n" + rule + "\n";
    for (const auto& c : cases) {
        md += "| " + c.name + " | " + std::to_string(c.runs.size()) + " | " +
              std::to_string(c.finished) + " | " + std::to_string(c.unstable) + " |";
        for (std::size_t m = 0; m < kEnsembleMetrics; ++m) {
            const char* pattern = kMetricText[m].pattern;
            std::string mean = meanCell(c.spread[m], pattern);
            if (m == 0 && c.endReached > 0) mean += " (end: " + std::to_string(c.endReached) + ")";
            md += " " + mean + " | " + rangeCell(c.spread[m], pattern) + " |";
        }
        md += "\n";
    }
    return md;
}

} // namespace lbdem::campaign
