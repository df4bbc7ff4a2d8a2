// Per-output profile files of a run: the flow-front outline and the probe lines, as small CSVs.
#pragma once

#include "app/cli/RunDriver.h"

#include <memory>
#include <string>

namespace lbdem::cli {

/// The CSV text of an outline polyline: header `x_m,y_m`, one vertex per row.
std::string outlineCsv(const solver::Snapshot& snapshot);

/// The CSV text of a probe line: header `s_m,x_m,y_m,<quantity>`, one sample per row; the value
/// is empty where the probe point is not in the fluid.
std::string probeCsv(const solver::SnapshotProbe& probe);

/// A sink writing DIR/profiles/outline_NNNNNN.csv (scenes with grains) and
/// DIR/profiles/<probe name>_NNNNNN.csv (each probe line, e.g. pore_pressure_failure_plane) at
/// every output, atomically; NNNNNN is the output index, the same after a resume.
std::unique_ptr<SnapshotSink> makeProfileSink(const std::string& dir);

} // namespace lbdem::cli
