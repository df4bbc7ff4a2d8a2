// The paper's figures of a sweep (PNG): runout, kinetic energy and Froude number against
// t/tau_c, final runout against slope.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace lbdem::cli {

/// What the figures need of one case of a sweep.
struct SweepFigureCase {
    std::string name;
    double packing = 0; ///< target packing fraction (the paper: dense 0.83, loose 0.79)
    double slope_deg = 0;
    bool submerged = false;
    std::string status;        ///< finished, unfinished, missing or unreadable (summary.json)
    double runout_final = 0;   ///< (L_f - L_i) / L_i at the end (summary.json runout_final)
    std::filesystem::path dir; ///< the case's output folder (timeseries.csv)
};

/// What writeSweepFigures did.
struct SweepFiguresResult {
    std::vector<std::string> files;   ///< the PNG files written, in the order drawn
    std::vector<std::string> skipped; ///< "case (reason)" for each case left out of the figures
    std::string unavailable;          ///< why no figure was drawn at all; empty otherwise
};

/// The name of a packing in figure titles and file names: "dense" from 0.81 up (between the
/// paper's 0.79 and 0.83), else "loose".
std::string packingName(double packing);

/// Draws into `out`, from the finished cases: runout_<packing>.png and energy_<packing>.png
/// (runout_normalised and ke_over_ep0 against t/tau_c, one figure per packing, colour by slope,
/// solid dry and dashed submerged), runout_vs_slope.png (final runout, packing x medium) and
/// froude.png (submerged cases, with the Fr = 0.4 hydroplaning line). Runs that share a case
/// name (an ensemble over packing seeds) are drawn as their mean with a shaded min-max band, named
/// in the legend. Unfinished or unreadable runs are skipped and listed by folder; a build without
/// VTK draws nothing and says so.
SweepFiguresResult writeSweepFigures(const std::string& sweepName,
                                     const std::vector<SweepFigureCase>& cases,
                                     const std::filesystem::path& out);

} // namespace lbdem::cli
