// Study table (CSV and Markdown) from the runs' summaries.
#include "app/cli/StudyReport.h"

#include "solver/io/CaseWriter.h"
#include "solver/scene/SceneMetrics.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace lbdem::cli {

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

std::optional<double> numericValue(const std::string& text) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(value)) return std::nullopt;
    return value;
}

/// The row whose metric is the reference of --reference finest.
std::size_t finestIndex(const StudySpec& study) {
    std::size_t finest = study.settings.size() - 1;
    if (!study.resolution) return finest;
    for (std::size_t k = 0; k < study.settings.size(); ++k)
        if (numericValue(study.settings[k].value).value_or(-1e300) >
            numericValue(study.settings[finest].value).value_or(-1e300))
            finest = k;
    return finest;
}

StudyRow readRow(const StudySpec& study, const StudySetting& setting) {
    StudyRow row;
    row.setting = study.key + "=" + setting.value;
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
    row.value = numberIn(*summary, study.metric.name);
    if (!row.value) row.status = "no metric";
    row.wallS = numberIn(*summary, "wall_s").value_or(0);
    row.mlups = numberIn(*summary, "mlups").value_or(0);
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

std::string describeReference(const StudySpec& study, const std::vector<StudyRow>& rows) {
    const std::string& metric = study.metric.name;
    if (study.reference == StudyReference::Finest)
        return "relative error against the finest setting, " + rows[finestIndex(study)].setting;
    if (study.metric.isError)
        return "the metric is itself the error against the analytic or published answer";
    return "relative error against the analytic or published value the run reports (" + metric +
           solver::kReferenceSuffix + ")";
}

} // namespace

bool runFinished(const std::filesystem::path& dir) {
    const auto summary = readSummary(dir);
    return summary && summary->is_object() && summary->value("finished", false);
}

std::optional<double> readStudyMetric(const StudySpec& study, const StudySetting& setting) {
    return readRow(study, setting).value;
}

std::vector<StudyRow> tabulateStudy(const StudySpec& study) {
    std::vector<StudyRow> rows;
    for (const auto& setting : study.settings)
        rows.push_back(readRow(study, setting));
    if (study.reference == StudyReference::Finest)
        for (auto& row : rows)
            row.reference = rows[finestIndex(study)].value;
    for (auto& row : rows) {
        if (!row.value) continue;
        if (study.reference == StudyReference::Analytic && study.metric.isError) {
            row.error = std::abs(*row.value);
        } else if (row.reference) {
            const double difference = std::abs(*row.value - *row.reference);
            row.error = *row.reference != 0 ? difference / std::abs(*row.reference) : difference;
        }
    }
    if (!study.resolution) return rows;
    // p = ln(e_prev / e) / ln(N / N_prev) between successive settings as given.
    for (std::size_t k = 1; k < rows.size(); ++k) {
        const auto n0 = numericValue(study.settings[k - 1].value),
                   n1 = numericValue(study.settings[k].value);
        const auto &e0 = rows[k - 1].error, &e1 = rows[k].error;
        if (n0 && n1 && e0 && e1 && *e0 > 0 && *e1 > 0 && *n0 > 0 && *n1 > 0 && *n0 != *n1)
            rows[k].order = std::log(*e0 / *e1) / std::log(*n1 / *n0);
    }
    return rows;
}

std::optional<double> fittedOrder(const StudySpec& study, const std::vector<StudyRow>& rows) {
    // Slope of ln e against -ln N by least squares.
    double sx = 0, sy = 0, sxx = 0, sxy = 0, count = 0;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const auto n = numericValue(study.settings[k].value);
        if (!study.resolution || !n || *n <= 0 || !rows[k].error || *rows[k].error <= 0) continue;
        const double x = -std::log(*n), y = std::log(*rows[k].error);
        sx += x, sy += y, sxx += x * x, sxy += x * y, count += 1;
    }
    const double denominator = count * sxx - sx * sx;
    if (count < 2 || denominator <= 0) return std::nullopt;
    return (count * sxy - sx * sy) / denominator;
}

std::vector<std::string> writeStudyTables(const StudySpec& study, const std::vector<StudyRow>& rows,
                                          const std::filesystem::path& out, bool plotted) {
    const std::string& metric = study.metric.name;
    std::string csv =
        "setting,key,value,status,metric,metric_value,reference,error,wall_s,mlups,observed_order\n";
    std::string md =
        "# Study of " + study.caseName + " over " + study.key + "\n\nMetric `" + metric +
        "` from each run's summary.json; error: " + describeReference(study, rows) + ".\n\n";
    md += "| setting | status | " + metric + " | reference | error | wall (s) | MLUPS |" +
          (study.resolution ? " order |\n" : "\n");
    md += std::string("|---|---|---|---|---|---|---|") + (study.resolution ? "---|\n" : "\n");
    bool extrapolated = false;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const auto& r = rows[k];
        extrapolated = extrapolated || r.wallExtrapolated;
        csv += r.setting + "," + study.key + "," + study.settings[k].value + "," + r.status + "," +
               metric + "," + number(r.value, "%.9g") + "," + number(r.reference, "%.9g") + "," +
               number(r.error, "%.6g") + "," + number(r.wallS, "%.3f") + "," +
               number(r.mlups, "%.2f") + "," + number(r.order, "%.4f") + "\n";
        md += "| " + r.setting + " | " + r.status + " | " + number(r.value, "%.6g") + " | " +
              (study.metric.isError && study.reference == StudyReference::Analytic
                   ? "0"
                   : number(r.reference, "%.6g")) +
              " | " + number(r.error, "%.3g") + " | " + number(r.wallS, "%.3g") +
              (r.wallExtrapolated ? "*" : "") + " | " + number(r.mlups, "%.1f") + " |" +
              (study.resolution ? " " + number(r.order, "%.2f") + " |\n" : "\n");
    }
    if (study.resolution) {
        md += "\nOrder: p = ln(e_prev / e) / ln(N / N_prev) between successive settings";
        if (const auto p = fittedOrder(study, rows))
            md += "; least squares over all settings: " + number(p, "%.2f");
        md += ".\n";
    }
    if (extrapolated)
        md += "\n\\* resumed run: wall time scaled from the steps timed after the resume.\n";
    if (plotted) {
        md += "\n![error of " + metric + " against wall time](study.png)\n";
        if (study.reference == StudyReference::Finest)
            md += "\nThe finest setting, the reference, has no point on the log axes.\n";
    }
    io::writeFileAtomically((out / "study.csv").string(), csv);
    io::writeFileAtomically((out / "study.md").string(), md);
    std::vector<std::string> written{(out / "study.csv").string(), (out / "study.md").string()};
    if (plotted) written.push_back((out / "study.png").string());
    return written;
}

} // namespace lbdem::cli
