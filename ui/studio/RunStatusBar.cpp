// Formatting the run's numbers for the status line.
#include "ui/studio/RunStatusBar.h"

#include <QLabel>

namespace lbdem::studio {

RunStatusBar::RunStatusBar(QWidget* parent) : QStatusBar(parent) {
    m_probe = new QLabel;
    m_state = new QLabel;
    m_time = new QLabel;
    m_speed = new QLabel;
    m_numbers = new QLabel;
    m_warnings = new QLabel;
    m_warnings->setStyleSheet("color: #9a5b00;");
    // A long probe line is cut, rather than widening the window as the mouse moves.
    m_probe->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    addWidget(m_probe, 1);
    for (QLabel* label : {m_state, m_time, m_speed, m_numbers, m_warnings})
        addPermanentWidget(label);
    setState(RunState::Empty);
}

void RunStatusBar::setPlan(const solver::Plan& plan) {
    m_numbers->setText(plan.has_fluid ? tr("tau %1, Mach %2, %3 x %4 nodes")
                                            .arg(plan.tau, 0, 'f', 4)
                                            .arg(plan.mach, 0, 'f', 3)
                                            .arg(plan.nx)
                                            .arg(plan.ny)
                                      : tr("dry: no fluid"));
    m_warningList.clear();
    for (const auto& warning : plan.warnings)
        m_warningList << QString::fromStdString(warning);
    showWarnings();
    m_time->setText(tr("t/\u03c4c 0.000"));
    m_speed->clear();
}

void RunStatusBar::setProgress(const RunProgress& progress) {
    m_time->setText(
        tr("step %1, t/\u03c4c %2").arg(progress.step).arg(progress.time_over_tc, 0, 'f', 3));
    if (progress.steps_per_second > 0)
        m_speed->setText(tr("%1 steps/s, %2 MLUPS")
                             .arg(progress.steps_per_second, 0, 'f', 1)
                             .arg(progress.mlups, 0, 'f', 2));
    else
        m_speed->clear();
}

void RunStatusBar::setState(RunState state) {
    m_state->setText(runStateName(state));
}

void RunStatusBar::addWarning(const QString& warning) {
    m_warningList << warning;
    showWarnings();
}

void RunStatusBar::setProbe(const QString& text) {
    m_probe->setText(text);
}

QString RunStatusBar::summary() const {
    QStringList parts;
    for (QLabel* label : {m_state, m_time, m_speed, m_numbers, m_warnings})
        if (!label->text().isEmpty()) parts << label->text();
    return parts.join(" | ");
}

void RunStatusBar::showWarnings() {
    m_warnings->setText(m_warningList.isEmpty() ? QString()
                                                : tr("%n warning(s)", "", m_warningList.size()));
    m_warnings->setToolTip(m_warningList.join("\n"));
}

} // namespace lbdem::studio
