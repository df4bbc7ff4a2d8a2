// Study table (CSV and Markdown) from the runs' summaries.
#include "campaign/StudyReport.h"

#include "campaign/StudyMap.h"

#include "solver/io/CaseWriter.h"
#include "solver/scene/SceneMetrics.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace lbdem::campaign {

namespace {

using Json = nlohmann::json;

std::optional<Json> readSummary(const std::filesystem::path& dir) {
    std::ifstream file(dir / "summary.json");
    if (!file) return std::nullopt;
    try {
        return Json::parse(file);
    } catch (const Json::exception&) {
        return Json(); // null: unreadable
    }
}

/// A number at the top level of summary.json, else in its "final" object.
std::optional<double> numberIn(const Json& summary, const std::string& name) {
    for (const Json* where : {&summary, summary.contains("final") ? &summary["final"] : nullptr}) {
        if (!where || !where->is_object()) continue;
        const auto found = where->find(name);
        if (found != where->end() && found->is_number()) return found->get<double>();
    }
    return std::nullopt;
}

/// The first line of summary.json's stop_reason of an unfinished run, if there is one.
std::optional<std::string> stopReason(const Json& summary) {
    if (!summary.is_object() || summary.value("finished", false)) return std::nullopt;
    const auto found = summary.find("stop_reason");
    if (found == summary.end() || !found->is_string()) return std::nullopt;
    const std::string text = found->get<std::string>();
    return text.substr(0, text.find('\n'));
}

std::optional<double> numericValue(const std::string& text) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(value)) return std::nullopt;
    return value;
}

/// True when settings a and b have the same value of every key but key.
bool sameExcept(const StudySetting& a, const StudySetting& b, int key) {
    for (std::size_t k = 0; k < a.values.size(); ++k)
        if (static_cast<int>(k) != key && a.values[k] != b.values[k]) return false;
    return true;
}

/// "key=value" of every key but skip, joined by commas: the series a setting belongs to.
std::string seriesLabel(const StudySpec& study, const StudySetting& setting, int skip) {
    std::string label;
    for (std::size_t k = 0; k < study.keys.size(); ++k) {
        if (static_cast<int>(k) == skip) continue;
        label += (label.empty() ? "" : ",") + study.keys[k] + "=" + setting.values[k];
    }
    return label;
}

/// The setting whose metric is the reference of row k under --reference finest: the largest
/// resolution (else the last value given) of the reference key, the other keys held.
std::size_t finestIndex(const StudySpec& study, std::size_t k) {
    const int axis = referenceKey(study);
    std::size_t finest = k;
    for (std::size_t j = 0; j < study.settings.size(); ++j) {
        if (!sameExcept(study.settings[j], study.settings[k], axis)) continue;
        if (axis != study.resolutionKey) {
            finest = j; // the last in the product order is the last value given
            continue;
        }
        if (numericValue(study.settings[j].values[axis]).value_or(-1e300) >
            numericValue(study.settings[finest].values[axis]).value_or(-1e300))
            finest = j;
    }
    return finest;
}

StudyRow readRow(const StudySpec& study, const StudySetting& setting) {
    StudyRow row;
    row.setting = settingLabel(study, setting);
    const auto summary = readSummary(setting.dir);
    if (!summary) {
        row.status = "missing";
        return row;
    }
    if (summary->is_null()) {
        row.status = "unreadable";
        return row;
    }
    row.status = summary->value("finished", false) ? "finished" : "unfinished";
    row.wallS = numberIn(*summary, "wall_s").value_or(0);
    row.mlups = numberIn(*summary, "mlups").value_or(0);
    if (const auto reason = stopReason(*summary)) {
        row.status = "unstable"; // its last metrics are from before the divergence: not used
        row.diagnosis = *reason;
        return row;
    }
    row.value = numberIn(*summary, study.metric.name);
    if (!row.value) row.status = "no metric";
    // A resumed run times only the steps after the resume (RunDriver): scale up to all steps.
    if (const auto plan = summary->find("plan"); plan != summary->end() && plan->is_object()) {
        const double nodes = plan->value("nx", 0.0) * plan->value("ny", 0.0);
        const double steps = numberIn(*summary, "steps").value_or(0);
        const double timed = nodes > 0 ? row.mlups * 1e6 * row.wallS / nodes : 0;
        if (timed > 0 && timed < 0.99 * steps) {
            row.wallS *= steps / timed;
            row.wallExtrapolated = true;
        }
    }
    if (study.reference == StudyReference::Analytic && !study.metric.isError)
        row.reference = numberIn(*summary, study.metric.name + solver::kReferenceSuffix);
    return row;
}

std::string number(const std::optional<double>& value, const char* pattern) {
    if (!value) return "";
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, pattern, *value);
    return buffer;
}

/// text as one CSV field: quoted, inner quotes doubled.
std::string csvQuoted(const std::string& text) {
    std::string field = "\"";
    for (const char c : text)
        field += c == '"' ? std::string("\"\"") : std::string(1, c);
    return field + "\"";
}

