// `lbdem bench --case`: where the time of a real case's step goes, against the memory roofline.
#pragma once

#include <string>
#include <vector>

namespace lbdem::cli {

/// What `lbdem bench --case` runs.
struct CaseBenchOptions {
    std::string path;                   ///< the case file
    std::vector<std::string> overrides; ///< --set key=value
    double tc = 0.5;                    ///< span to run [tau_c]
    int threads = 0;                    ///< OpenMP threads (0: the case's run.threads, else all)
    bool json = false;
};

/// Run the case for options.tc and print, per stage, the time per step and its share, the
/// effective MLUPS, the memory-bandwidth roofline measured before and after in the same run
/// and the projected wall time to the case's end; returns the exit code.
int runCaseBench(const CaseBenchOptions& options);

} // namespace lbdem::cli
