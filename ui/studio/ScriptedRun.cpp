// Running the studio from the command line for documentation screenshots and tests.
#include "ui/studio/ScriptedRun.h"

#include "ui/studio/MainWindow.h"
#include "ui/studio/SimulationController.h"
#include "ui/studio/WindowGrab.h"

#include <QCoreApplication>
#include <QTimer>

#include <iostream>

namespace lbdem::studio {

ScriptedRun::ScriptedRun(MainWindow& window, ScriptOptions options)
    : QObject(&window), m_window(window), m_options(std::move(options)) {}

void ScriptedRun::start() {
    SimulationController& controller = m_window.controller();
    connect(&m_window, &MainWindow::snapshotShown, this, &ScriptedRun::onShown);
    connect(&controller, &SimulationController::failed, this, [this](const QString& message) {
        if (m_done) return;
        m_done = true;
        std::cerr << "lbdem-studio: " << message.toStdString() << "\n";
        emit finished(1);
    });
    if (m_options.steps <= 0) {
        m_target = 0;
        return;
    }
    // The worker publishes the final state before it reports the run complete, so the target
    // may already be on screen when the step index arrives.
    connect(&controller, &SimulationController::runCompleted, this, [this](long long step) {
        m_target = step;
        if (m_window.shownSnapshot() && m_window.shownSnapshot()->step >= m_target) complete();
    });
    controller.run(m_options.steps);
}

void ScriptedRun::onShown(const solver::SnapshotPtr& snapshot) {
    if (m_target >= 0 && snapshot->step >= m_target) complete();
}

void ScriptedRun::complete() {
    if (m_done) return;
    m_done = true;
    // Let the layout and the view settle for one event-loop turn before grabbing.
    QTimer::singleShot(0, this, [this] {
        int code = 0;
        if (!m_options.screenshot.isEmpty()) {
            const QImage image = grabWindow(&m_window);
            if (image.save(m_options.screenshot, "PNG")) {
                std::cout << "wrote " << m_options.screenshot.toStdString() << " (" << image.width()
                          << " x " << image.height() << ")\n";
            } else {
                std::cerr << "lbdem-studio: cannot write the screenshot "
                          << m_options.screenshot.toStdString() << ".\n";
                code = 1;
            }
        }
        emit finished(code);
    });
}

} // namespace lbdem::studio
