// Line charts (VTK charts, rendered off-screen to PNG) for time series and sweep results.
#pragma once

#include <string>
#include <vector>

namespace lbdem::vis {

/// How a curve's line is drawn.
enum class LineStyle { Solid, Dashed, Dotted, DashDotted };

/// One named curve of (x, y) points, drawn in the order given.
struct ChartSeries {
    std::string name;
    std::vector<double> x, y;
    bool markers = false; ///< draw a marker at each point (for sparse data such as a sweep)
    int colour = -1;      ///< palette index (Tableau 10); -1: the series' position in the chart
    LineStyle style = LineStyle::Solid;
    std::vector<std::string> labels{}; ///< text beside each point (empty: none), e.g. a setting
    std::vector<double> low{}, high{}; ///< a shaded band from low to high at each x (empty: none)
    std::string bandName{};            ///< the band's legend entry (empty: the band is not listed)
};

/// A dashed reference line across the plot: horizontal at y = value, or vertical at x = value.
struct ReferenceLine {
    std::string name;
    double value = 0;
    bool horizontal = true;
};

/// What to plot: title, axis titles with units, curves and reference lines.
struct ChartSpec {
    std::string title;
    std::string xTitle, yTitle;
    std::vector<ChartSeries> series;
    std::vector<ReferenceLine> references;
    bool legend = true;
    bool legendAtLeft = false;       ///< legend in the top-left corner instead of the top-right one
    bool logX = false, logY = false; ///< logarithmic axes (every value on them must be positive)
};

/// Renders `spec` off-screen at `width` x `height` pixels into the PNG file `path`; needs an
/// X display (see ensureDisplay); bands are drawn first, translucent, in their series' colour.
/// Throws std::invalid_argument for a series whose x and y lengths differ (or whose labels or
/// band, when given, do not match them), a value that is not
/// positive on a logarithmic axis, or a spec with no points at all.
void renderLineChart(const ChartSpec& spec, const std::string& path, int width, int height);

/// A chart of time series against t/tau_c, e.g. runout or E_k/E_p0 of several runs.
ChartSpec timeSeriesChart(const std::string& title, const std::string& yTitle,
                          std::vector<ChartSeries> series);
/// Froude number against t/tau_c with the hydroplaning threshold Fr = 0.4 as a reference line.
ChartSpec froudeChart(std::vector<ChartSeries> series);
/// Final runout against slope [deg], one series per scene kind (dry, wet dense, wet loose),
/// with markers at the swept slopes; yTitle names the runout measure and its unit.
ChartSpec runoutVsSlopeChart(std::vector<ChartSeries> series,
                             const std::string& yTitle = "final runout [m]");

} // namespace lbdem::vis
