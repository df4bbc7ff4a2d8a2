// Wall-clock accounting of the named stages of a simulation step.
#pragma once

#include <array>
#include <chrono>
#include <cstddef>
#include <string_view>

namespace lbdem::solver {

/// The stages of Simulation::step(), in execution order (docs/style.md, Style §4).
enum class Stage : std::size_t {
    MapGrains,
    StreamCollide,
    Boundaries,
    HydrodynamicForces,
    DemSubsteps,
    Diagnostics,
    Count
};

/// Human-readable name of a stage, for reports.
std::string_view stageName(Stage stage);

/// Accumulates seconds per stage; not thread-safe, used from the stepping thread only.
class StageTimer {
public:
    using Clock = std::chrono::steady_clock;

    /// Add the time since start to stage and return the current time (to chain stages).
    Clock::time_point lap(Stage stage, Clock::time_point start) {
        const auto now = Clock::now();
        m_seconds[static_cast<std::size_t>(stage)] +=
            std::chrono::duration<double>(now - start).count();
        return now;
    }
    /// Seconds spent in stage so far.
    double seconds(Stage stage) const { return m_seconds[static_cast<std::size_t>(stage)]; }
    /// Seconds over all stages.
    double total() const;
    /// Forget all accumulated time.
    void reset() { m_seconds.fill(0.0); }

private:
    std::array<double, static_cast<std::size_t>(Stage::Count)> m_seconds{};
};

} // namespace lbdem::solver
