// The table and figure of a study: each setting's metric, its error, wall time and MLUPS.
#pragma once

#include "app/cli/StudyMetrics.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lbdem::cli {

/// What the error of each setting is measured against.
enum class StudyReference {
    Analytic, ///< the analytic or published value the run reports (or the metric is an error)
    Finest,   ///< the metric of the finest setting (largest resolution, else the last given)
};

/// One setting of a study and its run folder.
struct StudySetting {
    std::string value;         ///< the value of the varied key, as given
    std::filesystem::path dir; ///< OUT/<key>=<value>
};

/// A study: the case, the varied key and its settings, the metric and the reference.
struct StudySpec {
    std::string caseName;
    std::string key;
    std::vector<StudySetting> settings;
    StudyMetric metric;
    StudyReference reference = StudyReference::Finest;
    bool resolution = false; ///< key is a resolution: report the observed order
};

/// One setting's numbers, read from its summary.json.
struct StudyRow {
    std::string setting;             ///< key=value
    std::string status;              ///< finished, unfinished, missing, unreadable or "no metric"
    std::optional<double> value;     ///< the metric
    std::optional<double> reference; ///< what the error is measured against
    std::optional<double> error;     ///< relative error (absolute when the reference is 0)
    std::optional<double> order;     ///< observed order against the previous setting
    double wallS = 0;                ///< wall time of the whole run
    double mlups = 0;
    bool wallExtrapolated = false; ///< resumed run: wall time scaled up from the timed steps
};

/// True when dir/summary.json says the run finished (a study then skips it).
bool runFinished(const std::filesystem::path& dir);

/// The metric of one setting's summary.json, when it is there.
std::optional<double> readStudyMetric(const StudySpec& study, const StudySetting& setting);

/// Read every setting's summary.json and compute errors and observed orders.
std::vector<StudyRow> tabulateStudy(const StudySpec& study);

/// Least-squares order of convergence over the rows with a positive error (nullopt if < 2).
std::optional<double> fittedOrder(const StudySpec& study, const std::vector<StudyRow>& rows);

/// Write OUT/study.csv and OUT/study.md (and OUT/study.png when plotted is true); returns the
/// paths written.
std::vector<std::string> writeStudyTables(const StudySpec& study, const std::vector<StudyRow>& rows,
                                          const std::filesystem::path& out, bool plotted);

} // namespace lbdem::cli
