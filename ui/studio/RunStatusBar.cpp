// Formatting the run's numbers for the status line.
#include "ui/studio/RunStatusBar.h"

#include <QLabel>
#include <QTimer>

#include <algorithm>
#include <cmath>

namespace lbdem::studio {

RunStatusBar::RunStatusBar(QWidget* parent) : QStatusBar(parent) {
    m_probe = new QLabel;
    m_state = new QLabel;
    m_time = new QLabel;
    m_speed = new QLabel;
    m_numbers = new QLabel;
    m_noise = new QLabel;
    m_noise->setToolTip(tr("Grid-scale share of the fluid's vorticity away from solids: "
                           "0 for a smooth flow, about 1 for node-to-node noise"));
    m_warnings = new QLabel;
    m_notice = new QLabel;
    m_pending = new QLabel(tr("edits pending: Reset (Ctrl+R) applies them"));
    m_noticeTimer = new QTimer(this);
    m_noticeTimer->setSingleShot(true);
    connect(m_noticeTimer, &QTimer::timeout, this, [this] { showNotice(QString()); });
    m_probe->setObjectName("probe");
    m_notice->setObjectName("notice");
    m_pending->setObjectName("pendingEdits");
    m_warnings->setStyleSheet("color: #9a5b00;");
    m_pending->setStyleSheet("color: #9a5b00;");
    m_pending->setVisible(false);
    m_notice->setVisible(false);
    // A long probe line or notice is cut, rather than widening the window as the mouse moves.
    m_probe->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_notice->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    addWidget(m_probe, 2);
    addWidget(m_notice, 1);
    for (QLabel* label : {m_pending, m_state, m_time, m_speed, m_numbers, m_noise, m_warnings})
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
    if (!m_noticeTimer->isActive()) showNotice(QString());
}

void RunStatusBar::setProgress(const RunProgress& progress) {
    QString time =
        tr("step %1, t/\u03c4c %2").arg(progress.step).arg(progress.time_over_tc, 0, 'f', 3);
    if (progress.end_time_over_tc > 0)
        time += tr(" of %1 (%2 %)")
                    .arg(progress.end_time_over_tc, 0, 'f', 3)
                    .arg(std::min(100.0, 100.0 * progress.time_over_tc / progress.end_time_over_tc),
                         0, 'f', 0);
    m_time->setText(time);
    QStringList speed;
    if (progress.steps_per_second > 0)
        speed << tr("%1 steps/s, %2 MLUPS")
                     .arg(progress.steps_per_second, 0, 'f', 1)
                     .arg(progress.mlups, 0, 'f', 2);
    if (progress.threads > 0)
        speed << (progress.threads == 1 ? tr("1 thread") : tr("%1 threads").arg(progress.threads));
    if (progress.eta_seconds >= 0) speed << tr("ETA %1").arg(formatDuration(progress.eta_seconds));
    m_speed->setText(speed.join(", "));
}

QString RunStatusBar::formatDuration(double seconds) {
    const long long total = std::llround(seconds);
    if (total < 60) return tr("%1 s").arg(total);
    if (total < 3600) return tr("%1 min %2 s").arg(total / 60).arg(total % 60, 2, 10, QChar('0'));
    return tr("%1 h %2 min").arg(total / 3600).arg(total / 60 % 60, 2, 10, QChar('0'));
}

void RunStatusBar::setGridNoise(const std::map<std::string, double>& metrics) {
    const auto found = metrics.find("fluid_grid_noise");
    if (found == metrics.end() || !std::isfinite(found->second))
        m_noise->clear();
    else
        m_noise->setText(tr("grid noise %1").arg(found->second, 0, 'f', 3));
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

void RunStatusBar::setPendingEdits(bool pending) {
    m_pending->setVisible(pending);
}

void RunStatusBar::showNotice(const QString& text, int timeoutMs) {
    m_noticeTimer->stop();
    m_notice->setText(text);
    m_notice->setToolTip(text);
    m_notice->setVisible(!text.isEmpty());
    if (!text.isEmpty() && timeoutMs > 0) m_noticeTimer->start(timeoutMs);
}

QString RunStatusBar::notice() const {
    return m_notice->text();
}

bool RunStatusBar::pendingEditsShown() const {
    return !m_pending->isHidden();
}

QString RunStatusBar::summary() const {
    QStringList parts;
    for (QLabel* label : {m_state, m_time, m_speed, m_numbers, m_noise, m_warnings})
        if (!label->text().isEmpty()) parts << label->text();
    return parts.join(" | ");
}

void RunStatusBar::showWarnings() {
    m_warnings->setText(m_warningList.isEmpty() ? QString()
                                                : tr("%n warning(s)", "", m_warningList.size()));
    m_warnings->setToolTip(m_warningList.join("\n"));
}

} // namespace lbdem::studio