std::string describeReference(const StudySpec& study, const std::vector<StudyRow>& rows) {
    const std::string& metric = study.metric.name;
    if (study.reference == StudyReference::Finest) {
        if (study.keys.size() == 1)
            return "relative error against the finest setting, " +
                   rows[finestIndex(study, 0)].setting;
        const int axis = referenceKey(study);
        return "relative error against the " +
               std::string(axis == study.resolutionKey ? "largest" : "last given") + " value of " +
               study.keys[axis] + " with the other keys held";
    }
    if (study.metric.isError)
        return "the metric is itself the error against the analytic or published answer";
    return "relative error against the analytic or published value the run reports (" + metric +
           solver::kReferenceSuffix + ")";
}

/// The Markdown table: a column per varied key, then status, metric, error, time and order.
std::string markdownTable(const StudySpec& study, const std::vector<StudyRow>& rows) {
    const bool orders = study.resolutionKey >= 0;
    std::string md = "|", rule = "|";
    for (const auto& key : study.keys)
        md += " " + key + " |", rule += "---|";
    md += " status | " + study.metric.name + " | reference | error | wall (s) | MLUPS |" +
          (orders ? " order |\n" : "\n");
    md += rule + "---|---|---|---|---|---|" + (orders ? "---|\n" : "\n");
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const auto& r = rows[k];
        md += "|";
        for (const auto& value : study.settings[k].values)
            md += " " + value + " |";
        md += " " + r.status + " | " + number(r.value, "%.6g") + " | " +
              (study.metric.isError && study.reference == StudyReference::Analytic
                   ? (r.value ? "0" : "")
                   : number(r.reference, "%.6g")) +
              " | " + number(r.error, "%.3g") + " | " + number(r.wallS, "%.3g") +
              (r.wallExtrapolated ? "*" : "") + " | " + number(r.mlups, "%.1f") + " |" +
              (orders ? " " + number(r.order, "%.2f") + " |\n" : "\n");
    }
    return md;
}

} // namespace

std::string settingLabel(const StudySpec& study, const StudySetting& setting) {
    return seriesLabel(study, setting, -1);
}

int referenceKey(const StudySpec& study) {
    return study.resolutionKey >= 0 ? study.resolutionKey : static_cast<int>(study.keys.size()) - 1;
}

bool runFinished(const std::filesystem::path& dir) {
    const auto summary = readSummary(dir);
    return summary && summary->is_object() && summary->value("finished", false);
}

std::optional<std::string> runUnstable(const std::filesystem::path& dir) {
    const auto summary = readSummary(dir);
    return summary ? stopReason(*summary) : std::nullopt;
}

std::optional<double> readStudyMetric(const StudySpec& study, const StudySetting& setting) {
    return readRow(study, setting).value;
}

std::vector<StudyRow> tabulateStudy(const StudySpec& study) {
    std::vector<StudyRow> rows;
    for (const auto& setting : study.settings)
        rows.push_back(readRow(study, setting));
    if (study.reference == StudyReference::Finest)
        for (std::size_t k = 0; k < rows.size(); ++k)
            if (rows[k].value && rows[finestIndex(study, k)].status == "finished")
                rows[k].reference = rows[finestIndex(study, k)].value;
    for (auto& row : rows) {
        if (!row.value || row.status != "finished") continue;
        if (study.reference == StudyReference::Analytic && study.metric.isError) {
            row.error = std::abs(*row.value);
        } else if (row.reference) {
            const double difference = std::abs(*row.value - *row.reference);
            row.error = *row.reference != 0 ? difference / std::abs(*row.reference) : difference;
        }
    }
    const int axis = study.resolutionKey;
    if (axis < 0) return rows;
    // p = ln(e_prev / e) / ln(N / N_prev) between successive resolutions, the other keys held.
    for (std::size_t k = 0; k < rows.size(); ++k) {
        std::size_t previous = k;
        for (std::size_t j = 0; j < k; ++j)
            if (sameExcept(study.settings[j], study.settings[k], axis)) previous = j;
        if (previous == k) continue;
        const auto n0 = numericValue(study.settings[previous].values[axis]),
                   n1 = numericValue(study.settings[k].values[axis]);
        const auto &e0 = rows[previous].error, &e1 = rows[k].error;
        if (n0 && n1 && e0 && e1 && *e0 > 0 && *e1 > 0 && *n0 > 0 && *n1 > 0 && *n0 != *n1)
            rows[k].order = std::log(*e0 / *e1) / std::log(*n1 / *n0);
    }
    return rows;
}

