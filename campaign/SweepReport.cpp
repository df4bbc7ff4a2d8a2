// Sweep table (CSV and Markdown) from the runs' summaries, and the figures' section.
#include "campaign/SweepReport.h"

#include "campaign/SweepFindings.h"
#include "solver/io/CaseWriter.h"
#include "solver/io/TimeSeriesWriter.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace lbdem::campaign {

namespace {

struct Row {
    std::string name, packing, slope, medium, status, error;
    double runout = 0, endReachedTc = std::numeric_limits<double>::quiet_NaN(), kePeak = 0,
           tKePeak = 0, packingFinal = 0, wall = 0, mlups = 0;
    SweepFigureCase figure; ///< what the figures need of this case
};

double numberOr(const nlohmann::json& json, const char* key) {
    const auto found = json.find(key);
    return found != json.end() && found->is_number() ? found->get<double>() : 0.0;
}

} // namespace

double endReachedTc(const SweepEntry& entry) {
    const double limit =
        entry.spec.domain.width_m - entry.spec.grains.size_ratio * entry.spec.grains.d_min_m;
    try {
        const auto series = io::readTimeSeries((entry.dir / "timeseries.csv").string());
        const auto time = series.column("t_over_tc"), front = series.column("runout_m");
        for (std::size_t k = 0; k < std::min(time.size(), front.size()); ++k)
            if (front[k] >= limit) return time[k];
    } catch (const std::runtime_error&) {
    }
    return std::numeric_limits<double>::quiet_NaN();
}

namespace {

Row readRow(const SweepEntry& entry) {
    Row row;
    row.name = entry.dir.filename().string(); // the case, or the case and seed of an ensemble run
    row.packing = number(entry.spec.grains.packing, "%.2f");
    row.slope = number(entry.spec.domain.slope_deg, "%.1f");
    row.medium = entry.spec.fluid.enabled ? "submerged" : "dry";
    row.figure = {entry.spec.name,
                  entry.spec.grains.packing,
                  entry.spec.domain.slope_deg,
                  entry.spec.fluid.enabled,
                  "",
                  0.0,
                  entry.dir};
    std::ifstream file(entry.dir / "summary.json");
    if (!file) {
        // No summary: the run failed before its first output (its log says why) or never ran.
        const bool failed = std::filesystem::exists(entry.dir / "log.txt");
        row.status = row.figure.status = failed ? "failed" : "missing";
        if (failed) row.error = firstErrorLine(entry.dir / "log.txt");
        return row;
    }
    try {
        const auto summary = nlohmann::json::parse(file);
        // A run the stability guard stopped says why in stop_reason: unstable, not unfinished
        // (which a resume would finish), as in the ensemble table.
        row.status = summary.value("finished", false)  ? "finished"
                     : summary.contains("stop_reason") ? "unstable"
                                                       : "unfinished";
        row.runout = numberOr(summary, "runout_final");
        row.kePeak = numberOr(summary, "ke_peak");
        row.tKePeak = numberOr(summary, "t_ke_peak_over_tc");
        row.packingFinal = numberOr(summary, "packing_final");
        row.wall = numberOr(summary, "wall_s");
        row.mlups = numberOr(summary, "mlups");
        row.figure.runout_final = row.runout;
        row.endReachedTc = endReachedTc(entry);
    } catch (const nlohmann::json::exception&) {
        row.status = "unreadable";
    }
    row.figure.status = row.status;
    return row;
}

/// The Markdown section that shows the figures and names what they leave out.
std::string figuresSection(const SweepFiguresResult& figures, const std::filesystem::path& out) {
    std::string md = "\n## Figures\n\n";
    if (!figures.unavailable.empty()) md += "No figures: " + figures.unavailable + ".\n\n";
    for (const auto& file : figures.files) {
        const std::string name = std::filesystem::path(file).lexically_relative(out).string();
        md += "![" + std::filesystem::path(file).stem().string() + "](" + name + ")\n\n";
    }
    if (!figures.skipped.empty()) {
        md += "Not in the figures:";
        for (std::size_t k = 0; k < figures.skipped.size(); ++k)
            md += (k ? ", " : " ") + figures.skipped[k];
        md += ".\n";
    }
    return md;
}

/// The figures of a row for the table; blank (CSV) or a dash (Markdown) when the run left none.
bool hasFigures(const Row& row) {
    return row.status != "missing" && row.status != "failed" && row.status != "unreadable";
}

/// The cases that failed, each with the first error line of its log.
std::string failuresSection(const std::vector<Row>& rows) {
    std::string md;
    for (const auto& r : rows)
        if (r.status == "failed") md += "- " + r.name + ": " + r.error + "\n";
    return md.empty() ? md : "\n## Failed cases\n\n" + md;
}

} // namespace

