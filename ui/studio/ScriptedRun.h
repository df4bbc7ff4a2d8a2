// The scripted mode of the studio: run N steps, wait for the last frame, save a screenshot.
#pragma once

#include "solver/scene/Snapshot.h"

#include <QObject>
#include <QString>

namespace lbdem::studio {

class MainWindow;

/// What `lbdem-studio CASE --run-steps N --screenshot FILE --quit` asks for.
struct ScriptOptions {
    long long steps = 0; ///< steps to run (0: just show the start)
    QString screenshot;  ///< PNG of the whole window, empty for none
    bool quit = false;   ///< leave once the screenshot is saved
};

/// Drives a MainWindow whose case is already set: starts the run on the worker, waits until the
/// snapshot of the last step has been drawn, saves grabWindow() and emits finished().
class ScriptedRun : public QObject {
    Q_OBJECT
public:
    ScriptedRun(MainWindow& window, ScriptOptions options);

    /// Begin (call once the window is shown).
    void start();

signals:
    /// The script is done; exitCode 0 on success, 1 when the run failed or the image was not
    /// written (the reason went to stderr).
    void finished(int exitCode);

private:
    void onShown(const solver::SnapshotPtr& snapshot);
    void complete();

    MainWindow& m_window;
    ScriptOptions m_options;
    long long m_target = -1; ///< step index whose frame ends the script; -1 until known
    bool m_done = false;
};

} // namespace lbdem::studio
