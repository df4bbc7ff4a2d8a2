// Synthetic sweep folders for the sweep report and ensemble tests: named cases and run folders
// written as `lbdem run` would, with a runout that approaches a chosen final value.
#pragma once

#include "campaign/SweepReport.h"

#include <filesystem>
#include <optional>
#include <string>

namespace lbdem::support {

/// Whole text of a file ("" when missing).
std::string readText(const std::filesystem::path& path);

/// A case of a synthetic sweep named PACKING_SLOPEdeg_MEDIUM ("dense" above packing 0.81, else
/// "loose"), in out/NAME, or in out/NAME_sSEED with its seed when `seed` is above 0.
campaign::SweepEntry syntheticEntry(const std::filesystem::path& out, double packing, double slope,
                                    bool submerged, int seed = 0);

/// Writes dir/timeseries.csv, t/tau_c 0 to 4 in steps of 0.25, of a front starting at 0.05 m whose
/// normalised runout approaches `runout` as runout (1 - e^-t); the densimetric Froude column
/// when `froude`, and a constant pore pressure column when `porePressurePa` is given.
void writeSyntheticSeries(const std::filesystem::path& dir, double runout, bool froude,
                          std::optional<double> porePressurePa);

/// Writes dir/summary.json as `lbdem run` would: finished, runout_final, ke_peak, a kinetic-energy
/// peak at 1 tau_c and packing_final, then `moreFields` (", \"key\": value" pairs) as given.
void writeSyntheticSummary(const std::filesystem::path& dir, bool finished, double runout,
                           double kePeak, double packingFinal, const std::string& moreFields);

} // namespace lbdem::support
