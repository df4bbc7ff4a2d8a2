// The run loop of `lbdem run` and `lbdem resume`.
#include "app/cli/RunDriver.h"
#include "app/cli/StopSignals.h"
#include "campaign/Duration.h"

#include "solver/core/InputError.h"
#include "solver/io/CaseWriter.h"
#include "solver/io/Checkpoint.h"
#include "solver/io/PlanJson.h"
#include "solver/io/RunSummary.h"
#include "solver/io/TimeSeriesWriter.h"

#include <chrono>
#include <cmath>
#include <cstdio>
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

/// Remove temporary checkpoint files a killed writer left behind (checkpoint.h5.tmp.PID).
void removeStaleCheckpointFiles(const std::filesystem::path& dir) {
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(dir, error)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("checkpoint.h5.tmp.", 0) == 0) std::filesystem::remove(entry.path(), error);
    }
}

} // namespace

void checkUntilTc(const std::optional<double>& untilTc, const solver::Plan& plan) {
    if (!untilTc) return;
    const double endTc = plan.end_time_s / plan.tc_s;
    // A relative margin: the case's own end, printed and read back, is accepted.
    if (std::isfinite(*untilTc) && *untilTc > 0 && *untilTc <= endTc * (1 + 1e-9)) return;
    char text[160];
    std::snprintf(text, sizeof text,
                  "--until-tc %g: expected a time above 0 and at most the case's end, "
                  "run.end_tc = %g",
                  *untilTc, endTc);
    throw solver::InputError(text);
}

struct RunDriver::Progress {
    std::unique_ptr<io::TimeSeriesWriter> series;
    long long outputIndex = 0;
    double nextOutputS = 0;
    double nextCheckpointS = 0;
    double lastReportWall = -1e9;
    long long firstStep = 0;
    long long lastCheckpointStep = -1;
    bool lineOpen = false; // a progress line without its newline is on stderr
    Clock::time_point start = Clock::now();
};

RunDriver::RunDriver(solver::Simulation& simulation, RunDriverOptions options)
    : m_simulation(simulation), m_options(std::move(options)),
      m_progress(std::make_unique<Progress>()) {}

RunDriver::~RunDriver() = default;

void RunDriver::addSink(std::unique_ptr<SnapshotSink> sink) {
    m_sinks.push_back(std::move(sink));
}

void RunDriver::writeOutput() {
    auto& p = *m_progress;
    auto metrics = m_simulation.metrics();
    metrics["t_s"] = m_simulation.time();
    metrics["t_over_tc"] = m_simulation.timeOverTc();
    metrics["step"] = static_cast<double>(m_simulation.stepIndex());
    m_simulation.runDiagnostics().recordOutput(metrics, m_simulation.timeOverTc());
    p.series->append(metrics);
    if (!m_sinks.empty()) {
        const auto snapshot = m_simulation.snapshot();
        for (auto& sink : m_sinks)
            sink->write(*snapshot, p.outputIndex);
    }
    ++p.outputIndex;
}

void RunDriver::accountWork() {
    const auto& p = *m_progress;
    std::vector<double> stages;
    for (std::size_t k = 0; k < static_cast<std::size_t>(solver::Stage::Count); ++k)
        stages.push_back(m_simulation.timer().seconds(static_cast<solver::Stage>(k)));
    m_simulation.runDiagnostics().setProcessWork(seconds(p.start),
                                                 m_simulation.stepIndex() - p.firstStep, stages);
}

void RunDriver::writeCheckpoint() {
    accountWork();
    io::CheckpointData data;
    data.case_toml = io::formatCase(m_simulation.spec());
    data.state = m_simulation.saveState();
    data.run_id = m_options.identity.run_id;
    data.case_hash = m_options.identity.case_hash;
    io::writeCheckpoint((m_options.dir / "checkpoint.h5").string(), data);
    m_progress->lastCheckpointStep = m_simulation.stepIndex();
}

void RunDriver::writeSummary(bool finished, const std::string& stopReason) {
    accountWork();
    io::writeRunSummary(m_options.dir, m_simulation, finished, stopReason);
}

