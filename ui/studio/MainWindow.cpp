// Assembling the studio window: docks, toolbar, menus, shortcuts and the controller's signals.
#include "ui/studio/MainWindow.h"

#include "solver/core/InputError.h"
#include "solver/io/CaseLoader.h"
#include "solver/io/CaseWriter.h"
#include "solver/io/RunLock.h"
#include "solver/scene/CaseSchema.h"
#include "ui/studio/CaseEditor.h"
#include "ui/studio/CaseFiles.h"
#include "ui/studio/LivePlots.h"
#include "ui/studio/LiveView.h"
#include "ui/studio/RunStatusBar.h"
#include "ui/studio/SimulationController.h"
#include "ui/studio/ViewControls.h"
#include "ui/studio/ViewSettings.h"
#include "ui/vis/VtkRunWriter.h"

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QSplitter>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>

namespace lbdem::studio {

namespace {

/// True when every declared key has the same value in a and b (what the editor can change).
bool sameKeys(const solver::CaseSpec& a, const solver::CaseSpec& b) {
    const auto& params = solver::CaseSchema::instance().params();
    return std::all_of(params.begin(), params.end(),
                       [&](const solver::ParamDecl& decl) { return decl.get(a) == decl.get(b); });
}

/// How long a notice of the ensemble band stays beside the probe.
constexpr int kEnsembleNoticeMs = 10000;

} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), m_controller(new SimulationController(this)), m_editor(new CaseEditor),
      m_view(new LiveView), m_controls(new ViewControls), m_plots(new LivePlots),
      m_status(new RunStatusBar) {
    setWindowTitle(tr("lbdem studio"));
    auto* viewPane = new QWidget;
    auto* viewLayout = new QVBoxLayout(viewPane);
    viewLayout->setContentsMargins(0, 0, 0, 0);
    viewLayout->setSpacing(0);
    viewLayout->addWidget(m_controls);
    viewLayout->addWidget(m_view, 1);
    auto* splitter = new QSplitter(Qt::Vertical);
    splitter->setObjectName("viewPlotSplitter");
    splitter->addWidget(viewPane);
    splitter->addWidget(m_plots);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 1);
    setCentralWidget(splitter);

    auto* dock = new QDockWidget(tr("Case"), this);
    dock->setObjectName("caseDock");
    dock->setWidget(m_editor);
    m_editor->setMinimumWidth(300);
    addDockWidget(Qt::LeftDockWidgetArea, dock);
    setStatusBar(m_status);

    createActions();
    createMenus();
    connectController();
    connect(m_controls, &ViewControls::layersChanged, m_view, &LiveView::setLayers);
    connect(m_controls, &ViewControls::resetCameraRequested, m_view, &LiveView::resetCamera);
    connect(m_controls, &ViewControls::chainThresholdChanged, m_view, &LiveView::setChainThreshold);
    connect(m_view, &LiveView::colorRangesShown, m_controls, &ViewControls::showColorRanges);
    connect(m_view, &LiveView::probed, m_status, &RunStatusBar::setProbe);
    connect(m_editor, &CaseEditor::caseEdited, this, [this] {
        // Compared with the case built, so that an edit undone by hand is no edit.
        const auto& built = m_controller->loadedCase();
        setCaseChangedSinceLoad(!m_editor->isValid() || !built ||
                                !sameKeys(m_editor->currentCase(), *built));
        updateActions();
    });
    restoreSettings();
    m_controls->setLayers(m_view->layers());
    updateActions();
}

MainWindow::~MainWindow() {
    m_controller->shutdown();
}

