// The object that owns a Simulation and steps it in short batches on the solver thread.
#pragma once

#include "solver/scene/CaseSpec.h"
#include "ui/studio/StudioTypes.h"

#include <QElapsedTimer>
#include <QObject>
#include <QString>

#include <memory>

namespace lbdem::solver {
class Simulation;
}

namespace lbdem::studio {

/// Lives on the thread of a SimulationController (docs/style.md, Style §3): every slot runs there,
/// between batches, so pause, step and reset need no lock. A batch steps for about kBatchMs and
/// then re-queues itself. A snapshot is published at most every kFrameIntervalMs and only after the
/// GUI released the previous one (releaseFrame): frames are skipped, never queued.
/// The case's run.threads is applied on this thread (OpenMP's thread count is per thread, so
/// the lattice's team is sized here, not by the GUI thread).
class SimulationWorker : public QObject {
    Q_OBJECT
public:
    static constexpr int kBatchMs = 15;         ///< stepping time between two looks at the queue
    static constexpr int kFrameIntervalMs = 33; ///< at most ~30 snapshots a second
    static constexpr int kProgressIntervalMs = 250; ///< status figures four times a second
    /// An ETA needs this many steps and this much wall time since the run (re)started: the
    /// first steps include warm-up and would give a wild estimate.
    static constexpr int kEtaMinSteps = 10;
    static constexpr int kEtaMinMs = 1000;

    /// The OpenMP team size for a case asking for `requested` threads: that many, or for 0 all
    /// cores but one (so that the window stays fluid), at least 1.
    static int teamSizeFor(int requested);

    explicit SimulationWorker(QObject* parent = nullptr);
    ~SimulationWorker() override;

    /// Build a fresh Simulation of spec (discarding the current one) and publish its start.
    void load(const solver::CaseSpec& spec);

public slots:
    /// Step in batches until paused, finished, or (steps > 0) that many more steps are taken.
    void run(long long steps);
    /// Stop stepping after the current batch and publish the state reached.
    void pause();
    /// Take exactly one step (when not running) and publish it.
    void stepOnce();
    /// The GUI is done with the last published snapshot; the next one may be sent.
    void releaseFrame();

signals:
    /// A new Simulation was built from a case; plan holds its numbers.
    void loaded(lbdem::solver::Plan plan);
    /// The newest state; the next one waits until releaseFrame().
    void snapshotReady(lbdem::solver::SnapshotPtr snapshot);
    /// Step count and throughput, a few times a second while running.
    void progressed(lbdem::studio::RunProgress progress);
    /// The run state changed.
    void stateChanged(lbdem::studio::RunState state);
    /// Building or stepping failed; message is one sentence for the user.
    void failed(QString message);
    /// A run(steps > 0) took its last step, or met the end of the case first; step is the
    /// step index reached.
    void runCompleted(long long step);

private:
    void runBatch();
    void queueBatch();
    bool advance();
    void stopRunning(RunState next);
    void publish();
    void reportProgress(bool force);
    void setState(RunState state);
    void applyThreads(int requested);
    double etaSeconds(double timeOverTc, long long step) const;

    std::unique_ptr<solver::Simulation> m_simulation;
    RunState m_state = RunState::Empty;
    long long m_stepsLeft = 0;    ///< steps still to take in this run; <= 0: until finished
    bool m_batchQueued = false;   ///< a runBatch is waiting in the event queue
    bool m_frameInFlight = false; ///< the GUI has not released the last snapshot yet
    bool m_dirty = false;         ///< the state changed since the last published snapshot
    double m_nodesPerStep = 0;    ///< lattice nodes updated per step, for MLUPS
    long long m_stepAtProgress = 0;
    int m_threads = 0;         ///< team size measured on this thread when the run last started
    double m_endTc = 0;        ///< t / tau_c at the end of the case
    double m_tcAtRunStart = 0; ///< t / tau_c and step when the current run started
    long long m_stepAtRunStart = 0;
    QElapsedTimer m_sinceRunStart;
    QElapsedTimer m_sincePublish;
    QElapsedTimer m_sinceProgress;
};

} // namespace lbdem::studio
