// Sweep figures from each case's timeseries.csv, drawn with the vis line charts.
#include "campaign/figures/SweepFigures.h"

#include "campaign/EnsembleBand.h"
#include "campaign/SweepEnsemble.h"
#include "solver/io/TimeSeriesWriter.h"

#ifdef LBDEM_HAS_VIS
#include "ui/vis/LineChart.h"
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <set>
#include <tuple>

namespace lbdem::campaign {

#ifdef LBDEM_HAS_VIS
namespace {

constexpr int kWidth = 900, kHeight = 600;

/// One finished case with its time series: one run, or the finished runs of an ensemble (one
/// per packing seed) drawn as their mean and a band.
struct CaseCurves {
    const SweepFigureCase* run =
        nullptr; ///< the first run (what the runs share: packing, slope, medium)
    std::vector<io::TimeSeriesTable> tables;
    std::vector<double> runouts; ///< each run's final runout
};

/// One number formatted with a printf pattern.
std::string format(const char* pattern, double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, pattern, value);
    return buffer;
}

/// A slope as legends show it, e.g. "2.5 deg".
std::string slopeText(double slopeDeg) {
    return format("%g deg", slopeDeg);
}

/// The curve y(t/tau_c) of one column of a case, rows with a missing value left out; for an
/// ensemble the mean over its runs with the min-max band, at the first run's times that every
/// run covers.
vis::ChartSeries curve(const CaseCurves& c, const std::string& column, std::string name) {
    vis::ChartSeries series;
    series.name = std::move(name);
    const EnsembleBand band = ensembleBand(c.tables, column);
    series.x = band.t_over_tc, series.y = band.mean;
    if (c.tables.size() > 1) series.low = band.min, series.high = band.max;
    return series;
}

/// The legend entry of the bands when some case has several runs, e.g. "shaded: min-max of 3
/// seeds, line: mean"; empty otherwise.
std::string bandLegend(const std::vector<CaseCurves>& cases) {
    std::size_t fewest = 1000000, most = 0;
    for (const auto& c : cases)
        fewest = std::min(fewest, c.tables.size()), most = std::max(most, c.tables.size());
    if (most < 2) return "";
    const std::string count =
        fewest == most ? std::to_string(most) : std::to_string(fewest) + "-" + std::to_string(most);
    return "shaded: min-max of " + count + " seeds, line: mean";
}

/// Names the band of the first series that has one in the legend.
void nameFirstBand(std::vector<vis::ChartSeries>& series, const std::string& legend) {
    for (auto& s : series)
        if (!s.low.empty()) {
            s.bandName = legend;
            return;
        }
}

/// Figure labels of the packings present: "dense", "loose", or with the value when two
/// packings would share a name. Keyed by the packing rounded to two decimals.
std::map<std::string, std::string> packingLabels(const std::vector<CaseCurves>& cases) {
    std::map<std::string, std::string> labels;
    std::map<std::string, int> uses;
    for (const auto& c : cases)
        labels[format("%.2f", c.run->packing)] = packingName(c.run->packing);
    for (const auto& [key, label] : labels)
        ++uses[label];
    for (auto& [key, label] : labels)
        if (uses[label] > 1) {
            std::string digits = key;
            std::replace(digits.begin(), digits.end(), '.', 'p');
            label += "_" + digits;
        }
    return labels;
}

/// Palette index of each slope present, in increasing slope.
std::map<double, int> slopeColours(const std::vector<CaseCurves>& cases) {
    std::set<double> slopes;
    for (const auto& c : cases)
        slopes.insert(c.run->slope_deg);
    std::map<double, int> colours;
    for (const double slope : slopes)
        colours.emplace(slope, static_cast<int>(colours.size()));
    return colours;
}

/// Renders a chart into out/file, leaving out curves without points (a case that lacks the
/// column) and charts with no curve at all; appends the file to result.
void draw(vis::ChartSpec spec, const std::filesystem::path& out, const std::string& file,
          SweepFiguresResult& result) {
    spec.series.erase(std::remove_if(spec.series.begin(), spec.series.end(),
                                     [](const vis::ChartSeries& s) { return s.x.empty(); }),
                      spec.series.end());
    if (spec.series.empty()) return;
    vis::renderLineChart(spec, (out / file).string(), kWidth, kHeight);
    result.files.push_back((out / file).string());
}

/// The variant of a case of a sweep with variants (its name after "__"); empty otherwise.
std::string variantOf(const SweepFigureCase& run) {
    const auto cut = run.name.rfind("__");
    return cut == std::string::npos ? std::string() : run.name.substr(cut + 2);
}

/// Runout and E_k/E_p0 against t/tau_c for the cases of one packing: one colour per slope, or in
/// a sweep with variants one colour and legend entry per variant.
void drawPackingFigures(const std::string& sweepName, const std::string& packing,
                        const std::string& label, const std::vector<const CaseCurves*>& cases,
                        const std::map<double, int>& colours, const std::string& band,
                        const std::filesystem::path& out, SweepFiguresResult& result) {
    std::vector<vis::ChartSeries> runout, energy;
    std::map<std::string, int> variantColours; // in the order the variants come
    for (const auto* c : cases) {
        const std::string variant = variantOf(*c->run);
        const auto [at, fresh] =
            variantColours.emplace(variant, static_cast<int>(variantColours.size()));
        (void)fresh;
        const std::string name = std::string(c->run->submerged ? "submerged" : "dry") + ", " +
                                 slopeText(c->run->slope_deg) +
                                 (variant.empty() ? "" : ", " + variant);
        for (auto [series, column] :
             {std::pair{&runout, "runout_normalised"}, std::pair{&energy, "ke_over_ep0"}}) {
            series->push_back(curve(*c, column, name));
            series->back().colour = variant.empty() ? colours.at(c->run->slope_deg) : at->second;
            // Dashed marks the submerged cases; with variants it marks the ninth colour on, as
            // the palette's eight colours come round again.
            const bool dashed = variant.empty() ? c->run->submerged : at->second >= 8;
            series->back().style = dashed ? vis::LineStyle::Dashed : vis::LineStyle::Solid;
        }
    }
    nameFirstBand(runout, band);
    nameFirstBand(energy, band);
    const std::string title = ", " + packingName(std::stod(packing)) + " packing (" + packing + ")";
    auto runoutSpec =
        vis::timeSeriesChart(sweepName + ": runout" + title, "(L - L_i) / L_i", runout);
    runoutSpec.legendAtLeft = true; // runout grows with time: the top-left corner stays free
    draw(runoutSpec, out, "runout_" + label + ".png", result);
    draw(vis::timeSeriesChart(sweepName + ": kinetic energy" + title, "E_k / E_p0", energy), out,
         "energy_" + label + ".png", result);
}

/// Final runout against slope, one series per packing (densest first, colour) and medium (style);
/// an ensemble's mean with its min-max band.
void drawRunoutVsSlope(const std::string& sweepName, const std::vector<CaseCurves>& cases,
                       const std::map<std::string, std::string>& labels, const std::string& band,
                       const std::filesystem::path& out, SweepFiguresResult& result) {
    std::map<std::pair<std::string, bool>, std::map<double, Spread>>
        points; // (packing, wet) -> slope -> runout over the runs
    for (const auto& c : cases)
        if (const Spread runout = spreadOf(c.runouts); runout.count > 0)
            points[{format("%.2f", c.run->packing), c.run->submerged}][c.run->slope_deg] = runout;
    std::vector<vis::ChartSeries> series;
    int colour = 0;
    for (auto it = labels.rbegin(); it != labels.rend(); ++it, ++colour)
        for (const bool submerged : {false, true}) {
            const auto found = points.find({it->first, submerged});
            if (found == points.end()) continue;
            vis::ChartSeries s;
            s.name = it->second + ", " + (submerged ? "submerged" : "dry");
            bool spread = false;
            for (const auto& [slope, runout] : found->second)
                spread = spread || runout.count > 1;
            for (const auto& [slope, runout] : found->second) {
                s.x.push_back(slope), s.y.push_back(runout.mean);
                if (spread) s.low.push_back(runout.min), s.high.push_back(runout.max);
            }
            s.colour = colour;
            s.style = submerged ? vis::LineStyle::Dashed : vis::LineStyle::Solid;
            series.push_back(std::move(s));
        }
    nameFirstBand(series, band);
    auto spec = vis::runoutVsSlopeChart(std::move(series), "final runout (L_f - L_i) / L_i");
    spec.title = sweepName + ": " + spec.title;
    spec.legendAtLeft = true;
    draw(spec, out, "runout_vs_slope.png", result);
}

/// Densimetric Froude number of the submerged cases against t/tau_c, with Fr = 0.4.
void drawFroude(const std::string& sweepName, const std::vector<CaseCurves>& cases,
                const std::map<std::string, std::string>& labels,
                const std::map<double, int>& colours, const std::string& band,
                const std::filesystem::path& out, SweepFiguresResult& result) {
    const vis::LineStyle styles[] = {vis::LineStyle::Solid, vis::LineStyle::Dashed,
                                     vis::LineStyle::Dotted, vis::LineStyle::DashDotted};
    std::map<std::string, std::size_t> packingStyle; // densest solid, then dashed ...
    for (auto it = labels.rbegin(); it != labels.rend(); ++it)
        packingStyle.emplace(it->first, packingStyle.size() % 4);
    std::vector<vis::ChartSeries> series;
    for (const auto& c : cases) {
        if (!c.run->submerged) continue;
        const std::string key = format("%.2f", c.run->packing);
        series.push_back(
            curve(c, "froude_densimetric", labels.at(key) + ", " + slopeText(c.run->slope_deg)));
        series.back().colour = colours.at(c.run->slope_deg);
        series.back().style = styles[packingStyle.at(key)];
    }
    nameFirstBand(series, band);
    auto spec = vis::froudeChart(std::move(series));
    spec.title = sweepName + ": " + spec.title;
    draw(spec, out, "froude.png", result);
}

} // namespace
#endif