void MainWindow::createActions() {
    auto make = [this](const QString& text, QKeySequence key, const QString& tip) {
        auto* action = new QAction(text, this);
        action->setShortcut(key);
        action->setToolTip(QString("%1 (%2)").arg(tip, key.toString(QKeySequence::NativeText)));
        return action;
    };
    m_open = make(tr("&Open case..."), QKeySequence::Open, tr("Open a TOML case file"));
    m_save = make(tr("&Save case as..."), QKeySequence::SaveAs, tr("Save the edited case as TOML"));
    m_quit = make(tr("&Quit"), QKeySequence::Quit, tr("Stop the run and close the studio"));
    m_run = make(tr("&Run"), QKeySequence(Qt::Key_F5), tr("Run the case"));
    m_pause = make(tr("&Pause"), QKeySequence(Qt::Key_F6), tr("Pause after the current batch"));
    m_step = make(tr("S&tep"), QKeySequence(Qt::Key_F7), tr("Take one step"));
    m_reset = make(tr("R&eset"), QKeySequence(Qt::CTRL | Qt::Key_R),
                   tr("Rebuild the case from its start with the edited parameters"));
    m_exportPng = make(tr("Export view as &PNG..."), QKeySequence(Qt::CTRL | Qt::Key_E),
                       tr("Save the live view as a PNG image"));
    m_exportCsv = make(tr("Export plots as &CSV..."), QKeySequence(),
                       tr("Save the metrics of every frame shown as CSV"));
    m_recordVtk =
        make(tr("Record &VTU series..."), QKeySequence(),
             tr("Write every frame shown as VTU/VTI files with .pvd series for ParaView"));
    m_recordVtk->setCheckable(true);
    m_ensemble = make(tr("Show ensemble &band..."), QKeySequence(),
                      tr("Shade behind the live curves the min-max of this case's finished runs "
                         "in a sweep folder (lbdem sweep --seeds)"));
    connect(m_open, &QAction::triggered, this, &MainWindow::openDialog);
    connect(m_save, &QAction::triggered, this, &MainWindow::saveDialog);
    connect(m_quit, &QAction::triggered, this, &QWidget::close);
    connect(m_run, &QAction::triggered, this, &MainWindow::startRun);
    connect(m_pause, &QAction::triggered, m_controller, &SimulationController::pause);
    connect(m_step, &QAction::triggered, m_controller, &SimulationController::step);
    connect(m_reset, &QAction::triggered, this, &MainWindow::resetRun);
    connect(m_exportPng, &QAction::triggered, this, &MainWindow::exportPng);
    connect(m_exportCsv, &QAction::triggered, this, &MainWindow::exportCsv);
    connect(m_recordVtk, &QAction::toggled, this, &MainWindow::toggleVtkRecording);
    connect(m_ensemble, &QAction::triggered, this, &MainWindow::ensembleDialog);

    auto* toolbar = addToolBar(tr("Run"));
    toolbar->setObjectName("runToolbar");
    toolbar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    for (QAction* action : {m_open, m_save})
        toolbar->addAction(action);
    toolbar->addSeparator();
    for (QAction* action : {m_run, m_pause, m_step, m_reset})
        toolbar->addAction(action);
    toolbar->addSeparator();
    toolbar->addAction(m_exportPng);
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(m_open);
    m_recentMenu = file->addMenu(tr("Open &recent"));
    m_presetMenu = file->addMenu(tr("Open &preset"));
    for (const QString& preset : samplePresets()) {
        const QString path = sampleCasesDir() + "/" + preset;
        const QString folder = preset.contains('/') ? preset.section('/', 0, 0) : QString();
        QMenu* menu = m_presetMenu;
        if (!folder.isEmpty()) {
            const auto existing =
                m_presetMenu->findChildren<QMenu*>(folder, Qt::FindDirectChildrenOnly);
            menu = existing.isEmpty() ? m_presetMenu->addMenu(folder) : existing.front();
            menu->setObjectName(folder);
        }
        menu->addAction(preset.section('/', -1), this, [this, path] { openCaseFile(path); });
    }
    m_presetMenu->setEnabled(!m_presetMenu->isEmpty());
    file->addAction(m_save);
    file->addSeparator();
    for (QAction* action : {m_exportPng, m_exportCsv, m_recordVtk, m_ensemble})
        file->addAction(action);
    file->addSeparator();
    file->addAction(m_quit);
    QMenu* run = menuBar()->addMenu(tr("&Run"));
    for (QAction* action : {m_run, m_pause, m_step, m_reset})
        run->addAction(action);
    rebuildRecentMenu();
}

