// vtkChartXY in a vtkContextView with an off-screen window, grabbed into a PNG.
#include "ui/vis/LineChart.h"

#include "ui/vis/ColorMaps.h"
#include "ui/vis/HeadlessDisplay.h"
#include "ui/vis/OffscreenRenderer.h"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace lbdem::vis {

namespace {

// Tableau-10 colours, distinguishable and colour-blind tolerant.
constexpr unsigned char kPalette[][3] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {214, 39, 40},
                                         {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {127, 127, 127}};

/// A two-column table (x, y) for one curve.
vtkSmartPointer<vtkTable> curveTable(const std::string& name, const std::vector<double>& x,
                                     const std::vector<double>& y) {
    vtkNew<vtkDoubleArray> xs, ys;
    xs->SetName("x");
    ys->SetName(name.empty() ? "y" : name.c_str());
    for (std::size_t k = 0; k < x.size(); ++k) {
        xs->InsertNextValue(x[k]);
        ys->InsertNextValue(y[k]);
    }
    auto table = vtkSmartPointer<vtkTable>::New();
    table->AddColumn(xs);
    table->AddColumn(ys);
    return table;
}

/// Adds one line plot of `table` to `chart` in palette colour `index`.
vtkPlot* addLine(vtkChartXY* chart, vtkTable* table, std::size_t index, float width) {
    vtkPlot* plot = chart->AddPlot(vtkChart::LINE);
    plot->SetInputData(table, 0, 1);
    const auto* rgb = kPalette[index % (sizeof kPalette / sizeof kPalette[0])];
    plot->SetColor(rgb[0], rgb[1], rgb[2], 255);
    plot->SetWidth(width);
    return plot;
}

/// The x and y ranges covered by all series.
void dataRange(const ChartSpec& spec, double range[4]) {
    range[0] = range[2] = INFINITY;
    range[1] = range[3] = -INFINITY;
    for (const auto& s : spec.series)
        for (std::size_t k = 0; k < s.x.size(); ++k) {
            range[0] = std::min(range[0], s.x[k]), range[1] = std::max(range[1], s.x[k]);
            range[2] = std::min(range[2], s.y[k]), range[3] = std::max(range[3], s.y[k]);
        }
    for (const auto& r : spec.references) {
        const int axis = r.horizontal ? 2 : 0;
        range[axis] = std::min(range[axis], r.value), range[axis + 1] = std::max(range[axis + 1], r.value);
    }
}

/// Adds the series and reference lines of `spec` to `chart`.
void addPlots(const ChartSpec& spec, vtkChartXY* chart) {
    double range[4];
    dataRange(spec, range);
    for (std::size_t k = 0; k < spec.series.size(); ++k) {
        const auto& s = spec.series[k];
        vtkPlot* plot = addLine(chart, curveTable(s.name, s.x, s.y), k, 2.0f);
        if (auto* points = vtkPlotPoints::SafeDownCast(plot); points && s.markers)
            points->SetMarkerStyle(vtkPlotPoints::CIRCLE);
    }
    for (const auto& r : spec.references) {
        const std::vector<double> xs = r.horizontal ? std::vector<double>{range[0], range[1]} : std::vector<double>{r.value, r.value};
        const std::vector<double> ys = r.horizontal ? std::vector<double>{r.value, r.value} : std::vector<double>{range[2], range[3]};
        vtkPlot* plot = chart->AddPlot(vtkChart::LINE);
        plot->SetInputData(curveTable(r.name, xs, ys), 0, 1);
        plot->SetColor(0, 0, 0, 200);
        plot->SetWidth(1.5f);
        plot->GetPen()->SetLineType(vtkPen::DASH_LINE);
    }
}

/// Fixed axis ranges with a margin, so end points and markers are not cut by the frame and the
/// top-right legend does not cover the highest curve; a range that starts at 0 keeps 0.
void fitAxes(const ChartSpec& spec, vtkChartXY* chart) {
    double range[4];
    dataRange(spec, range);
    bool markers = false;
    for (const auto& s : spec.series) markers = markers || s.markers;
    const double dx = std::max(range[1] - range[0], 1e-12), dy = std::max(range[3] - range[2], 1e-12);
    const double x0 = markers ? range[0] - 0.04 * dx : range[0], x1 = markers ? range[1] + 0.04 * dx : range[1];
    const double y0 = range[2] == 0 ? 0.0 : range[2] - 0.05 * dy, y1 = range[3] + 0.2 * dy;
    for (const auto& [axis, low, high] : {std::tuple{vtkAxis::BOTTOM, x0, x1}, std::tuple{vtkAxis::LEFT, y0, y1}}) {
        chart->GetAxis(axis)->SetBehavior(vtkAxis::FIXED);
        chart->GetAxis(axis)->SetRange(low, high);
    }
}

} // namespace

