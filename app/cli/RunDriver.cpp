// The run loop of `lbdem run` and `lbdem resume`.
#include "app/cli/RunDriver.h"
#include "app/cli/Duration.h"

#include "solver/core/InputError.h"
#include "solver/io/CaseWriter.h"
#include "solver/io/Checkpoint.h"
#include "solver/io/PlanJson.h"
#include "solver/io/TimeSeriesWriter.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <fstream>
#include <iostream>

namespace lbdem::cli {

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kProgressPeriodS = 2.0;

double seconds(Clock::time_point since) {
    return std::chrono::duration<double>(Clock::now() - since).count();
}

/// Keep only the rows of an existing timeseries.csv up to and including step (for a resume
/// after a kill: rows written after the last checkpoint are computed again).
void trimTimeSeries(const std::string& path, long long step) {
    std::ifstream in(path);
    if (!in) return;
    std::string header, line, kept;
    if (!std::getline(in, header)) return;
    const auto table = io::readTimeSeries(path);
    const auto steps = table.column("step");
    kept = header + "\n";
    for (std::size_t row = 0; std::getline(in, line); ++row)
        if (row < steps.size() && steps[row] <= step) kept += line + "\n";
    in.close();
    io::writeFileAtomically(path, kept);
}

/// Outputs the base stress is averaged over (DESIGN §6: effective stress at the base over the
/// front, averaged over 5 outputs).
constexpr std::size_t kBaseStressWindow = 5;

/// The last `count` values of a column of an existing timeseries.csv, oldest first.
std::deque<double> lastValues(const std::string& path, const std::string& name, std::size_t count) {
    std::ifstream probe(path);
    if (!probe) return {};
    const auto values = io::readTimeSeries(path).column(name);
    const std::size_t first = values.size() > count ? values.size() - count : 0;
    return std::deque<double>(values.begin() + static_cast<std::ptrdiff_t>(first), values.end());
}

} // namespace

struct RunDriver::Progress {
    std::unique_ptr<io::TimeSeriesWriter> series;
    long long outputIndex = 0;
    double nextOutputS = 0;
    double nextCheckpointS = 0;
    double lastReportWall = -1e9;
    long long firstStep = 0;
    double kePeak = 0, tKePeakOverTc = 0;
    std::map<std::string, double> lastMetrics;
    std::deque<double> baseStress; // the last kBaseStressWindow values, as printed
    long long lastOutputStep = -1;
    Clock::time_point start = Clock::now();
};

RunDriver::RunDriver(solver::Simulation& simulation, RunDriverOptions options)
    : m_simulation(simulation), m_options(std::move(options)), m_progress(std::make_unique<Progress>()) {}

RunDriver::~RunDriver() = default;

void RunDriver::addSink(std::unique_ptr<SnapshotSink> sink) { m_sinks.push_back(std::move(sink)); }

void RunDriver::writeOutput() {
    auto& p = *m_progress;
    auto metrics = m_simulation.metrics();
    metrics["t_s"] = m_simulation.time();
    metrics["t_over_tc"] = m_simulation.timeOverTc();
    metrics["step"] = static_cast<double>(m_simulation.stepIndex());
    if (const auto base = metrics.find("base_normal_stress_front_pa"); base != metrics.end()) {
        // The mean of the printed values, so that a resumed run (which reads them back from
        // timeseries.csv) continues the same sequence bit for bit.
        p.baseStress.push_back(io::printedValue(base->second));
        if (p.baseStress.size() > kBaseStressWindow) p.baseStress.pop_front();
        double sum = 0;
        for (double v : p.baseStress) sum += v;
        metrics["base_normal_stress_front_avg5_pa"] = sum / static_cast<double>(p.baseStress.size());
    }
    p.series->append(metrics);
    if (const auto ke = metrics.find("ke_over_ep0"); ke != metrics.end() && ke->second > p.kePeak) {
        p.kePeak = ke->second;
        p.tKePeakOverTc = m_simulation.timeOverTc();
    }
    p.lastMetrics = metrics;
    p.lastOutputStep = m_simulation.stepIndex();
    if (!m_sinks.empty()) {
        const auto snapshot = m_simulation.snapshot();
        for (auto& sink : m_sinks) sink->write(*snapshot, p.outputIndex);
    }
    ++p.outputIndex;
}

void RunDriver::writeCheckpoint() {
    io::CheckpointData data;
    data.case_toml = io::formatCase(m_simulation.spec());
    data.state = m_simulation.saveState();
    io::writeCheckpoint((m_options.dir / "checkpoint.h5").string(), data);
}

