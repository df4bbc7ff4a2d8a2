// The paper's findings checked seed by seed on a sweep's ensemble: for how many packing seeds
// each one holds, at each slope.
#pragma once

#include "campaign/SweepEnsemble.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lbdem::campaign {

/// One finding at one slope (or over all slopes) and how many seeds support it.
struct Finding {
    std::string statement; ///< e.g. "dense: dry runout longer than submerged"
    std::string where;     ///< "5 deg", or "0-7.5 deg" for a finding over the slopes
    int holds = 0;         ///< seeds for which it holds
    int fails = 0;         ///< seeds for which it does not
    int undecided = 0; ///< seeds where a front at the domain's end leaves the runout a lower bound
                       ///< that decides nothing
    int seeds() const { return holds + fails + undecided; }
};

/// The paper's findings (Kumar, Delenne & Soga, as listed in docs/paper.md) that the cases of
/// the sweep allow, each compared seed by seed between runs of the same packing seed that both
/// finished; a finding whose cases are not in the sweep is left out. In a sweep with variants,
/// only the first variant's cases count.
std::vector<Finding> computeFindings(const std::vector<EnsembleCase>& cases);

/// findings.csv and the Markdown table ("holds for k of n seeds").
std::string findingsCsv(const std::vector<Finding>& findings);
std::string findingsMarkdown(const std::vector<Finding>& findings);

/// The ensemble and variant parts of a sweep report; all empty for a sweep of single runs.
struct SweepEnsembleReport {
    std::string markdown; ///< the variants, spread and findings sections, then the runs' heading
    std::string csv;      ///< the per-case spread table, written as OUT/sweep.csv (seeds only)
    std::vector<std::string> files; ///< OUT/variants.csv, OUT/sweep.csv and OUT/findings.csv
};

/// When entries hold variants: writes OUT/variants.csv (each variant against the reference);
/// when they hold ensemble runs (a seed each): OUT/sweep.csv (spread per case) and
/// OUT/findings.csv. Returns the Markdown of what it wrote.
SweepEnsembleReport sweepEnsembleReport(const std::vector<SweepEntry>& entries,
                                        const std::filesystem::path& out);

} // namespace lbdem::campaign