void renderLineChart(const ChartSpec& spec, const std::string& path, int width, int height) {
    std::size_t points = 0;
    for (const auto& s : spec.series) {
        if (s.x.size() != s.y.size())
            throw std::invalid_argument("chart series '" + s.name + "' has " + std::to_string(s.x.size()) +
                                        " x values but " + std::to_string(s.y.size()) + " y values");
        points += s.x.size();
    }
    if (points == 0) throw std::invalid_argument("chart '" + spec.title + "' has no points");
    ensureDisplay();
    vtkNew<vtkContextView> view;
    view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
    view->GetRenderWindow()->SetOffScreenRendering(1);
    view->GetRenderWindow()->SetMultiSamples(0);
    view->GetRenderWindow()->SetSize(width, height);
    vtkNew<vtkChartXY> chart;
    view->GetScene()->AddItem(chart);
    chart->SetTitle(spec.title);
    chart->GetTitleProperties()->SetFontSize(14);
    // Titles may carry Greek (t/τc): use the Unicode font when installed, else ASCII.
    std::string xTitle = spec.xTitle;
    if (!useUnicodeFont(chart->GetAxis(vtkAxis::BOTTOM)->GetTitleProperties()) ||
        !useUnicodeFont(chart->GetAxis(vtkAxis::LEFT)->GetTitleProperties()) ||
        !useUnicodeFont(chart->GetTitleProperties())) {
        const std::string unicode = timeOverTcSymbol(true);
        for (auto at = xTitle.find(unicode); at != std::string::npos; at = xTitle.find(unicode))
            xTitle.replace(at, unicode.size(), timeOverTcSymbol(false));
    }
    chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(xTitle);
    chart->GetAxis(vtkAxis::LEFT)->SetTitle(spec.yTitle);
    chart->SetShowLegend(spec.legend);
    chart->GetLegend()->SetInline(true);
    chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
    chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
    addPlots(spec, chart);
    fitAxes(spec, chart);
    view->GetRenderWindow()->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(view->GetRenderWindow());
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->Update();
    writePng(grab->GetOutput(), path);
    view->GetRenderWindow()->Finalize();
}

ChartSpec timeSeriesChart(const std::string& title, const std::string& yTitle,
                          std::vector<ChartSeries> series) {
    ChartSpec spec;
    spec.title = title;
    spec.xTitle = timeOverTcSymbol(true);
    spec.yTitle = yTitle;
    spec.series = std::move(series);
    return spec;
}

ChartSpec froudeChart(std::vector<ChartSeries> series) {
    ChartSpec spec = timeSeriesChart("Froude number at the front", "Fr", std::move(series));
    // Hydroplaning sets in above Fr of about 0.3-0.4 (Mohrig et al. 1998, GSA Bulletin 110).
    spec.references.push_back({"Fr = 0.4", 0.4, true});
    return spec;
}

ChartSpec runoutVsSlopeChart(std::vector<ChartSeries> series) {
    ChartSpec spec;
    spec.title = "Final runout against slope";
    spec.xTitle = "slope [deg]";
    spec.yTitle = "final runout [m]";
    for (auto& s : series) s.markers = true;
    spec.series = std::move(series);
    return spec;
}

} // namespace lbdem::vis
