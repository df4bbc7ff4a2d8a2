// Running diagnostics: peak, averaging window and work totals, and their archive form.
#include "solver/scene/RunDiagnostics.h"

#include <algorithm>

namespace lbdem::solver {

namespace {

constexpr const char* kPeak = "run/ke_peak";              // {peak, t/tau_c of the peak}
constexpr const char* kWindow = "run/base_stress_window"; // oldest first
constexpr const char* kWork = "run/work";                 // {wall seconds, steps}
constexpr const char* kStages = "run/stage_seconds";
constexpr const char* kLastStep = "run/last_output_step";
constexpr const char* kLastPrefix = "run/last_metric/"; // one array per metric

/// Element-wise sum of two per-stage vectors of possibly different lengths.
std::vector<double> sum(const std::vector<double>& a, const std::vector<double>& b) {
    std::vector<double> total(std::max(a.size(), b.size()), 0.0);
    for (std::size_t k = 0; k < a.size(); ++k)
        total[k] += a[k];
    for (std::size_t k = 0; k < b.size(); ++k)
        total[k] += b[k];
    return total;
}

} // namespace

void RunDiagnostics::recordOutput(std::map<std::string, double>& metrics, double timeOverTc) {
    if (const auto base = metrics.find("base_normal_stress_front_pa"); base != metrics.end()) {
        m_baseStress.push_back(base->second);
        if (m_baseStress.size() > kBaseStressWindow) m_baseStress.pop_front();
        double total = 0;
        for (const double value : m_baseStress)
            total += value; // oldest first: a fixed order
        metrics["base_normal_stress_front_avg5_pa"] =
            total / static_cast<double>(m_baseStress.size());
    }
    if (const auto ke = metrics.find("ke_over_ep0"); ke != metrics.end() && ke->second > m_kePeak) {
        m_kePeak = ke->second;
        m_tKePeakOverTc = timeOverTc;
    }
    m_lastMetrics = metrics;
    const auto step = metrics.find("step");
    m_lastOutputStep =
        step != metrics.end() ? static_cast<long long>(step->second) : m_lastOutputStep + 1;
}

void RunDiagnostics::setProcessWork(double wallSeconds, long long steps,
                                    const std::vector<double>& stageSeconds) {
    m_wallNow = wallSeconds;
    m_stepsNow = steps;
    m_stagesNow = stageSeconds;
}

std::vector<double> RunDiagnostics::stageSeconds() const {
    return sum(m_stagesBefore, m_stagesNow);
}

void RunDiagnostics::save(StateArchive& archive) const {
    archive.reals[kPeak] = {m_kePeak, m_tKePeakOverTc};
    archive.reals[kWindow] = std::vector<double>(m_baseStress.begin(), m_baseStress.end());
    archive.reals[kWork] = {wallSeconds(), static_cast<double>(stepsTimed())};
    archive.reals[kStages] = stageSeconds();
    archive.integers[kLastStep] = {m_lastOutputStep};
    for (const auto& [name, value] : m_lastMetrics)
        archive.reals[kLastPrefix + name] = {value};
}

void RunDiagnostics::restore(const StateArchive& archive) {
    *this = RunDiagnostics{};
    if (!archive.reals.count(kPeak))
        return; // a checkpoint written before the diagnostics were saved
    m_kePeak = archive.real(kPeak).at(0);
    m_tKePeakOverTc = archive.real(kPeak).at(1);
    const auto& window = archive.real(kWindow);
    m_baseStress.assign(window.begin(), window.end());
    m_wallBefore = archive.real(kWork).at(0);
    m_stepsBefore = static_cast<long long>(archive.real(kWork).at(1));
    m_stagesBefore = archive.real(kStages);
    m_lastOutputStep = archive.integer(kLastStep).at(0);
    const std::string prefix = kLastPrefix;
    for (auto it = archive.reals.lower_bound(prefix); it != archive.reals.end(); ++it) {
        if (it->first.compare(0, prefix.size(), prefix) != 0) break;
        if (!it->second.empty())
            m_lastMetrics[it->first.substr(prefix.size())] = it->second.front();
    }
}

} // namespace lbdem::solver
