// Batched stepping, frame skipping and progress reports of the solver thread.
#include "ui/studio/SimulationWorker.h"

#include "solver/core/InputError.h"
#include "solver/core/OpenMp.h"
#include "solver/scene/Plan.h"
#include "solver/scene/Simulation.h"

#include <QMetaObject>
#include <QThread>

#include <algorithm>
#include <exception>

namespace lbdem::studio {

SimulationWorker::SimulationWorker(QObject* parent) : QObject(parent) {
    m_sincePublish.start();
    m_sinceProgress.start();
}

// Out of line: Simulation is only forward-declared in the header.
SimulationWorker::~SimulationWorker() = default;

int SimulationWorker::teamSizeFor(int requested) {
    return requested > 0 ? requested : std::max(1, solver::ompProcessorCount() - 1);
}

void SimulationWorker::load(const solver::CaseSpec& spec) {
    m_simulation.reset();
    m_stepsLeft = 0;
    try {
        // Before building: packing and lattice set-up run parallel loops too.
        applyThreads(spec.run.threads);
        const solver::Plan plan = solver::makePlan(spec);
        m_simulation = std::make_unique<solver::Simulation>(spec, plan);
        m_nodesPerStep = plan.has_fluid ? double(plan.nx) * double(plan.ny) : 0.0;
        m_endTc = plan.tc_s > 0 ? plan.end_time_s / plan.tc_s : plan.end_time_s;
        m_sinceRunStart.invalidate();
        emit loaded(plan);
    } catch (const std::exception& error) {
        m_simulation.reset();
        setState(RunState::Failed);
        emit failed(QString::fromStdString(error.what()));
        return;
    }
    setState(RunState::Ready);
    m_dirty = true;
    if (!m_frameInFlight) publish();
    reportProgress(true);
}

void SimulationWorker::run(long long steps) {
    if (!m_simulation || m_state == RunState::Failed) return;
    if (m_simulation->finished()) {
        setState(RunState::Finished);
        if (steps > 0) emit runCompleted(m_simulation->stepIndex());
        return;
    }
    m_stepsLeft = steps;
    if (m_state != RunState::Running) {
        applyThreads(m_simulation->spec().run.threads);
        m_stepAtProgress = m_simulation->stepIndex();
        m_sinceProgress.restart();
        m_stepAtRunStart = m_stepAtProgress;
        m_tcAtRunStart = m_simulation->timeOverTc();
        m_sinceRunStart.start();
    }
    setState(RunState::Running);
    queueBatch();
}

void SimulationWorker::pause() {
    if (m_state == RunState::Running) stopRunning(RunState::Paused);
}

void SimulationWorker::stepOnce() {
    if (!m_simulation || m_state == RunState::Running || m_state == RunState::Failed) return;
    if (m_simulation->finished()) return;
    if (!advance()) return;
    setState(m_simulation->finished() ? RunState::Finished : RunState::Paused);
    m_dirty = true;
    if (!m_frameInFlight) publish();
    reportProgress(true);
}

void SimulationWorker::releaseFrame() {
    m_frameInFlight = false;
    // While running the next batch publishes; otherwise the final state must still be shown.
    if (m_dirty && m_simulation && m_state != RunState::Running) publish();
}

void SimulationWorker::queueBatch() {
    if (m_batchQueued) return;
    m_batchQueued = true;
    QMetaObject::invokeMethod(this, &SimulationWorker::runBatch, Qt::QueuedConnection);
}

void SimulationWorker::runBatch() {
    m_batchQueued = false;
    if (m_state != RunState::Running || !m_simulation) return;
    const QThread* thread = QThread::currentThread();
    QElapsedTimer batch;
    batch.start();
    bool reachedCount = false;
    do {
        if (!advance()) return;
        if (m_stepsLeft > 0 && --m_stepsLeft == 0) reachedCount = true;
    } while (!reachedCount && !m_simulation->finished() && batch.elapsed() < kBatchMs &&
             !thread->isInterruptionRequested());
    m_dirty = true;
    if (m_simulation->finished()) {
        // A counted run that meets the end of the case ends there too.
        const bool counted = m_stepsLeft > 0 || reachedCount;
        stopRunning(RunState::Finished);
        if (counted) emit runCompleted(m_simulation->stepIndex());
        return;
    }
    if (reachedCount) {
        stopRunning(RunState::Paused);
        emit runCompleted(m_simulation->stepIndex());
        return;
    }
    reportProgress(false);
    if (!m_frameInFlight && m_sincePublish.elapsed() >= kFrameIntervalMs) publish();
    if (!thread->isInterruptionRequested()) queueBatch();
}

bool SimulationWorker::advance() {
    try {
        m_simulation->step();
        return true;
    } catch (const std::exception& error) {
        m_stepsLeft = 0;
        setState(RunState::Failed);
        emit failed(QString::fromStdString(error.what()));
        m_dirty = true;
        if (!m_frameInFlight) publish();
        return false;
    }
}

void SimulationWorker::stopRunning(RunState next) {
    m_stepsLeft = 0;
    // No ETA once stopped, and the pace of a later run is measured afresh (a pause must not
    // count as running time).
    m_sinceRunStart.invalidate();
    reportProgress(true);
    setState(next);
    m_dirty = true;
    if (!m_frameInFlight) publish();
}

void SimulationWorker::publish() {
    if (!m_simulation) return;
    solver::SnapshotPtr snapshot;
    try {
        snapshot = m_simulation->snapshot();
    } catch (const std::exception& error) {
        // No exception may cross Qt's event loop: a failing snapshot stops the run instead.
        m_stepsLeft = 0;
        m_dirty = false;
        setState(RunState::Failed);
        emit failed(QString::fromStdString(error.what()));
        return;
    }
    emit snapshotReady(snapshot);
    m_frameInFlight = true;
    m_dirty = false;
    m_sincePublish.restart();
}

void SimulationWorker::reportProgress(bool force) {
    if (!m_simulation) return;
    const qint64 elapsedMs = m_sinceProgress.elapsed();
    if (!force && elapsedMs < kProgressIntervalMs) return;
    RunProgress progress;
    progress.step = m_simulation->stepIndex();
    progress.time_over_tc = m_simulation->timeOverTc();
    progress.end_time_over_tc = m_endTc;
    progress.threads = m_threads;
    progress.eta_seconds = etaSeconds(progress.time_over_tc, progress.step);
    if (elapsedMs > 0 && progress.step > m_stepAtProgress) {
        const double seconds = elapsedMs / 1000.0;
        progress.steps_per_second = double(progress.step - m_stepAtProgress) / seconds;
        progress.mlups = progress.steps_per_second * m_nodesPerStep / 1e6;
    }
    m_stepAtProgress = progress.step;
    m_sinceProgress.restart();
    emit progressed(progress);
}

void SimulationWorker::applyThreads(int requested) {
    solver::ompSetThreads(teamSizeFor(requested));
    m_threads = solver::ompTeamSize(); // the team the kernels get
}

double SimulationWorker::etaSeconds(double timeOverTc, long long step) const {
    if (!m_sinceRunStart.isValid()) return -1;
    const qint64 elapsedMs = m_sinceRunStart.elapsed();
    const double advanced = timeOverTc - m_tcAtRunStart;
    if (step - m_stepAtRunStart < kEtaMinSteps || elapsedMs < kEtaMinMs || advanced <= 0) return -1;
    return std::max(0.0, m_endTc - timeOverTc) * (elapsedMs / 1000.0) / advanced;
}

void SimulationWorker::setState(RunState state) {
    if (state == m_state) return;
    m_state = state;
    emit stateChanged(state);
}

} // namespace lbdem::studio