std::string packingName(double packing) {
    return packing >= 0.81 ? "dense" : "loose";
}

std::string firstErrorLine(const std::filesystem::path& logPath) {
    std::ifstream log(logPath);
    std::string line, first;
    while (std::getline(log, line)) {
        if (first.empty() && !line.empty()) first = line;
        if (line.rfind("lbdem:", 0) == 0) return line.substr(0, 300);
    }
    return first.empty() ? "no error message in " + logPath.string() : first.substr(0, 300);
}

SweepReportResult writeSweepReport(const std::string& name, const std::vector<SweepEntry>& entries,
                                   const std::filesystem::path& out,
                                   const SweepFigureWriter& writeSweepFigures) {
    std::vector<Row> rows;
    for (const auto& entry : entries)
        rows.push_back(readRow(entry));
    std::string csv = "case,packing,slope_deg,medium,status,runout_final,end_reached_tc,ke_peak,"
                      "t_ke_peak_over_tc,packing_final,wall_s,mlups\n";
    const SweepEnsembleReport ensemble = sweepEnsembleReport(entries, out);
    std::string md =
        "# Sweep " + name + "\n\n" + ensemble.markdown +
        "| case | packing | slope (deg) | medium | status | "
        "(L_f - L_i)/L_i | front at the domain's end (t/tau_c) | peak E_k/E_p0 | t_peak/tau_c | "
        "final packing | wall (s) | MLUPS |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& r : rows) {
        const bool reached = std::isfinite(r.endReachedTc);
        if (!hasFigures(r)) {
            csv += r.name + "," + r.packing + "," + r.slope + "," + r.medium + "," + r.status +
                   ",,,,,,,\n";
            md += "| " + r.name + " | " + r.packing + " | " + r.slope + " | " + r.medium + " | " +
                  r.status + " | - | - | - | - | - | - | - |\n";
            continue;
        }
        csv += r.name + "," + r.packing + "," + r.slope + "," + r.medium + "," + r.status + "," +
               number(r.runout, "%.6g") + "," + (reached ? number(r.endReachedTc, "%.6g") : "") +
               "," + number(r.kePeak, "%.6g") + "," + number(r.tKePeak, "%.6g") + "," +
               number(r.packingFinal, "%.6g") + "," + number(r.wall, "%.1f") + "," +
               number(r.mlups, "%.1f") + "\n";
        md += "| " + r.name + " | " + r.packing + " | " + r.slope + " | " + r.medium + " | " +
              r.status + " | " + number(r.runout, "%.3f") + (reached ? " (end)" : "") + " | " +
              (reached ? number(r.endReachedTc, "%.2f") : "never") + " | " +
              number(r.kePeak, "%.4f") + " | " + number(r.tKePeak, "%.2f") + " | " +
              number(r.packingFinal, "%.3f") + " | " + number(r.wall, "%.0f") + " | " +
              number(r.mlups, "%.0f") + " |\n";
    }
    std::vector<SweepFigureCase> figureCases;
    for (const auto& r : rows)
        figureCases.push_back(r.figure);
    const SweepFiguresResult figures = writeSweepFigures(name, figureCases, out);
    md += failuresSection(rows);
    md += figuresSection(figures, out);
    const std::string runsCsv = ensemble.csv.empty() ? "sweep.csv" : "runs.csv";
    io::writeFileAtomically((out / runsCsv).string(), csv);
    io::writeFileAtomically((out / "sweep.md").string(), md);
    SweepReportResult result{{(out / runsCsv).string(), (out / "sweep.md").string()},
                             figures.unavailable};
    result.files.insert(result.files.end(), ensemble.files.begin(), ensemble.files.end());
    result.files.insert(result.files.end(), figures.files.begin(), figures.files.end());
    return result;
}

} // namespace lbdem::campaign
