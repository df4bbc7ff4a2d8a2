// The paper's figures of a sweep (PNG): runout, kinetic energy and Froude number against
// t/tau_c, final runout against slope.
#pragma once

#include "campaign/SweepFigureCase.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lbdem::campaign {

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

} // namespace lbdem::campaign