void RunDriver::stopOnSignal(int signal) {
    closeProgressLine();
    // The step under way has ended: the checkpoint holds this very step, so that lbdem resume
    // goes on exactly as the run would have.
    if (m_simulation.stepIndex() != m_progress->lastCheckpointStep) writeCheckpoint();
    writeSummary(false);
    char text[64];
    std::snprintf(text, sizeof text, "%.4g", m_simulation.timeOverTc());
    throw StoppedBySignal(signal, std::string("stopped at t/τc = ") + text + "; lbdem resume " +
                                      m_options.dir.string() + " continues");
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
    std::fprintf(
        stderr, "\rt/tc %7.3f / %.3g  step %lld  %.0f steps/s  %.1f MLUPS  ETA %s   %s",
        m_simulation.timeOverTc(), endTc, m_simulation.stepIndex(), rate, mlups,
        campaign::formatDuration(rate > 0 ? std::max(0.0, remainingSteps) / rate : 0).c_str(),
        last ? "\n" : "");
    std::fflush(stderr);
    p.lineOpen = !last;
}

void RunDriver::closeProgressLine() {
    if (m_progress->lineOpen) std::fputs("\n", stderr);
    m_progress->lineOpen = false;
}

void RunDriver::startSeries(double outputInterval, double checkpointInterval) {
    auto& p = *m_progress;
    const std::string seriesPath = (m_options.dir / "timeseries.csv").string();
    removeStaleCheckpointFiles(m_options.dir);
    if (m_options.resumed) trimTimeSeries(seriesPath, m_simulation.stepIndex());
    p.series = std::make_unique<io::TimeSeriesWriter>(seriesPath, m_options.resumed);
    p.firstStep = m_simulation.stepIndex();
    const double now = m_simulation.time();
    // A resumed run has written every output time up to now (within half a step).
    p.outputIndex = m_options.resumed
                        ? static_cast<long long>(
                              std::floor((now + 0.5 * m_simulation.plan().dt_s) / outputInterval)) +
                              1
                        : 0;
    p.nextOutputS = m_options.resumed ? p.outputIndex * outputInterval : now;
    // A fresh run checkpoints at t = 0 too (after its first output), so that it can be resumed
    // whenever it is stopped.
    p.nextCheckpointS = checkpointInterval <= 0 ? 1e300
                        : m_options.resumed     ? now + checkpointInterval
                                                : now;
}

void RunDriver::run() {
    auto& p = *m_progress;
    const auto& spec = m_simulation.spec();
    const auto& plan = m_simulation.plan();
    const double outputInterval = spec.run.output_interval_tc * plan.tc_s;
    const double checkpointInterval = spec.output.checkpoint_interval_tc * plan.tc_s;
    const double endS = m_options.until_tc > 0 ? m_options.until_tc * plan.tc_s : plan.end_time_s;
    const double halfStep = 0.5 * plan.dt_s;
    // A resumed run already at (or past) the requested end is left as it is: no output, no
    // checkpoint, and its summary keeps the figures of the run that got it there.
    if (m_options.resumed && m_simulation.time() >= endS - halfStep) {
        if (!m_options.quiet)
            std::cout << m_options.dir.string()
                      << " is already at t/tc = " << m_simulation.timeOverTc() << " (asked for "
                      << endS / plan.tc_s
                      << "): nothing to run, its outputs are left as they are\n";
        return;
    }
    startSeries(outputInterval, checkpointInterval);

    p.start = Clock::now();
    const StopSignals stopSignals; // from here a signal stops the run at the end of a step
    try {
        while (true) {
            if (m_simulation.time() >= p.nextOutputS - halfStep) {
                writeOutput();
                p.nextOutputS = p.outputIndex * outputInterval;
                writeSummary(false);
            }
            if (m_simulation.time() >= p.nextCheckpointS - halfStep) {
                writeCheckpoint();
                p.nextCheckpointS += checkpointInterval;
            }
            if (m_simulation.time() >= endS - halfStep) break;
            if (const int signal = StopSignals::stopSignal()) stopOnSignal(signal);
            m_simulation.step();
            reportProgress(seconds(p.start), false);
        }
    } catch (const solver::SimulationError& error) {
        // The stability guard stopped the run: say so in summary.json, so that a study or a
        // sweep can tell an unstable run from a killed one without reading the log.
        closeProgressLine(); // the diagnosis goes on its own line
        writeSummary(false, error.what());
        throw;
    } catch (...) {
        closeProgressLine();
        throw;
    }
    // The flows end between output times: record the final state too, so that summary.json's
    // "final" is the end of the run (not done at an --until-tc stop, to keep resumes aligned).
    if (m_simulation.finished() &&
        m_simulation.stepIndex() != m_simulation.runDiagnostics().lastOutputStep())
        writeOutput();
    writeCheckpoint();
    writeSummary(m_simulation.finished());
    reportProgress(seconds(p.start), true);
}

} // namespace lbdem::cli