void MainWindow::connectController() {
    connect(m_controller, &SimulationController::snapshotReady, this, &MainWindow::showSnapshot);
    connect(m_controller, &SimulationController::loaded, this, [this](const solver::Plan& plan) {
        m_plots->clear();
        m_status->setPlan(plan);
    });
    connect(m_controller, &SimulationController::progressed, m_status, &RunStatusBar::setProgress);
    connect(m_controller, &SimulationController::stateChanged, this, [this](RunState state) {
        m_status->setState(state);
        updateActions();
    });
    connect(m_controller, &SimulationController::failed, this, [this](const QString& message) {
        m_status->addWarning(message);
        m_status->showNotice(message);
    });
}

void MainWindow::showSnapshot(const solver::SnapshotPtr& snapshot) {
    QElapsedTimer drawing;
    drawing.start();
    const bool first = !m_shown || m_shown->step > snapshot->step;
    m_shown = snapshot;
    m_view->showSnapshot(snapshot);
    if (first) m_view->resetCamera();
    m_plots->addSnapshot(*snapshot);
    m_status->setGridNoise(snapshot->metrics);
    if (m_vtkWriter) m_vtkWriter->write(*snapshot);
    // Release only after drawing: the worker sends the next frame when this one is done, and
    // not before the GUI had as much time for input as it spent drawing.
    m_controller->releaseFrame(int(drawing.elapsed()));
    emit snapshotShown(snapshot);
}

bool MainWindow::openCaseFile(const QString& path, QString* error) {
    try {
        setCase(io::loadCase(path.toStdString()), path);
        rememberCaseFile(path);
        rebuildRecentMenu();
        return true;
    } catch (const std::exception& failure) {
        const QString message = QString::fromStdString(failure.what());
        if (error)
            *error = message;
        else
            QMessageBox::warning(this, tr("Cannot open case"), message);
        return false;
    }
}

void MainWindow::setCase(const solver::CaseSpec& spec, const QString& source) {
    m_casePath = source;
    setWindowTitle(tr("%1 - lbdem studio").arg(QFileInfo(source).fileName()));
    m_editor->setCase(spec);
    m_caseName = spec.name;
    showEnsembleBand();
    m_controller->load(spec);
    setCaseChangedSinceLoad(false);
    updateActions();
}

void MainWindow::startRun() {
    if (!m_editor->isValid()) return;
    if (m_controller->state() == RunState::Empty || m_controller->state() == RunState::Failed) {
        m_controller->load(m_editor->currentCase());
        setCaseChangedSinceLoad(false);
    }
    m_controller->run();
}

void MainWindow::resetRun() {
    if (!m_editor->isValid()) return;
    m_controller->load(m_editor->currentCase());
    setCaseChangedSinceLoad(false);
    updateActions();
}

void MainWindow::setCaseChangedSinceLoad(bool changed) {
    m_caseChangedSinceLoad = changed;
    m_status->setPendingEdits(changed);
}

void MainWindow::updateActions() {
    const RunState state = m_controller->state();
    const bool valid = m_editor->isValid();
    const bool running = state == RunState::Running;
    m_run->setEnabled(valid && !running && state != RunState::Finished);
    m_pause->setEnabled(running);
    m_step->setEnabled(!running && (state == RunState::Ready || state == RunState::Paused));
    m_reset->setEnabled(valid);
    m_save->setEnabled(valid);
}

void MainWindow::rebuildRecentMenu() {
    m_recentMenu->clear();
    for (const QString& path : recentCaseFiles())
        m_recentMenu->addAction(path, this, [this, path] { openCaseFile(path); });
    m_recentMenu->setEnabled(!m_recentMenu->isEmpty());
}

