// Permeability chart: one curve per coupling method and the two Carman–Kozeny relations.
#include "app/cli/PermeabilityPlot.h"

#ifdef LBDEM_HAS_VIS
#include "ui/vis/HeadlessDisplay.h"
#include "ui/vis/LineChart.h"
#endif

#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace lbdem::cli {

bool writePermeabilityPlot(const std::string& csvPath, const std::string& pngPath) {
#ifdef LBDEM_HAS_VIS
    std::ifstream file(csvPath);
    std::string line;
    if (!file || !std::getline(file, line)) return false;
    // Columns: method, hydro_radius_ratio, quasi_porosity, k_over_d2, carman_kozeny_spheres,
    // carman_kozeny_cylinders, wall_s.
    std::map<std::string, vis::ChartSeries> methods;
    vis::ChartSeries spheres{"Carman-Kozeny, spheres", {}, {}, false};
    vis::ChartSeries cylinders{"Carman-Kozeny, cylinders", {}, {}, false};
    while (std::getline(file, line)) {
        std::stringstream row(line);
        std::string cell;
        std::vector<std::string> cells;
        while (std::getline(row, cell, ','))
            cells.push_back(cell);
        if (cells.size() < 6) continue;
        const double porosity = std::stod(cells[2]);
        auto& series = methods[cells[0]];
        series.name = "LBM, " + cells[0];
        series.markers = true;
        series.x.push_back(porosity);
        series.y.push_back(std::stod(cells[3]));
        if (cells[0] == methods.begin()->first) {
            spheres.x.push_back(porosity);
            spheres.y.push_back(std::stod(cells[4]));
            cylinders.x.push_back(porosity);
            cylinders.y.push_back(std::stod(cells[5]));
        }
    }
    if (methods.empty()) return false;
    vis::ChartSpec spec;
    spec.title = "Permeability of a random disc packing (hydrodynamic radius 0.7 ... 0.95 R)";
    spec.xTitle = "quasi-porosity n";
    spec.yTitle = "K / d^2";
    for (auto& [name, series] : methods)
        spec.series.push_back(series);
    spec.series.push_back(spheres);
    spec.series.push_back(cylinders);
    vis::ensureDisplay();
    vis::renderLineChart(spec, pngPath, 900, 600);
    return true;
#else
    (void)csvPath;
    (void)pngPath;
    return false;
#endif
}

} // namespace lbdem::cli
