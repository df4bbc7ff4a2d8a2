// Synthetic sweep folders for the sweep report and ensemble tests.
#include "tests/support/SyntheticSweep.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace lbdem::support {

namespace fs = std::filesystem;

std::string readText(const fs::path& path) {
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

campaign::SweepEntry syntheticEntry(const fs::path& out, double packing, double slope,
                                    bool submerged, int seed) {
    campaign::SweepEntry e;
    char name[64];
    std::snprintf(name, sizeof name, "%s_%gdeg_%s", packing > 0.81 ? "dense" : "loose", slope,
                  submerged ? "submerged" : "dry");
    e.spec.name = name;
    e.spec.grains.packing = packing;
    e.spec.domain.slope_deg = slope;
    e.spec.fluid.enabled = submerged;
    e.seed = seed;
    e.dir = out / (seed > 0 ? std::string(name) + "_s" + std::to_string(seed) : std::string(name));
    return e;
}

void writeSyntheticSeries(const fs::path& dir, double runout, bool froude,
                          std::optional<double> porePressurePa) {
    fs::create_directories(dir);
    const double initialWidth = 0.05; // L_i: the front starts there
    std::ofstream series(dir / "timeseries.csv");
    series << "t_s,t_over_tc,step,ke_over_ep0,runout_m,runout_normalised"
           << (froude ? ",froude_densimetric" : "")
           << (porePressurePa ? ",pore_pressure_failure_plane_pa" : "") << "\n";
    for (int k = 0; k <= 16; ++k) {
        const double t = 0.25 * k, grown = runout * (1 - std::exp(-t));
        series << 0.01 * t << "," << t << "," << 100 * k << "," << 0.1 * runout * t * std::exp(-t)
               << "," << initialWidth * (1 + grown) << "," << grown;
        if (froude) series << "," << 0.5 * runout * t * std::exp(-t);
        if (porePressurePa) series << "," << *porePressurePa;
        series << "\n";
    }
}

void writeSyntheticSummary(const fs::path& dir, bool finished, double runout, double kePeak,
                           double packingFinal, const std::string& moreFields) {
    std::ofstream summary(dir / "summary.json");
    summary << "{\"finished\": " << (finished ? "true" : "false")
            << ", \"runout_final\": " << runout << ", \"ke_peak\": " << kePeak
            << ", \"t_ke_peak_over_tc\": 1.0, \"packing_final\": " << packingFinal << moreFields
            << "}\n";
}

} // namespace lbdem::support