void MainWindow::openDialog() {
    const QString dir = QSettings().value("files/lastDir", sampleCasesDir()).toString();
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open case"), dir, tr("Cases (*.toml)"));
    if (path.isEmpty()) return;
    QSettings().setValue("files/lastDir", QFileInfo(path).absolutePath());
    openCaseFile(path);
}

void MainWindow::saveDialog() {
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Save case"), m_casePath, tr("Cases (*.toml)"));
    if (path.isEmpty()) return;
    try {
        io::writeCase(m_editor->currentCase(), path.toStdString());
        m_casePath = path;
        rememberCaseFile(path);
        rebuildRecentMenu();
    } catch (const std::exception& failure) {
        QMessageBox::warning(this, tr("Cannot save case"), QString::fromStdString(failure.what()));
    }
}

void MainWindow::exportPng() {
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export view"), "view.png", tr("PNG (*.png)"));
    if (path.isEmpty()) return;
    if (!m_view->grabImage().save(path, "PNG"))
        QMessageBox::warning(this, tr("Cannot export"), tr("Could not write %1.").arg(path));
}

void MainWindow::exportCsv() {
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export plots"), "metrics.csv", tr("CSV (*.csv)"));
    if (path.isEmpty()) return;
    try {
        m_plots->writeCsv(path);
    } catch (const std::exception& failure) {
        QMessageBox::warning(this, tr("Cannot export"), QString::fromStdString(failure.what()));
    }
}

void MainWindow::toggleVtkRecording(bool on) {
    m_vtkWriter.reset();
    m_recordLock.reset();
    if (!on) return;
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Record VTU series into"));
    try {
        // Not into a folder that an lbdem run (or another studio) is writing.
        if (!dir.isEmpty()) {
            m_recordLock = std::make_unique<io::RunLock>(dir.toStdString());
            m_vtkWriter = std::make_unique<vis::VtkRunWriter>(dir.toStdString());
        }
    } catch (const std::exception& failure) {
        QMessageBox::warning(this, tr("Cannot record"), QString::fromStdString(failure.what()));
    }
    if (!m_vtkWriter) {
        m_recordLock.reset();
        m_recordVtk->setChecked(false);
    }
}

int MainWindow::setEnsembleFolder(const QString& folder) {
    m_ensembleFolder = folder;
    return showEnsembleBand();
}

void MainWindow::ensembleDialog() {
    const QString start = m_ensembleFolder.isEmpty() ? QSettings().value("files/lastDir").toString()
                                                     : m_ensembleFolder;
    const QString folder = QFileDialog::getExistingDirectory(
        this, tr("Sweep folder with this case's runs (NAME_s1, NAME_s2, ...)"), start);
    if (folder.isEmpty()) return;
    QSettings().setValue("ensemble/folder", folder);
    setEnsembleFolder(folder);
}

int MainWindow::showEnsembleBand() {
    if (m_ensembleFolder.isEmpty() || m_caseName.empty()) {
        m_plots->clearEnsemble();
        return 0;
    }
    const int runs = m_plots->showEnsemble(m_ensembleFolder.toStdString(), m_caseName);
    const QString name = QString::fromStdString(m_caseName);
    m_status->showNotice(runs > 0
                             ? tr("ensemble band: %1 finished runs of %2 in %3")
                                   .arg(runs)
                                   .arg(name, m_ensembleFolder)
                             : tr("no finished ensemble of %1 in %2").arg(name, m_ensembleFolder),
                         kEnsembleNoticeMs);
    return runs;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    m_controller->shutdown();
    saveSettings();
    event->accept();
}

void MainWindow::restoreSettings() {
    QSettings settings;
    if (!restoreGeometry(settings.value("window/geometry").toByteArray())) resize(1400, 900);
    restoreState(settings.value("window/state").toByteArray());
    m_view->setLayers(loadViewSettings(settings, m_view->layers()));
    m_ensembleFolder = settings.value("ensemble/folder").toString();
}

void MainWindow::saveSettings() const {
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
    saveViewSettings(settings, m_view->layers());
}

} // namespace lbdem::studio
