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
#include <vtkPlotArea.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace lbdem::vis {

namespace {

// Tableau-10 colours, distinguishable and colour-blind tolerant.
constexpr unsigned char kPalette[][3] = {{31, 119, 180},  {255, 127, 14},  {44, 160, 44},
                                         {214, 39, 40},   {148, 103, 189}, {140, 86, 75},
                                         {227, 119, 194}, {127, 127, 127}};

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

/// The vtkPen line type of a line style.
int penLineType(LineStyle style) {
    switch (style) {
    case LineStyle::Dashed:
        return vtkPen::DASH_LINE;
    case LineStyle::Dotted:
        return vtkPen::DOT_LINE;
    case LineStyle::DashDotted:
        return vtkPen::DASH_DOT_LINE;
    case LineStyle::Solid:
        break;
    }
    return vtkPen::SOLID_LINE;
}

/// Adds one plot of `table` to `chart` in palette colour `index` and the given style: a line, or
/// a point (vtkChart::POINTS) when the table has one row, as VTK cannot draw a one-point line.
vtkPlot* addLine(vtkChartXY* chart, vtkTable* table, std::size_t index, float width,
                 LineStyle style) {
    vtkPlot* plot =
        chart->AddPlot(table->GetNumberOfRows() < 2 ? vtkChart::POINTS : vtkChart::LINE);
    plot->SetInputData(table, 0, 1);
    const auto* rgb = kPalette[index % (sizeof kPalette / sizeof kPalette[0])];
    plot->SetColor(rgb[0], rgb[1], rgb[2], 255);
    plot->SetWidth(width);
    if (style != LineStyle::Solid) plot->GetPen()->SetLineType(penLineType(style));
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
            if (k < s.low.size())
                range[2] = std::min(range[2], s.low[k]), range[3] = std::max(range[3], s.high[k]);
        }
    for (const auto& r : spec.references) {
        const int axis = r.horizontal ? 2 : 0;
        range[axis] = std::min(range[axis], r.value),
        range[axis + 1] = std::max(range[axis + 1], r.value);
    }
}

/// Adds the shaded band of series `s` to `chart` in palette colour `index`, translucent.
void addBand(vtkChartXY* chart, const ChartSeries& s, std::size_t index) {
    vtkNew<vtkDoubleArray> xs, lows, highs;
    xs->SetName("x");
    lows->SetName("low");
    highs->SetName(s.bandName.empty() ? "high" : s.bandName.c_str());
    // Straight between the points, sampled 8 times per interval: VTK leaves a band of two points
    // (a sweep of two slopes) unpainted.
    constexpr int kSamples = 8;
    for (std::size_t k = 0; k < s.x.size(); ++k)
        for (int j = 0; j < (k + 1 < s.x.size() ? kSamples : 1); ++j) {
            const std::size_t next = std::min(k + 1, s.x.size() - 1);
            const double f = static_cast<double>(j) / kSamples;
            xs->InsertNextValue(s.x[k] + f * (s.x[next] - s.x[k]));
            lows->InsertNextValue(s.low[k] + f * (s.low[next] - s.low[k]));
            highs->InsertNextValue(s.high[k] + f * (s.high[next] - s.high[k]));
        }
    vtkNew<vtkTable> table;
    table->AddColumn(xs);
    table->AddColumn(lows);
    table->AddColumn(highs);
    auto* area = vtkPlotArea::SafeDownCast(chart->AddPlot(vtkChart::AREA));
    area->SetInputData(table);
    area->SetInputArray(0, "x");
    area->SetInputArray(1, "low");
    area->SetInputArray(2, highs->GetName());
    area->SetLabel(s.bandName);
    const auto* rgb = kPalette[index % (sizeof kPalette / sizeof kPalette[0])];
    area->SetColor(rgb[0], rgb[1], rgb[2], 60);
    area->SetLegendVisibility(!s.bandName.empty());
}

