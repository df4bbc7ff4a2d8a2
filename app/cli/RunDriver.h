// Drives a Simulation to its end: outputs at intervals, checkpoints, progress, summary.
#pragma once

#include "solver/io/RunIdentity.h"
#include "solver/scene/Simulation.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace lbdem::cli {

/// Writes the snapshot series of a run (VTU/VTI/PVD, PNG frames); supplied by the vis layer.
class SnapshotSink {
public:
    virtual ~SnapshotSink() = default;
    /// Called at every output time with the output's index.
    virtual void write(const solver::Snapshot& snapshot, long long outputIndex) = 0;
};

/// How a run is driven.
struct RunDriverOptions {
    std::filesystem::path dir; ///< output folder (exists)
    bool quiet = false;        ///< no progress lines
    double until_tc = -1;      ///< stop at this t / tau_c instead of the case's end (if > 0)
    bool resumed = false;      ///< continuing from DIR/checkpoint.h5: append, do not restart
    io::RunIdentity identity;  ///< the run's id and case hash, written into every checkpoint
};

/// Refuse (InputError, exit 2) an --until-tc that is not a time within the case: not finite, not
/// above 0, or past the case's end (a run would never reach it, or would run without end).
void checkUntilTc(const std::optional<double>& untilTc, const solver::Plan& plan);

/// Steps a Simulation and writes timeseries.csv, summary.json, checkpoint.h5 and the snapshot
/// series into the output folder, so that a run killed at any moment leaves valid files.
class RunDriver {
public:
    RunDriver(solver::Simulation& simulation, RunDriverOptions options);
    ~RunDriver();

    /// Add a writer of the snapshot series (VTK, PNG); called at every output.
    void addSink(std::unique_ptr<SnapshotSink> sink);

    /// Run to the end time (a resumed run already there is left untouched); returns when
    /// finished. Throws SimulationError when unstable (the
    /// outputs and checkpoint written so far stay valid; summary.json then says finished = false
    /// and gives the diagnosis as stop_reason). A SIGINT or SIGTERM ends the step under way, then
    /// writes a checkpoint and throws StoppedBySignal (lbdem resume continues the run).
    void run();

private:
    [[noreturn]] void stopOnSignal(int signal);
    struct Progress;
    void startSeries(double outputInterval, double checkpointInterval);
    void writeOutput();
    void writeCheckpoint();
    void accountWork();
    void writeSummary(bool finished, const std::string& stopReason = {});
    void reportProgress(double wallSeconds, bool last);
    void closeProgressLine();

    solver::Simulation& m_simulation;
    RunDriverOptions m_options;
    std::vector<std::unique_ptr<SnapshotSink>> m_sinks;
    std::unique_ptr<Progress> m_progress;
};

} // namespace lbdem::cli
