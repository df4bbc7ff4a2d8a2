// The combined table and figures of a sweep.
#pragma once

#include "solver/scene/CaseSpec.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lbdem::cli {

/// One case of a sweep and its output folder.
struct SweepEntry {
    solver::CaseSpec spec;
    std::filesystem::path dir;
};

/// The first line of a run's log that reports an error ("lbdem: ..."), or a note that the log
/// has none; what a sweep shows for a case that failed.
std::string firstErrorLine(const std::filesystem::path& logPath);

/// What writeSweepReport wrote.
struct SweepReportResult {
    std::vector<std::string> files; ///< sweep.csv, sweep.md and the PNG figures
    std::string note;               ///< why figures are missing (no VTK, nothing finished ...)
};

/// Write OUT/sweep.csv, OUT/sweep.md and (when built with VTK) the paper's figures as PNG, from
/// each case's summary.json and timeseries.csv; sweep.md links the figures and names the cases
/// left out of them.
SweepReportResult writeSweepReport(const std::string& name, const std::vector<SweepEntry>& entries,
                                   const std::filesystem::path& out);

} // namespace lbdem::cli
