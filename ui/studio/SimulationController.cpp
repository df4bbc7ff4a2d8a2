// Posting requests to the solver thread and forwarding its results to the GUI thread.
#include "ui/studio/SimulationController.h"

#include "ui/studio/SimulationWorker.h"

#include <QMetaObject>
#include <QTimer>

namespace lbdem::studio {

SimulationController::SimulationController(QObject* parent) : QObject(parent) {
    registerStudioTypes();
    m_thread.setObjectName("lbdem-solver");
    m_worker = new SimulationWorker;
    m_worker->moveToThread(&m_thread);
    connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    connect(m_worker, &SimulationWorker::loaded, this, &SimulationController::loaded);
    connect(m_worker, &SimulationWorker::snapshotReady, this, &SimulationController::snapshotReady);
    connect(m_worker, &SimulationWorker::progressed, this, &SimulationController::progressed);
    connect(m_worker, &SimulationWorker::failed, this, &SimulationController::failed);
    connect(m_worker, &SimulationWorker::runCompleted, this, &SimulationController::runCompleted);
    connect(m_worker, &SimulationWorker::stateChanged, this, [this](RunState state) {
        m_state = state;
        emit stateChanged(state);
    });
    m_thread.start();
}

SimulationController::~SimulationController() {
    shutdown();
}

void SimulationController::load(const solver::CaseSpec& spec) {
    m_case = spec;
    post([spec](SimulationWorker& worker) { worker.load(spec); });
}

void SimulationController::reset() {
    if (m_case) load(*m_case);
}

void SimulationController::run(long long steps) {
    post([steps](SimulationWorker& worker) { worker.run(steps); });
}

void SimulationController::pause() {
    post([](SimulationWorker& worker) { worker.pause(); });
}

void SimulationController::step() {
    post([](SimulationWorker& worker) { worker.stepOnce(); });
}

void SimulationController::releaseFrame(int idleMs) {
    if (idleMs <= 0) {
        post([](SimulationWorker& worker) { worker.releaseFrame(); });
        return;
    }
    QTimer::singleShot(idleMs, this,
                       [this] { post([](SimulationWorker& worker) { worker.releaseFrame(); }); });
}

void SimulationController::shutdown() {
    if (!m_thread.isRunning()) return;
    // The worker checks the interruption flag between steps, so the current batch ends early;
    // quit() then ends the event loop and the finished signal deletes the worker there.
    m_thread.requestInterruption();
    m_thread.quit();
    m_thread.wait();
    m_worker = nullptr;
}

void SimulationController::post(std::function<void(SimulationWorker&)> request) {
    if (!m_worker) return;
    QMetaObject::invokeMethod(
        m_worker, [worker = m_worker, request = std::move(request)] { request(*worker); },
        Qt::QueuedConnection);
}

} // namespace lbdem::studio
