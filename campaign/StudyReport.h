// The table and figure of a study: each setting's metric, its error, wall time and MLUPS.
#pragma once

#include "campaign/StudyMetrics.h"

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace lbdem::campaign {

/// What the error of each setting is measured against.
enum class StudyReference {
    Analytic, ///< the analytic or published value the run reports (or the metric is an error)
    Finest,   ///< the metric of the finest setting along the reference key, the others held
};

/// One setting of a study (one point of the product of the varied keys) and its run folder.
struct StudySetting {
    std::vector<std::string> values; ///< the value of each varied key, as given
    std::filesystem::path dir;       ///< OUT/<key>=<value>[,<key>=<value>...]
};

/// A study: the case, the varied keys and their product, the metric and the reference.
struct StudySpec {
    std::string caseName;
    std::vector<std::string> keys;      ///< the varied keys, in the order given
    std::vector<StudySetting> settings; ///< the cartesian product, the first key slowest
    StudyMetric metric;
    StudyReference reference = StudyReference::Finest;
    int resolutionKey = -1; ///< index of the key that sets the resolution (observed order), or -1
};

/// One setting's numbers, read from its summary.json.
struct StudyRow {
    std::string setting;   ///< key=value[,key=value...]
    std::string status;    ///< finished, unstable, unfinished, missing, unreadable or "no metric"
    std::string diagnosis; ///< unstable: the first line of the stability guard's message
    std::optional<double> value;     ///< the metric
    std::optional<double> reference; ///< what the error is measured against
    std::optional<double> error;     ///< relative error (absolute when the reference is 0)
    std::optional<double> order;     ///< observed order against the previous resolution
    double wallS = 0;                ///< wall time of the whole run
    double mlups = 0;
    bool wallExtrapolated = false; ///< resumed run: wall time scaled up from the timed steps
};

/// "key=value" for each varied key, joined by commas: the setting's label and folder name.
std::string settingLabel(const StudySpec& study, const StudySetting& setting);

/// The key along which errors against the finest setting and observed orders are taken: the
/// resolution key when one is varied, else the last key.
int referenceKey(const StudySpec& study);

/// True when dir/summary.json says the run finished (a study then skips it).
bool runFinished(const std::filesystem::path& dir);

/// The first line of the diagnosis when the stability guard stopped the run in dir
/// (summary.json: finished = false and stop_reason), else nullopt.
std::optional<std::string> runUnstable(const std::filesystem::path& dir);

/// The metric of one setting's summary.json, when it is there.
std::optional<double> readStudyMetric(const StudySpec& study, const StudySetting& setting);

/// Read every setting's summary.json and compute errors and observed orders.
std::vector<StudyRow> tabulateStudy(const StudySpec& study);

/// A least-squares order of convergence fitted to one series of settings.
struct FittedOrder {
    std::string series; ///< the values of the other keys ("" for a one-key study)
    double order = 0;
};

/// Least-squares order over the rows with a positive error, one per series of settings that
/// differ only in the resolution key (none when no resolution key is varied or < 2 points).
std::vector<FittedOrder> fittedOrders(const StudySpec& study, const std::vector<StudyRow>& rows);

/// Write OUT/study.csv and OUT/study.md (linking OUT/study.png when plotted is true, else
/// stating plotNote when it is not empty); returns the paths written.
std::vector<std::string> writeStudyTables(const StudySpec& study, const std::vector<StudyRow>& rows,
                                          const std::filesystem::path& out, bool plotted,
                                          const std::string& plotNote = {});

/// Draws the error of each row against its wall time into the PNG file path (study.png); returns
/// false when it draws nothing. An empty plotter: this build cannot draw.
using StudyPlotter = std::function<bool(const StudySpec& study, const std::vector<StudyRow>& rows,
                                        const std::string& path)>;

/// What writeStudyReport wrote.
struct StudyReportResult {
    std::vector<std::string> files; ///< study.csv, study.md, study.png when drawn, study_map.md
    std::string plotNote;           ///< why study.png is not drawn although plot could draw it
};

/// Tabulate the study from its runs' summary.json: OUT/study.csv and OUT/study.md, OUT/study.png
/// (drawn by plot) when the errors have a scale, and OUT/study_map.md over two or more keys.
StudyReportResult writeStudyReport(const StudySpec& study, const std::filesystem::path& out,
                                   const StudyPlotter& plot);

} // namespace lbdem::campaign