void RunDriver::writeSummary(double wallSeconds, bool finished, const std::string& stopReason) const {
    const auto& plan = m_simulation.plan();
    const auto& p = *m_progress;
    const double steps = static_cast<double>(m_simulation.stepIndex() - p.firstStep);
    const double nodes = static_cast<double>(plan.nx) * plan.ny;
    nlohmann::json summary{
        {"case", m_simulation.spec().name},
        {"finished", finished},
        {"scene", m_simulation.spec().scene},
        {"plan", {{"h", plan.h_m}, {"dt", plan.dt_s}, {"tau", plan.tau}, {"mach", plan.mach},
                  {"nx", plan.nx}, {"ny", plan.ny}, {"substeps", plan.substeps}}},
        {"steps", m_simulation.stepIndex()},
        {"t_over_tc", m_simulation.timeOverTc()},
        {"wall_s", wallSeconds},
        {"mlups", wallSeconds > 0 ? nodes * steps / wallSeconds / 1e6 : 0.0},
        {"final", p.lastMetrics},
    };
    auto final = [&](const char* metric) {
        const auto found = p.lastMetrics.find(metric);
        return found == p.lastMetrics.end() ? nlohmann::json(nullptr) : nlohmann::json(found->second);
    };
    summary["runout_final"] = final("runout_normalised");
    summary["packing_final"] = final("packing_fraction");
    summary["ke_peak"] = p.kePeak;
    summary["t_ke_peak_over_tc"] = p.tKePeakOverTc;
    // Where the time went, per stage of the step (this process only; outputs are not counted).
    nlohmann::json stages = nlohmann::json::object();
    for (std::size_t k = 0; k < static_cast<std::size_t>(solver::Stage::Count); ++k) {
        const auto stage = static_cast<solver::Stage>(k);
        stages[std::string(solver::stageName(stage))] = m_simulation.timer().seconds(stage);
    }
    summary["stage_seconds"] = stages;
    if (!stopReason.empty()) summary["stop_reason"] = stopReason;
    io::writeFileAtomically((m_options.dir / "summary.json").string(), summary.dump(2) + "\n");
}

void RunDriver::reportProgress(double wallSeconds, bool last) {
    auto& p = *m_progress;
    if (m_options.quiet || (!last && wallSeconds - p.lastReportWall < kProgressPeriodS)) return;
    p.lastReportWall = wallSeconds;
    const auto& plan = m_simulation.plan();
    const double steps = static_cast<double>(m_simulation.stepIndex() - p.firstStep);
    const double rate = wallSeconds > 0 ? steps / wallSeconds : 0;
    const double mlups = rate * plan.nx * static_cast<double>(plan.ny) / 1e6;
    const double endTc = m_options.until_tc > 0 ? m_options.until_tc : plan.end_time_s / plan.tc_s;
    const double remainingSteps = (endTc - m_simulation.timeOverTc()) * plan.tc_s / plan.dt_s;
    std::fprintf(stderr, "\rt/tc %7.3f / %.3g  step %lld  %.0f steps/s  %.1f MLUPS  ETA %s   %s",
                 m_simulation.timeOverTc(), endTc, m_simulation.stepIndex(), rate, mlups,
                 formatDuration(rate > 0 ? std::max(0.0, remainingSteps) / rate : 0).c_str(),
                 last ? "\n" : "");
    std::fflush(stderr);
}

void RunDriver::run() {
    auto& p = *m_progress;
    const auto& spec = m_simulation.spec();
    const auto& plan = m_simulation.plan();
    const double outputInterval = spec.run.output_interval_tc * plan.tc_s;
    const double checkpointInterval = spec.output.checkpoint_interval_tc * plan.tc_s;
    const std::string seriesPath = (m_options.dir / "timeseries.csv").string();
    const double endS = m_options.until_tc > 0 ? m_options.until_tc * plan.tc_s : plan.end_time_s;
    const double halfStep = 0.5 * plan.dt_s;
    // A resumed run already at (or past) the requested end is left as it is: no output, no
    // checkpoint, and its summary keeps the figures of the run that got it there.
    if (m_options.resumed && m_simulation.time() >= endS - halfStep) {
        if (!m_options.quiet)
            std::cout << m_options.dir.string() << " is already at t/tc = " << m_simulation.timeOverTc()
                      << " (asked for " << endS / plan.tc_s << "): nothing to run, its outputs are left as they are\n";
        return;
    }
    if (m_options.resumed) {
        trimTimeSeries(seriesPath, m_simulation.stepIndex());
        p.baseStress = lastValues(seriesPath, "base_normal_stress_front_pa", kBaseStressWindow);
    }
    p.series = std::make_unique<io::TimeSeriesWriter>(seriesPath, m_options.resumed);
    p.firstStep = m_simulation.stepIndex();
    const double now = m_simulation.time();
    // A resumed run has written every output time up to now (within half a step).
    p.outputIndex = m_options.resumed
                        ? static_cast<long long>(std::floor((now + 0.5 * plan.dt_s) / outputInterval)) + 1
                        : 0;
    p.nextOutputS = m_options.resumed ? p.outputIndex * outputInterval : now;
    p.nextCheckpointS = checkpointInterval > 0 ? now + checkpointInterval : 1e300;

    p.start = Clock::now();
    try {
        while (true) {
            if (m_simulation.time() >= p.nextOutputS - halfStep) {
                writeOutput();
                p.nextOutputS = p.outputIndex * outputInterval;
                writeSummary(seconds(p.start), false);
            }
            if (m_simulation.time() >= p.nextCheckpointS - halfStep) {
                writeCheckpoint();
                p.nextCheckpointS += checkpointInterval;
            }
            if (m_simulation.time() >= endS - halfStep) break;
            m_simulation.step();
            reportProgress(seconds(p.start), false);
        }
    } catch (const solver::SimulationError& error) {
        // The stability guard stopped the run: say so in summary.json, so that a study or a
        // sweep can tell an unstable run from a killed one without reading the log.
        writeSummary(seconds(p.start), false, error.what());
        throw;
    }
    // The flows end between output times: record the final state too, so that summary.json's
    // "final" is the end of the run (not done at an --until-tc stop, to keep resumes aligned).
    if (m_simulation.finished() && m_simulation.stepIndex() != p.lastOutputStep) writeOutput();
    writeCheckpoint();
    writeSummary(seconds(p.start), m_simulation.finished());
    reportProgress(seconds(p.start), true);
}

} // namespace lbdem::cli
