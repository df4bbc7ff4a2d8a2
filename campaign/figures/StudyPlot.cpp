// Study figure with lbdem::vis line charts (log-log axes, points labelled with the settings).
#include "campaign/figures/StudyPlot.h"

#ifdef LBDEM_HAS_VIS
#include "ui/vis/LineChart.h"

#include <algorithm>
#endif

namespace lbdem::campaign {

bool studyPlotAvailable() {
#ifdef LBDEM_HAS_VIS
    return true;
#else
    return false;
#endif
}

bool writeStudyPlot(const StudySpec& study, const std::vector<StudyRow>& rows,
                    const std::string& path) {
#ifdef LBDEM_HAS_VIS
    // One series for a one-key study; otherwise one per value of the first key, its points
    // labelled with the other keys' values.
    const bool multi = study.keys.size() > 1;
    std::vector<vis::ChartSeries> series;
    std::size_t points = 0;
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const auto& values = study.settings[k].values;
        const std::string name = multi ? study.keys[0] + "=" + values[0] : study.keys[0];
        if (series.empty() || series.back().name != name)
            series.push_back(vis::ChartSeries{name, {}, {}, true, static_cast<int>(series.size())});
        const auto& row = rows[k];
        if (!row.error || *row.error <= 0 || row.wallS <= 0) continue; // a log axis has no 0
        std::string label = multi ? "" : row.setting;
        for (std::size_t key = 1; key < values.size(); ++key)
            label += (key > 1 ? "," : "") + study.keys[key] + "=" + values[key];
        series.back().x.push_back(row.wallS);
        series.back().y.push_back(*row.error);
        series.back().labels.push_back(label);
        ++points;
    }
    if (points == 0) return false;
    series.erase(std::remove_if(series.begin(), series.end(),
                                [](const vis::ChartSeries& s) { return s.x.empty(); }),
                 series.end());
    vis::ChartSpec spec;
    const bool isError = study.reference == StudyReference::Analytic && study.metric.isError;
    spec.yTitle = isError ? study.metric.name : "relative error of " + study.metric.name;
    spec.title = study.caseName + ": " + spec.yTitle + " against wall time";
    spec.xTitle = "wall time [s]";
    spec.series = std::move(series);
    spec.legend = multi;
    spec.logX = spec.logY = true;
    vis::renderLineChart(spec, path, 900, 600);
    return true;
#else
    (void)study;
    (void)rows;
    (void)path;
    return false;
#endif
}

} // namespace lbdem::campaign
