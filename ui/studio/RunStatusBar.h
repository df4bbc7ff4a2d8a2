// The status line: run state, t/tau_c, steps/s, MLUPS, tau, Mach, warnings and the probe.
#pragma once

#include "ui/studio/StudioTypes.h"

#include <QStatusBar>
#include <QStringList>

class QLabel;

namespace lbdem::studio {

/// Permanent labels on the right for the numbers of the run; the probe text on the left.
class RunStatusBar : public QStatusBar {
    Q_OBJECT
public:
    explicit RunStatusBar(QWidget* parent = nullptr);

    /// The numbers of a freshly built case: tau, Mach and the plan's warnings.
    void setPlan(const solver::Plan& plan);
    /// Step, t/tau_c, steps/s and MLUPS.
    void setProgress(const RunProgress& progress);
    /// The run state word.
    void setState(RunState state);
    /// Add a warning (also shown as the tooltip of the warnings label).
    void addWarning(const QString& warning);
    /// The probe line (what lies under the cursor).
    void setProbe(const QString& text);
    /// Everything the labels show, joined (for tests and logs).
    QString summary() const;

private:
    void showWarnings();

    QLabel* m_state;
    QLabel* m_time;
    QLabel* m_speed;
    QLabel* m_numbers;
    QLabel* m_warnings;
    QLabel* m_probe;
    QStringList m_warningList;
};

} // namespace lbdem::studio
