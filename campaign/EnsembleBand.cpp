// Ensemble bands from the runs' timeseries.csv.
#include "campaign/EnsembleBand.h"

#include "campaign/StudyReport.h"
#include "campaign/SweepEnsemble.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <exception>

namespace lbdem::campaign {

namespace fs = std::filesystem;

EnsembleBand ensembleBand(const std::vector<io::TimeSeriesTable>& tables,
                          const std::string& column) {
    EnsembleBand band;
    if (tables.empty()) return band;
    band.runs = static_cast<int>(tables.size());
    std::vector<std::vector<double>> times, values;
    for (const auto& table : tables)
        times.push_back(table.column("t_over_tc")), values.push_back(table.column(column));
    for (const double at : times.front()) {
        std::vector<double> ys;
        for (std::size_t r = 0; r < tables.size(); ++r)
            ys.push_back(interpolate(times[r], values[r], at));
        const Spread spread = spreadOf(ys);
        if (!std::isfinite(at) || spread.count < static_cast<int>(ys.size())) continue;
        band.t_over_tc.push_back(at), band.mean.push_back(spread.mean);
        band.min.push_back(spread.min), band.max.push_back(spread.max);
    }
    return band;
}

std::vector<fs::path> finishedEnsembleRuns(const fs::path& sweepOut, const std::string& caseName) {
    std::vector<std::pair<long, fs::path>> runs;
    const std::string prefix = caseName + "_s";
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(sweepOut, error)) {
        const std::string name = entry.path().filename().string();
        if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
        const std::string digits = name.substr(prefix.size());
        if (!std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
            continue;
        if (entry.is_directory(error) && runFinished(entry.path()))
            runs.emplace_back(std::strtol(digits.c_str(), nullptr, 10), entry.path());
    }
    std::sort(runs.begin(), runs.end());
    std::vector<fs::path> folders;
    for (const auto& run : runs)
        folders.push_back(run.second);
    return folders;
}

EnsembleBand loadEnsembleBand(const fs::path& sweepOut, const std::string& caseName,
                              const std::string& column) {
    std::vector<io::TimeSeriesTable> tables;
    for (const auto& dir : finishedEnsembleRuns(sweepOut, caseName)) {
        try {
            auto table = io::readTimeSeries((dir / "timeseries.csv").string());
            if (!table.column(column).empty()) tables.push_back(std::move(table));
        } catch (const std::exception&) {
            // a finished run whose series cannot be read is left out of the band
        }
    }
    auto band = ensembleBand(tables, column);
    if (band.t_over_tc.empty()) band.runs = 0;
    return band;
}

} // namespace lbdem::campaign