/// Adds the series (bands first, behind every line) and reference lines of `spec` to `chart`.
void addPlots(const ChartSpec& spec, vtkChartXY* chart) {
    double range[4];
    dataRange(spec, range);
    for (std::size_t k = 0; k < spec.series.size(); ++k)
        if (!spec.series[k].low.empty())
            addBand(chart, spec.series[k],
                    spec.series[k].colour >= 0 ? static_cast<std::size_t>(spec.series[k].colour)
                                               : k);
    for (std::size_t k = 0; k < spec.series.size(); ++k) {
        const auto& s = spec.series[k];
        const std::size_t colour = s.colour >= 0 ? static_cast<std::size_t>(s.colour) : k;
        vtkPlot* plot = addLine(chart, curveTable(s.name, s.x, s.y), colour, 2.0f, s.style);
        // Markers differ with the line style too, so that styles stay apart where no line is drawn.
        const int markers[] = {vtkPlotPoints::CIRCLE, vtkPlotPoints::SQUARE, vtkPlotPoints::DIAMOND,
                               vtkPlotPoints::CROSS};
        if (auto* points = vtkPlotPoints::SafeDownCast(plot);
            points && (s.markers || s.x.size() < 2))
            points->SetMarkerStyle(markers[static_cast<int>(s.style)]);
    }
    for (const auto& r : spec.references) {
        const std::vector<double> xs = r.horizontal ? std::vector<double>{range[0], range[1]}
                                                    : std::vector<double>{r.value, r.value};
        const std::vector<double> ys = r.horizontal ? std::vector<double>{r.value, r.value}
                                                    : std::vector<double>{range[2], range[3]};
        vtkPlot* plot = chart->AddPlot(vtkChart::LINE);
        plot->SetInputData(curveTable(r.name, xs, ys), 0, 1);
        plot->SetColor(0, 0, 0, 200);
        plot->SetWidth(1.5f);
        plot->GetPen()->SetLineType(vtkPen::DASH_LINE);
    }
}

/// A logarithmic axis over [low, high] (both positive), with margins below and above given as
/// fractions of the decades spanned (at least half a decade, so that one point still shows).
void setLogRange(vtkAxis* axis, double low, double high, double below, double above) {
    const double decades = std::max(std::log10(high / low), 0.5);
    axis->SetLogScale(true);
    axis->SetBehavior(vtkAxis::FIXED);
    axis->SetUnscaledRange(low * std::pow(10.0, -below * decades),
                           high * std::pow(10.0, above * decades));
}

/// Fixed axis ranges with a margin, so end points and markers are not cut by the frame and the
/// legend at the top does not cover the highest curve; a range that starts at 0 keeps 0.
void fitAxes(const ChartSpec& spec, vtkChartXY* chart) {
    double range[4];
    dataRange(spec, range);
    bool markers = false;
    for (const auto& s : spec.series)
        markers = markers || s.markers;
    const double dy = std::max(range[3] - range[2], 1e-12);
    // A single x value (e.g. a sweep of one slope) still gets an axis: 10 % or 0.5 either side.
    const double xPad = range[1] > range[0] ? (markers ? 0.04 * (range[1] - range[0]) : 0.0)
                                            : std::max(0.1 * std::abs(range[0]), 0.5);
    const double x0 = range[0] - xPad, x1 = range[1] + xPad;
    // Head room for the legend: 20 % of the range, more when it lists many curves.
    const std::size_t entries = spec.legend ? spec.series.size() + spec.references.size() : 0;
    const double headRoom = std::max(0.2, 0.045 * static_cast<double>(entries));
    const double y0 = range[2] == 0 ? 0.0 : range[2] - 0.05 * dy, y1 = range[3] + headRoom * dy;
    for (const auto& [axis, low, high] :
         {std::tuple{vtkAxis::BOTTOM, x0, x1}, std::tuple{vtkAxis::LEFT, y0, y1}}) {
        chart->GetAxis(axis)->SetBehavior(vtkAxis::FIXED);
        chart->GetAxis(axis)->SetRange(low, high);
    }
    bool labelled = false;
    for (const auto& s : spec.series)
        labelled = labelled || !s.labels.empty();
    if (spec.logX) // labels sit right of their points: room for the last one
        setLogRange(chart->GetAxis(vtkAxis::BOTTOM), range[0], range[1], 0.05,
                    labelled ? 0.2 : 0.05);
    if (spec.logY) setLogRange(chart->GetAxis(vtkAxis::LEFT), range[2], range[3], 0.05, headRoom);
}

