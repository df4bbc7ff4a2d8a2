// The band of an ensemble: one column of timeseries.csv over the packing seeds of a case, as the
// mean, min and max at each output time (what the sweep figures shade, what the studio can draw
// behind a live curve).
#pragma once

#include "solver/io/TimeSeriesWriter.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lbdem::campaign {

/// A column over the runs of an ensemble: at each time of the first run that every run covers
/// with a finite value, the mean, min and max over the runs.
struct EnsembleBand {
    std::vector<double> t_over_tc, mean, min, max;
    int runs = 0; ///< how many runs the band is taken over
};

/// The band of column over tables (each a run's timeseries.csv), linear between each run's rows;
/// empty when there is no table.
EnsembleBand ensembleBand(const std::vector<io::TimeSeriesTable>& tables,
                          const std::string& column);

/// The folders of the finished runs of caseName in a sweep's output folder (OUT/NAME_sK whose
/// summary.json says finished), in increasing seed.
std::vector<std::filesystem::path> finishedEnsembleRuns(const std::filesystem::path& sweepOut,
                                                        const std::string& caseName);

/// The band of column over the finished runs of caseName in sweepOut; empty (runs = 0) when the
/// case has no finished run there or none of them has the column.
EnsembleBand loadEnsembleBand(const std::filesystem::path& sweepOut, const std::string& caseName,
                              const std::string& column);

} // namespace lbdem::campaign
