// What the figures of a sweep are drawn from, and the writer that draws them (supplied by a layer
// that may use VTK: campaign/figures).
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace lbdem::campaign {

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

/// Draws the figures of a sweep named sweepName from its cases into out.
using SweepFigureWriter = std::function<SweepFiguresResult(
    const std::string& sweepName, const std::vector<SweepFigureCase>& cases,
    const std::filesystem::path& out)>;

} // namespace lbdem::campaign
