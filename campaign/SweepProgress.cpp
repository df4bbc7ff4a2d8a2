// Progress lines of `lbdem sweep`, from the timeseries.csv each case writes as it goes.
#include "campaign/SweepProgress.h"
#include "campaign/Duration.h"

#include "solver/io/TimeSeriesWriter.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace lbdem::campaign {

namespace {

/// Seconds of a case's wall time before its pace is trusted (start-up: packing, allocation).
constexpr double kPaceAfterS = 20;

} // namespace

double runProgressTc(const std::filesystem::path& dir) {
    const auto path = dir / "timeseries.csv";
    if (!std::filesystem::exists(path)) return 0;
    try {
        const auto values = io::readTimeSeries(path.string()).column("t_over_tc");
        return values.empty() ? 0 : values.back();
    } catch (const std::runtime_error&) {
        return 0; // being written this very moment: the next look will do
    }
}

SweepProgress::SweepProgress(const std::vector<SweepEntry>& cases, int maxParallel, int skipped)
    : m_maxParallel(std::max(1, maxParallel)), m_skipped(skipped) {
    for (const auto& entry : cases) {
        Case c;
        c.name = entry.dir.filename().string(); // the case, or the case and its seed
        c.dir = entry.dir;
        c.fluid = entry.spec.fluid.enabled;
        c.startTc = c.nowTc = runProgressTc(entry.dir);
        c.endTc = entry.spec.run.end_tc;
        m_cases.push_back(c);
    }
}

void SweepProgress::finished(std::size_t index, double wall_s) {
    auto& c = m_cases.at(index);
    c.done = true;
    c.wall_s = wall_s;
    c.nowTc = c.endTc;
}

bool SweepProgress::timed(const Case& c) {
    return c.wall_s >= kPaceAfterS && c.nowTc > c.startTc;
}

double SweepProgress::paceOfKind(bool fluid) const {
    double advanced = 0, wall = 0;
    for (const auto& c : m_cases)
        if (c.fluid == fluid && timed(c)) {
            advanced += c.nowTc - c.startTc;
            wall += c.wall_s;
        }
    return wall > 0 ? advanced / wall : 0;
}

std::string SweepProgress::line(const std::vector<RunningJob>& running) {
    for (const auto& job : running) {
        auto& c = m_cases.at(job.index);
        c.wall_s = job.wall_s;
        c.nowTc = std::max(c.nowTc, runProgressTc(c.dir));
    }
    const int done =
        m_skipped + static_cast<int>(std::count_if(m_cases.begin(), m_cases.end(),
                                                   [](const Case& c) { return c.done; }));
    std::string text = std::to_string(done) + "/" +
                       std::to_string(m_skipped + static_cast<int>(m_cases.size())) + " done";
    double left = 0, longestRunning = 0;
    int untimed = 0; // cases of a kind none of which has run long enough to show its pace
    std::vector<bool> isRunning(m_cases.size(), false);
    for (std::size_t k = 0; k < running.size(); ++k) {
        const auto& c = m_cases.at(running[k].index);
        isRunning[running[k].index] = true;
        char part[160];
        std::snprintf(part, sizeof part, "%s %s t/tc %.2f/%.3g", k == 0 ? "; running" : ",",
                      c.name.c_str(), c.nowTc, c.endTc);
        text += part;
        const double pace = timed(c) ? (c.nowTc - c.startTc) / c.wall_s : paceOfKind(c.fluid);
        if (pace <= 0) {
            ++untimed;
            continue;
        }
        const double remaining = std::max(0.0, c.endTc - c.nowTc) / pace;
        left += remaining;
        longestRunning = std::max(longestRunning, remaining);
    }
    for (std::size_t k = 0; k < m_cases.size(); ++k) {
        const auto& c = m_cases[k];
        if (c.done || isRunning[k]) continue;
        const double pace = paceOfKind(c.fluid);
        if (pace <= 0) {
            ++untimed;
            continue;
        }
        left += std::max(0.0, c.endTc - c.startTc) / pace;
    }
    // The work left spread over the job slots, but never sooner than the longest running case.
    if (left <= 0 && untimed > 0)
        return text + "; ETA once a case has run " + formatDuration(kPaceAfterS);
    text += "; ETA " + formatDuration(std::max(longestRunning, left / m_maxParallel));
    if (untimed > 0) text += " + " + std::to_string(untimed) + " case(s) not timed yet";
    return text;
}

} // namespace lbdem::campaign