std::vector<FittedOrder> fittedOrders(const StudySpec& study, const std::vector<StudyRow>& rows) {
    const int axis = study.resolutionKey;
    std::vector<FittedOrder> fits;
    if (axis < 0) return fits;
    std::vector<bool> done(rows.size(), false);
    for (std::size_t first = 0; first < rows.size(); ++first) {
        if (done[first]) continue;
        // Slope of ln e against -ln N by least squares over one series.
        double sx = 0, sy = 0, sxx = 0, sxy = 0, count = 0;
        for (std::size_t k = first; k < rows.size(); ++k) {
            if (!sameExcept(study.settings[k], study.settings[first], axis)) continue;
            done[k] = true;
            const auto n = numericValue(study.settings[k].values[axis]);
            if (!n || *n <= 0 || !rows[k].error || *rows[k].error <= 0) continue;
            const double x = -std::log(*n), y = std::log(*rows[k].error);
            sx += x, sy += y, sxx += x * x, sxy += x * y, count += 1;
        }
        const double denominator = count * sxx - sx * sx;
        if (count >= 2 && denominator > 0)
            fits.push_back({seriesLabel(study, study.settings[first], axis),
                            (count * sxy - sx * sy) / denominator});
    }
    return fits;
}

std::vector<std::string> writeStudyTables(const StudySpec& study, const std::vector<StudyRow>& rows,
                                          const std::filesystem::path& out, bool plotted,
                                          const std::string& plotNote) {
    const std::string& metric = study.metric.name;
    std::string csv, keys;
    for (const auto& key : study.keys)
        csv += key + ",", keys += (keys.empty() ? "" : " × ") + key;
    csv += "status,metric,metric_value,reference,error,wall_s,mlups,observed_order,diagnosis\n";
    std::string md = "# Study of " + study.caseName + " over " + keys + "\n\nMetric `" + metric +
                     "` from each run's summary.json; error: " + describeReference(study, rows) +
                     ".\n\n" + markdownTable(study, rows);
    bool extrapolated = false;
    std::string unstable;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const auto& r = rows[k];
        extrapolated = extrapolated || r.wallExtrapolated;
        for (const auto& value : study.settings[k].values)
            csv += value + ",";
        csv += r.status + "," + metric + "," + number(r.value, "%.9g") + "," +
               number(r.reference, "%.9g") + "," + number(r.error, "%.6g") + "," +
               number(r.wallS, "%.3f") + "," + number(r.mlups, "%.2f") + "," +
               number(r.order, "%.4f") + "," + (r.diagnosis.empty() ? "" : csvQuoted(r.diagnosis)) +
               "\n";
        if (r.status == "unstable") unstable += "- `" + r.setting + "`: " + r.diagnosis + "\n";
    }
    if (study.resolutionKey >= 0) {
        md += "\nOrder: p = ln(e_prev / e) / ln(N / N_prev) between successive settings of " +
              study.keys[study.resolutionKey];
        const auto fits = fittedOrders(study, rows);
        if (fits.size() == 1 && study.keys.size() == 1) {
            md += "; least squares over all settings: " + number(fits.front().order, "%.2f");
        } else if (!fits.empty()) {
            md += "; least squares per series:";
            for (const auto& fit : fits)
                md += " " + fit.series + " " + number(fit.order, "%.2f") + ";";
            md.pop_back();
        }
        md += ".\n";
    }
    if (!unstable.empty())
        md += "\nStopped by the stability guard (the first line of its diagnosis):\n\n" + unstable;
    if (extrapolated)
        md += "\n\\* resumed run: wall time scaled from the steps timed after the resume.\n";
    if (plotted) {
        md += "\n![error of " + metric + " against wall time](study.png)\n";
        if (study.reference == StudyReference::Finest)
            md += "\nThe finest setting, the reference, has no point on the log axes.\n";
    } else if (!plotNote.empty()) {
        md += "\n" + plotNote + "\n";
    }
    io::writeFileAtomically((out / "study.csv").string(), csv);
    io::writeFileAtomically((out / "study.md").string(), md);
    std::vector<std::string> written{(out / "study.csv").string(), (out / "study.md").string()};
    if (plotted) written.push_back((out / "study.png").string());
    return written;
}

StudyReportResult writeStudyReport(const StudySpec& study, const std::filesystem::path& out,
                                   const StudyPlotter& plot) {
    const auto rows = tabulateStudy(study);
    // Over several keys with neither an analytic value nor a resolution key, the "error" is a
    // difference from the last value of a key: tabulated, but not worth a figure.
    const bool noErrorScale = study.keys.size() > 1 && study.resolutionKey < 0 &&
                              study.reference == StudyReference::Finest;
    const bool plotted = plot && !noErrorScale && plot(study, rows, (out / "study.png").string());
    StudyReportResult result;
    if (noErrorScale && plot)
        result.plotNote =
            "The errors are differences from the last value of " + study.keys.back() +
            ", neither an analytic value nor a finer resolution, so study.png is not drawn.";
    else if (plot && !plotted)
        result.plotNote =
            "No setting has a positive error and wall time, so study.png is not drawn.";
    result.files = writeStudyTables(study, rows, out, plotted, result.plotNote);
    if (study.keys.size() > 1) result.files.push_back(writeStudyMap(study, rows, out));
    return result;
}

} // namespace lbdem::campaign
