// The combined table and figures of a sweep.
#pragma once

#include "campaign/SweepFigureCase.h"
#include "solver/scene/CaseSpec.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lbdem::campaign {

/// One run of a sweep (a case, or a case with one packing seed of an ensemble) and its folder.
struct SweepEntry {
    solver::CaseSpec spec = solver::defaultCase();
    std::filesystem::path dir;
    int seed = 0;        ///< the packing seed of an ensemble run; 0 outside an ensemble
    std::string variant; ///< the variant of a controlled-experiment sweep; empty outside one
};

/// The first line of a run's log that reports an error ("lbdem: ..."), or a note that the log
/// has none; what a sweep shows for a case that failed.
std::string firstErrorLine(const std::filesystem::path& logPath);

/// t/tau_c at which the front first came within the largest grain diameter of the domain's end
/// (from then on the runout is bounded by the domain, not by the flow); NaN when it never did.
double endReachedTc(const SweepEntry& entry);

/// What writeSweepReport wrote.
struct SweepReportResult {
    std::vector<std::string> files; ///< sweep.csv, sweep.md and the PNG figures
    std::string note;               ///< why figures are missing (no VTK, nothing finished ...)
};

/// Write OUT/sweep.csv, OUT/sweep.md and the paper's figures (drawn by writeSweepFigures), from
/// each case's summary.json and timeseries.csv; sweep.md links the figures and names the cases
/// left out of them. An ensemble (runs with a seed) gets the per-case spread over its seeds in
/// sweep.csv and sweep.md, the findings in findings.csv and sweep.md, one row per run in runs.csv.
SweepReportResult writeSweepReport(const std::string& name, const std::vector<SweepEntry>& entries,
                                   const std::filesystem::path& out,
                                   const SweepFigureWriter& writeSweepFigures);

} // namespace lbdem::campaign