/// The screen coordinate of value along axis (coordinate 0: x, 1: y) once the chart is laid out.
double screenPosition(vtkAxis* axis, double value, int coordinate) {
    const float* from = axis->GetPoint1();
    const float* to = axis->GetPoint2();
    const double t = axis->GetLogScaleActive()
                         ? std::log10(value / axis->GetUnscaledMinimum()) /
                               std::log10(axis->GetUnscaledMaximum() / axis->GetUnscaledMinimum())
                         : (value - axis->GetMinimum()) / (axis->GetMaximum() - axis->GetMinimum());
    return from[coordinate] + t * (to[coordinate] - from[coordinate]);
}

/// Text actors beside the labelled points of `spec` (call after a first render has laid out the
/// axes); returns whether any label was added.
bool addPointLabels(const ChartSpec& spec, vtkChartXY* chart, vtkRenderer* renderer) {
    bool added = false;
    for (const auto& s : spec.series)
        for (std::size_t k = 0; k < s.labels.size(); ++k) {
            const double x = screenPosition(chart->GetAxis(vtkAxis::BOTTOM), s.x[k], 0);
            const double y = screenPosition(chart->GetAxis(vtkAxis::LEFT), s.y[k], 1);
            vtkNew<vtkTextActor> text;
            text->SetInput(s.labels[k].c_str());
            text->GetTextProperty()->SetFontSize(12);
            text->GetTextProperty()->SetColor(0.15, 0.15, 0.15);
            text->SetDisplayPosition(static_cast<int>(x) + 7, static_cast<int>(y) + 4);
            renderer->AddActor2D(text);
            added = true;
        }
    return added;
}

} // namespace

void renderLineChart(const ChartSpec& spec, const std::string& path, int width, int height) {
    std::size_t points = 0;
    for (const auto& s : spec.series) {
        if (s.x.size() != s.y.size())
            throw std::invalid_argument("chart series '" + s.name + "' has " +
                                        std::to_string(s.x.size()) + " x values but " +
                                        std::to_string(s.y.size()) + " y values");
        if (!s.labels.empty() && s.labels.size() != s.x.size())
            throw std::invalid_argument("chart series '" + s.name + "' has " +
                                        std::to_string(s.labels.size()) + " labels for " +
                                        std::to_string(s.x.size()) + " points");
        if ((!s.low.empty() || !s.high.empty()) &&
            (s.low.size() != s.x.size() || s.high.size() != s.x.size()))
            throw std::invalid_argument("chart series '" + s.name +
                                        "' has a band that does not match its " +
                                        std::to_string(s.x.size()) + " points");
        for (std::size_t k = 0; k < s.x.size(); ++k)
            if ((spec.logX && !(s.x[k] > 0)) || (spec.logY && !(s.y[k] > 0)))
                throw std::invalid_argument("chart series '" + s.name +
                                            "' has a value that is not positive on a "
                                            "logarithmic axis");
        points += s.x.size();
    }
    for (const auto& r : spec.references)
        if ((r.horizontal ? spec.logY : spec.logX) && !(r.value > 0))
            throw std::invalid_argument("reference line '" + r.name +
                                        "' is not positive on a logarithmic axis");
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
    chart->GetLegend()->SetHorizontalAlignment(spec.legendAtLeft ? vtkChartLegend::LEFT
                                                                 : vtkChartLegend::RIGHT);
    chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
    addPlots(spec, chart);
    fitAxes(spec, chart);
    view->GetRenderWindow()->Render();
    if (addPointLabels(spec, chart, view->GetRenderer())) view->GetRenderWindow()->Render();
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

ChartSpec runoutVsSlopeChart(std::vector<ChartSeries> series, const std::string& yTitle) {
    ChartSpec spec;
    spec.title = "Final runout against slope";
    spec.xTitle = "slope [deg]";
    spec.yTitle = yTitle;
    for (auto& s : series)
        s.markers = true;
    spec.series = std::move(series);
    return spec;
}

} // namespace lbdem::vis
