// The studio's live view: after a short run of a small deterministic case it matches
// the committed baseline tests/baselines/studio_live_view.png; a fixed colour range set in the
// view controls applies to the view at once, stays on later frames and is remembered.
//
// Regenerating the baseline (after a deliberate change to what the view draws):
//   LBDEM_UPDATE_BASELINES=1 ctest --test-dir build/release -R lbdem.ui.live_view
// then look at tests/baselines/studio_live_view.png before committing it (docs/style.md, Style
// §7). A failing run leaves the image and the difference in build/release/Testing/Temporary/. CTest
// runs it with OMP_NUM_THREADS=1; LBDEM_ANY_THREADS=1 lifts that check (1, 2 and 4 threads gave
// identical pixels when the baseline was made).
//
// The column is read from the committed packing in tests/data/packing_cache/ rather than
// generated: the deposition that generates it is chaotic, so a processor with other vector
// instructions (other rounding; the build uses -march=native) settles the discs elsewhere, grain
// by grain, and the image with them. From the same column the 100 steps differ only by rounding.
// If the case or the generator changes, the test fails saying so; then delete the old file,
// rerun once with LBDEM_UPDATE_BASELINES=1 (it copies the new packing back) and commit both.
#include "ui/studio/LiveView.h"
#include "solver/scene/Plan.h"
#include "tests/render/ImageBaseline.h"
#include "tests/ui/StudioTestCase.h"
#include "ui/studio/MainWindow.h"
#include "ui/studio/SimulationController.h"
#include "ui/studio/ViewControls.h"

#include <vtkImageData.h>

#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <memory>

using lbdem::studio::MainWindow;
namespace vis = lbdem::vis;

namespace {

// Steps before the baseline image: the column has started to slump and stir the fluid.
constexpr long long kSteps = 100;
// The live view's size in the test (fixed, so the window layout cannot change the image).
constexpr int kWidth = 720, kHeight = 380;
// vtkImageDifference's thresholded error, as in the render tests (VTK's own default is 10).
constexpr double kTolerance = 10.0;
// The committed packing of the small case (see the head of this file).
const QString kCommittedPackings = QStringLiteral(LBDEM_SOURCE_DIR "/tests/data/packing_cache");

/// Waits until the frame after `steps` fluid steps from the start is on screen. (Snapshot::step
/// of a coupled scene counts DEM sub-steps, so the frame is recognised by its time.)
bool waitForShownSteps(MainWindow& window, long long steps, int timeoutMs) {
    const double dt = lbdem::solver::makePlan(lbdem::studio::test::smallCase()).dt_s;
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < timeoutMs) {
        if (window.shownSnapshot() && window.shownSnapshot()->time_s >= (steps - 0.5) * dt)
            return true;
        QTest::qWait(10);
    }
    return false;
}

/// Fraction of pixels that differ at all between two images of the same size.
double differingFraction(const QImage& a, const QImage& b) {
    const QImage x = a.convertToFormat(QImage::Format_RGB32),
                 y = b.convertToFormat(QImage::Format_RGB32);
    long long differing = 0;
    for (int row = 0; row < x.height(); ++row)
        for (int col = 0; col < x.width(); ++col)
            differing += x.pixel(col, row) != y.pixel(col, row);
    return double(differing) / (double(x.width()) * x.height());
}

/// A window on the small case with the live view at the test size, shown.
void openSmallCase(MainWindow& window) {
    window.resize(1200, 800);
    window.liveView().setFixedSize(kWidth, kHeight);
    window.setCase(lbdem::studio::test::smallCase(), "small");
    window.show();
}

/// The child of the view controls named `name`; fails the test when missing.
template <typename Widget> Widget* control(MainWindow& window, const char* name) {
    auto* widget = window.viewControls().findChild<Widget*>(name);
    if (!widget) qFatal("no view control %s", name);
    return widget;
}

} // namespace

class LiveViewTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true); // keep the user's settings out of the test
        // A private cache holding only the committed packing (see the head of this file).
        QVERIFY(m_cache.isValid());
        const QDir committed(kCommittedPackings);
        for (const QString& name : committed.entryList({"packing-*.txt"}, QDir::Files))
            QVERIFY(QFile::copy(committed.filePath(name), QDir(m_cache.path()).filePath(name)));
        qputenv("LBDEM_CACHE_DIR", m_cache.path().toUtf8());
        QApplication::setOrganizationName("lbdem-test-live-view");
        // The image must not depend on how the solver's loops were split between threads.
        QVERIFY2(qgetenv("OMP_NUM_THREADS") == "1" ||
                     qEnvironmentVariableIsSet("LBDEM_ANY_THREADS"),
                 "run with OMP_NUM_THREADS=1 (CTest sets it)");
    }

    // Every test starts from the default view options (no geometry or ranges from earlier runs).
    void init() { QSettings().clear(); }

    void matchesBaseline() {
        MainWindow window;
        openSmallCase(window);
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.controller().run(kSteps);
        QVERIFY(waitForShownSteps(window, kSteps, 60000));
        const QImage view = window.liveView().grabImage();
        QCOMPARE(view.size(), QSize(kWidth, kHeight));
        const QString path =
            QDir(LBDEM_BINARY_DIR).filePath("Testing/Temporary/studio_live_view.grab.png");
        QDir().mkpath(QFileInfo(path).absolutePath());
        QVERIFY(view.save(path, "PNG"));
        const auto image = lbdem::support::readPng(path.toStdString());
        QVERIFY(image);
        QVERIFY(lbdem::support::distinctColours(image) > 50); // not blank
        const auto result =
            lbdem::support::compareWithBaseline(image, "studio_live_view", kTolerance);
        qInfo("thresholded error against the baseline: %g (tolerance %g) %s", result.error,
              kTolerance, result.message.c_str());
        QVERIFY2(result.passed, result.message.c_str());
    }

    void fixedRangeAppliesLive() {
        auto window = std::make_unique<MainWindow>();
        openSmallCase(*window);
        QVERIFY(QTest::qWaitForWindowExposed(window.get()));
        window->controller().run(20);
        QVERIFY(waitForShownSteps(*window, 20, 60000));
        lbdem::studio::LiveView& view = window->liveView();
        const QImage fitted = view.grabImage();
        const vis::ColorRange fittedFluid = view.fluidColorRange();
        QVERIFY(!fittedFluid.fixed);
        QVERIFY(fittedFluid.max > 1e-6); // the fluid moves

        // Fixing keeps the range shown (rounded to the digits of the spin boxes) ...
        control<QCheckBox>(*window, "fluidRangeFixed")->setChecked(true);
        auto* max = control<QDoubleSpinBox>(*window, "fluidRangeMax");
        QVERIFY(std::abs(view.fluidColorRange().max - fittedFluid.max) <= 1e-3 * fittedFluid.max);
        QVERIFY(view.fluidColorRange().fixed);
        // ... and a narrower range recolours the view at once.
        max->setValue(0.2 * max->value());
        const vis::ColorRange pinned = view.fluidColorRange();
        QCOMPARE(pinned, (vis::ColorRange{true, 0.0, max->value()}));
        QCOMPARE(view.layers().fluidRange(), pinned);
        const double differing = differingFraction(fitted, view.grabImage());
        qInfo("fluid range [0, %g] fixed to [0, %g]: %.3f of the pixels change", fittedFluid.max,
              pinned.max, differing);
        QVERIFY(differing > 0.02); // only the moving fluid near the column changes colour

        control<QCheckBox>(*window, "grainRangeFixed")->setChecked(true);
        control<QDoubleSpinBox>(*window, "grainRangeMax")->setValue(1e-3);
        QCOMPARE(view.grainColorRange(), (vis::ColorRange{true, 0.0, 1e-3}));

        // Later frames keep the fixed ranges.
        window->controller().step();
        QVERIFY(waitForShownSteps(*window, 21, 30000));
        QCOMPARE(view.fluidColorRange(), pinned);
        QCOMPARE(view.grainColorRange(), (vis::ColorRange{true, 0.0, 1e-3}));

        // Closing saves the ranges; the next window starts with them.
        window->close();
        window.reset();
        MainWindow next;
        QCOMPARE(next.liveView().layers().fluidRange(), pinned);
        QCOMPARE(next.viewControls().layers().fluidRange(), pinned);
        QVERIFY(next.viewControls().findChild<QCheckBox*>("fluidRangeFixed")->isChecked());
        QCOMPARE(next.liveView().layers().grainRange(), (vis::ColorRange{true, 0.0, 1e-3}));
    }

    // Runs last: the column came from the committed packing, not from the generator.
    void cleanupTestCase() {
        const QDir cache(m_cache.path()), committed(kCommittedPackings);
        const QStringList used = cache.entryList({"packing-*.txt"}, QDir::Files),
                          known = committed.entryList({"packing-*.txt"}, QDir::Files);
        for (const QString& name : used) {
            if (known.contains(name)) continue;
            if (qEnvironmentVariableIsSet("LBDEM_UPDATE_BASELINES"))
                QFile::copy(cache.filePath(name), committed.filePath(name));
            QFAIL(qPrintable(
                "the small case's packing is not the committed one (case or generator changed): "
                "commit the new " +
                name +
                " into tests/data/packing_cache/ with a new "
                "baseline (see the head of tests/ui/LiveViewTest.cpp)"));
        }
    }

private:
    QTemporaryDir m_cache;
};

QTEST_MAIN(LiveViewTest)
#include "LiveViewTest.moc"
