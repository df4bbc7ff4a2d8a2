// The running diagnostics of a run (kinetic-energy peak, base-stress window, work totals),
// part of the saved state so that a resumed run continues them exactly.
#pragma once

#include "solver/core/StateArchive.h"

#include <array>
#include <cstddef>
#include <deque>
#include <map>
#include <string>
#include <vector>

namespace lbdem::solver {

/// What a run accumulates across its outputs and across the processes that ran it: the peak of
/// E_k / E_p0 and its time, the last kBaseStressWindow values of the base stress at the front
/// (averaged into base_normal_stress_front_avg5_pa), the metrics of the last output, and the wall
/// time, steps and per-stage seconds of all processes so far. Saved into and restored from the
/// state archive ("run/..." arrays).
class RunDiagnostics {
public:
    /// Outputs the base stress at the front is averaged over (the effective stress at the base
    /// over the front, averaged over 5 outputs, as the paper's figures use it).
    static constexpr std::size_t kBaseStressWindow = 5;

    /// Take the metrics of an output at timeOverTc: updates the peak and the window, and adds
    /// base_normal_stress_front_avg5_pa to metrics when the scene reports the base stress.
    void recordOutput(std::map<std::string, double>& metrics, double timeOverTc);
    /// Set the work of the running process so far (wall seconds, steps, seconds per stage); the
    /// totals are these plus what earlier processes of the run did.
    void setProcessWork(double wallSeconds, long long steps,
                        const std::vector<double>& stageSeconds);

    /// Largest E_k / E_p0 of all outputs (0 when none reported it).
    double kePeak() const { return m_kePeak; }
    /// t / tau_c of that peak.
    double tKePeakOverTc() const { return m_tKePeakOverTc; }
    /// The metrics of the latest output (empty before the first).
    const std::map<std::string, double>& lastMetrics() const { return m_lastMetrics; }
    /// Step index of the latest output (-1 before the first).
    long long lastOutputStep() const { return m_lastOutputStep; }
    /// Wall seconds of all processes of the run.
    double wallSeconds() const { return m_wallBefore + m_wallNow; }
    /// Steps taken by all processes of the run while timed.
    long long stepsTimed() const { return m_stepsBefore + m_stepsNow; }
    /// Seconds per stage of all processes (indexed by Stage).
    std::vector<double> stageSeconds() const;

    /// Write the diagnostics into archive as "run/..." arrays.
    void save(StateArchive& archive) const;
    /// Restore diagnostics saved by save(); an archive without them (an older checkpoint)
    /// leaves a fresh state.
    void restore(const StateArchive& archive);

private:
    double m_kePeak = 0, m_tKePeakOverTc = 0;
    std::deque<double> m_baseStress;
    std::map<std::string, double> m_lastMetrics;
    long long m_lastOutputStep = -1;
    double m_wallBefore = 0, m_wallNow = 0;
    long long m_stepsBefore = 0, m_stepsNow = 0;
    std::vector<double> m_stagesBefore, m_stagesNow;
};

} // namespace lbdem::solver