SweepFiguresResult writeSweepFigures(const std::string& sweepName,
                                     const std::vector<SweepFigureCase>& cases,
                                     const std::filesystem::path& out) {
    SweepFiguresResult result;
#ifdef LBDEM_HAS_VIS
    std::vector<CaseCurves> curves; // the runs of one case (its packing seeds) together
    for (const auto& run : cases) {
        const std::string folder =
            run.dir.filename().string(); // the case, or the case and its seed
        if (run.status != "finished") {
            result.skipped.push_back(folder + " (" + run.status + ")");
            continue;
        }
        try {
            auto table = io::readTimeSeries((run.dir / "timeseries.csv").string());
            auto same = std::find_if(curves.begin(), curves.end(),
                                     [&](const CaseCurves& c) { return c.run->name == run.name; });
            if (same == curves.end()) same = curves.insert(curves.end(), CaseCurves{&run, {}, {}});
            same->tables.push_back(std::move(table));
            same->runouts.push_back(run.runout_final);
        } catch (const std::exception&) {
            result.skipped.push_back(folder + " (no readable timeseries.csv)");
        }
    }
    if (curves.empty()) {
        result.unavailable = "no finished case with a timeseries.csv to draw";
        return result;
    }
    const auto labels = packingLabels(curves);
    const auto colours = slopeColours(curves);
    const std::string band = bandLegend(curves);
    // Sorted by slope, dry before submerged, so that legends read in order.
    std::sort(curves.begin(), curves.end(), [](const CaseCurves& a, const CaseCurves& b) {
        return std::tie(a.run->slope_deg, a.run->submerged) <
               std::tie(b.run->slope_deg, b.run->submerged);
    });
    try {
        for (auto it = labels.rbegin(); it != labels.rend(); ++it) { // densest first
            std::vector<const CaseCurves*> ofPacking;
            for (const auto& c : curves)
                if (format("%.2f", c.run->packing) == it->first) ofPacking.push_back(&c);
            drawPackingFigures(sweepName, it->first, it->second, ofPacking, colours, band, out,
                               result);
        }
        drawRunoutVsSlope(sweepName, curves, labels, band, out, result);
        drawFroude(sweepName, curves, labels, colours, band, out, result);
    } catch (const std::exception& error) {
        result.unavailable = std::string("drawing the figures failed: ") + error.what();
    }
#else
    (void)sweepName, (void)cases, (void)out;
    result.unavailable = "this build has no VTK (configure with LBDEM_GUI=ON to draw the figures)";
#endif
    return result;
}

} // namespace lbdem::campaign
