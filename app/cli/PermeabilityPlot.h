// The paper's Figure 3 from `lbdem verify permeability`: K/d^2 against quasi-porosity.
#pragma once

#include <string>

namespace lbdem::cli {

/// Plot the permeability table (coupling-permeability.csv) against Carman–Kozeny for spheres and
/// cylinders into pngPath; returns false (and writes nothing) in builds without VTK.
bool writePermeabilityPlot(const std::string& csvPath, const std::string& pngPath);

} // namespace lbdem::cli
