// The status line: run state, t/tau_c and its end, steps/s, MLUPS, threads, ETA, tau, Mach,
// grid noise, warnings and the probe.
#pragma once

#include "ui/studio/StudioTypes.h"

#include <QStatusBar>
#include <QStringList>

#include <map>
#include <string>

class QLabel;
class QTimer;

namespace lbdem::studio {

/// Permanent labels on the right for the numbers of the run; the probe text and notices on the
/// left. QStatusBar::showMessage is never used: a temporary message hides every non-permanent
/// widget, the probe among them, for as long as it stands.
class RunStatusBar : public QStatusBar {
    Q_OBJECT
public:
    explicit RunStatusBar(QWidget* parent = nullptr);

    /// The numbers of a freshly built case: tau, Mach and the plan's warnings.
    void setPlan(const solver::Plan& plan);
    /// Step, t/tau_c of now and of the end, steps/s, MLUPS, threads and the ETA once known.
    void setProgress(const RunProgress& progress);
    /// The fluid's grid-scale share of vorticity (timeseries column fluid_grid_noise) of the
    /// frame shown; cleared when the frame has none.
    void setGridNoise(const std::map<std::string, double>& metrics);
    /// The run state word.
    void setState(RunState state);
    /// Add a warning (also shown as the tooltip of the warnings label).
    void addWarning(const QString& warning);
    /// The probe line (what lies under the cursor).
    void setProbe(const QString& text);
    /// Show or hide the mark that the editor holds edits the running case does not have yet.
    void setPendingEdits(bool pending);
    /// A one-line notice beside the probe (full text in its tooltip); it goes after timeoutMs,
    /// or with timeoutMs = 0 when the next case is built.
    void showNotice(const QString& text, int timeoutMs = 0);
    /// The probe label (for tests: it must stay visible whatever else the status line shows).
    const QLabel* probeLabel() const { return m_probe; }
    /// The notice shown now (empty when none).
    QString notice() const;
    /// True while the pending-edits mark is shown.
    bool pendingEditsShown() const;
    /// Everything the labels show, joined (for tests and logs).
    QString summary() const;
    /// A wall-time span as the status line shows it ("42 s", "3 min 07 s", "2 h 05 min").
    static QString formatDuration(double seconds);

private:
    void showWarnings();

    QLabel* m_state;
    QLabel* m_time;
    QLabel* m_speed;
    QLabel* m_numbers;
    QLabel* m_noise;
    QLabel* m_warnings;
    QLabel* m_probe;
    QLabel* m_notice;
    QLabel* m_pending;
    QTimer* m_noticeTimer;
    QStringList m_warningList;
};

} // namespace lbdem::studio
