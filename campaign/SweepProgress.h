// Progress of a running sweep: each running case's t/tau_c and an estimate of the time left.
#pragma once

#include "campaign/JobRunner.h"
#include "campaign/SweepReport.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace lbdem::campaign {

/// How far the run in dir has got: t/tau_c of the last row of its timeseries.csv (0 if none).
double runProgressTc(const std::filesystem::path& dir);

/// Follows the jobs of a sweep and writes one progress line on request.
class SweepProgress {
public:
    /// cases: the sweep's cases left to run, in job order; skipped: cases already finished.
    SweepProgress(const std::vector<SweepEntry>& cases, int maxParallel, int skipped);

    /// Record that job index ended after wall_s seconds.
    void finished(std::size_t index, double wall_s);

    /// "2/16 done; running A t/tc 4.25/16, B t/tc 3.75/16; ETA 1h52m": the ETA extrapolates each
    /// running case at its own pace and the waiting ones at the pace of their kind (with or
    /// without fluid); cases of a kind not timed yet are counted, not guessed.
    std::string line(const std::vector<RunningJob>& running);

private:
    struct Case {
        std::string name;
        std::filesystem::path dir;
        bool fluid = false;
        double startTc = 0; ///< t/tau_c when the sweep began (a resumed case starts part way)
        double endTc = 0;
        bool done = false;
        double wall_s = 0; ///< wall time so far, or in all once done
        double nowTc = 0;  ///< t/tau_c at the last look
    };
    /// Whether the case has run long enough (past its start-up) for its pace to count.
    static bool timed(const Case& c);
    double
    paceOfKind(bool fluid) const; ///< t/tau_c per wall second over the timed cases; 0 if none

    std::vector<Case> m_cases;
    int m_maxParallel;
    int m_skipped;
};

} // namespace lbdem::campaign
