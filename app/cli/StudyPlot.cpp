// Study figure with lbdem::vis line charts (log-log axes, points labelled with the settings).
#include "app/cli/StudyPlot.h"

#ifdef LBDEM_HAS_VIS
#include "ui/vis/LineChart.h"
#endif

namespace lbdem::cli {

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
    vis::ChartSeries series{study.key, {}, {}, true};
    for (const auto& row : rows) {
        if (!row.error || *row.error <= 0 || row.wallS <= 0) continue; // a log axis has no 0
        series.x.push_back(row.wallS);
        series.y.push_back(*row.error);
        series.labels.push_back(row.setting);
    }
    if (series.x.empty()) return false;
    vis::ChartSpec spec;
    const bool isError = study.reference == StudyReference::Analytic && study.metric.isError;
    spec.yTitle = isError ? study.metric.name : "relative error of " + study.metric.name;
    spec.title = study.caseName + ": " + spec.yTitle + " against wall time";
    spec.xTitle = "wall time [s]";
    spec.series.push_back(std::move(series));
    spec.legend = false;
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

} // namespace lbdem::cli
