// The GUI-side handle of the solver thread: owns the QThread and the SimulationWorker on it.
#pragma once

#include "solver/scene/CaseSpec.h"
#include "ui/studio/StudioTypes.h"

#include <QObject>
#include <QThread>

#include <functional>
#include <optional>

namespace lbdem::studio {

class SimulationWorker;

/// Every call posts a request to the worker and returns at once; results come back as queued
/// signals on the GUI thread. Whoever shows a snapshot calls releaseFrame() when done with it,
/// which lets the worker send the next one (frames are skipped, never queued).
class SimulationController : public QObject {
    Q_OBJECT
public:
    /// Start the solver thread (with no case loaded yet).
    explicit SimulationController(QObject* parent = nullptr);
    /// Shuts the thread down: see shutdown().
    ~SimulationController() override;

    /// Discard the current run and build spec from its start (edits apply here).
    void load(const solver::CaseSpec& spec);
    /// Rebuild the case last loaded, from its start.
    void reset();
    /// Run until paused or finished, or (steps > 0) for that many more steps.
    void run(long long steps = 0);
    /// Pause after the current batch.
    void pause();
    /// Take one step while paused.
    void step();
    /// The GUI is done with the last snapshot it received. With idleMs > 0 the next frame may
    /// be sent only after that pause: a GUI whose drawing is slow (software OpenGL) passes its
    /// drawing time, so that at most about half of its time goes to frames and input events
    /// still get through between them.
    void releaseFrame(int idleMs = 0);
    /// Request stop, quit the thread's event loop and wait for it (at most one batch);
    /// the worker and its Simulation are destroyed on their own thread. Idempotent.
    void shutdown();

    /// True while the solver thread runs (false after shutdown()).
    bool isThreadRunning() const { return m_thread.isRunning(); }
    /// The last state the worker reported.
    RunState state() const { return m_state; }
    /// The case last loaded, if any.
    const std::optional<solver::CaseSpec>& loadedCase() const { return m_case; }

signals:
    /// Forwarded from the worker; see SimulationWorker.
    void loaded(lbdem::solver::Plan plan);
    void snapshotReady(lbdem::solver::SnapshotPtr snapshot);
    void progressed(lbdem::studio::RunProgress progress);
    void stateChanged(lbdem::studio::RunState state);
    void failed(QString message);
    void runCompleted(long long step);

private:
    /// Queue request to run on the worker thread (dropped after shutdown).
    void post(std::function<void(SimulationWorker&)> request);

    QThread m_thread;
    SimulationWorker* m_worker = nullptr; ///< lives on m_thread; deleted when it finishes
    RunState m_state = RunState::Empty;
    std::optional<solver::CaseSpec> m_case;
};

} // namespace lbdem::studio
