// The studio's main window: it assembles the editor, view, plots, toolbar and status line.
#pragma once

#include "solver/scene/CaseSpec.h"
#include "ui/studio/StudioTypes.h"

#include <QMainWindow>
#include <QString>

#include <memory>

class QAction;
class QMenu;

namespace lbdem::vis {
class VtkRunWriter;
}
namespace lbdem::io {
class RunLock;
}

namespace lbdem::studio {

class CaseEditor;
class LivePlots;
class LiveView;
class RunStatusBar;
class SimulationController;
class ViewControls;

/// Wires widgets to the SimulationController; behaviour lives in the parts it assembles.
/// Settings (geometry, dock layout, recent files, layers, colourings and colour ranges) persist
/// through QSettings.
class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Load the case file at path into the editor and the solver; on bad input returns false
    /// and sets error to one sentence naming file, line and key.
    bool openCaseFile(const QString& path, QString* error = nullptr);
    /// Show spec in the editor and build it on the solver thread (source names it in the title).
    void setCase(const solver::CaseSpec& spec, const QString& source);

    /// Shade behind the live curves the band of the case's finished ensemble in the sweep folder
    /// (its NAME_sK runs), now and for every case loaded later; an empty folder removes it.
    /// Returns how many runs the band holds for the current case (0: none there).
    int setEnsembleFolder(const QString& folder);

    SimulationController& controller() { return *m_controller; }
    CaseEditor& caseEditor() { return *m_editor; }
    LiveView& liveView() { return *m_view; }
    ViewControls& viewControls() { return *m_controls; }
    LivePlots& livePlots() { return *m_plots; }
    RunStatusBar& runStatus() { return *m_status; }
    QAction* runAction() const { return m_run; }
    QAction* pauseAction() const { return m_pause; }
    QAction* stepAction() const { return m_step; }
    QAction* resetAction() const { return m_reset; }
    /// The snapshot on screen (null before the first).
    const solver::SnapshotPtr& shownSnapshot() const { return m_shown; }
    /// True while the editor holds edits that the case last built does not have.
    bool caseChangedSinceLoad() const { return m_caseChangedSinceLoad; }

signals:
    /// snapshot was drawn in the view and added to the plots.
    void snapshotShown(lbdem::solver::SnapshotPtr snapshot);

protected:
    /// Stops the solver thread (request stop, quit, wait) and saves the settings.
    void closeEvent(QCloseEvent* event) override;

private:
    void createActions();
    void createMenus();
    void connectController();
    void showSnapshot(const solver::SnapshotPtr& snapshot);
    void startRun();
    void resetRun();
    void updateActions();
    void setCaseChangedSinceLoad(bool changed);
    void rebuildRecentMenu();
    void openDialog();
    void saveDialog();
    void exportPng();
    void exportCsv();
    void ensembleDialog();
    int showEnsembleBand();
    void toggleVtkRecording(bool on);
    void restoreSettings();
    void saveSettings() const;

    SimulationController* m_controller;
    CaseEditor* m_editor;
    LiveView* m_view;
    ViewControls* m_controls;
    LivePlots* m_plots;
    RunStatusBar* m_status;
    QAction *m_open = nullptr, *m_save = nullptr, *m_quit = nullptr;
    QAction *m_run = nullptr, *m_pause = nullptr, *m_step = nullptr, *m_reset = nullptr;
    QAction *m_exportPng = nullptr, *m_exportCsv = nullptr, *m_recordVtk = nullptr;
    QAction* m_ensemble = nullptr;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_presetMenu = nullptr;
    solver::SnapshotPtr m_shown;
    std::unique_ptr<io::RunLock> m_recordLock; ///< the recording folder's, while recording
    std::unique_ptr<vis::VtkRunWriter> m_vtkWriter;
    QString m_casePath;
    std::string m_caseName;
    QString m_ensembleFolder;
    bool m_caseChangedSinceLoad = false; ///< the editor differs from the case last built
};

} // namespace lbdem::studio
