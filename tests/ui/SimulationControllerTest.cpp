// The solver thread: snapshots arrive, frames are skipped not queued, pause stops them, reset
// and step work, and shutdown joins the thread (docs/style.md, Style §3, §7).
#include "ui/studio/SimulationController.h"
#include "tests/ui/StudioTestCase.h"
#include "ui/studio/SimulationWorker.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTest>

#ifdef _OPENMP
#include <omp.h>
#endif

using lbdem::solver::SnapshotPtr;
using lbdem::studio::RunProgress;
using lbdem::studio::RunState;
using lbdem::studio::SimulationController;

class SimulationControllerTest : public QObject {
    Q_OBJECT

private:
    // Plays the GUI: takes each snapshot and releases it at once.
    static void releaseEach(SimulationController& controller) {
        QObject::connect(&controller, &SimulationController::snapshotReady, &controller,
                         [&controller](const SnapshotPtr&) { controller.releaseFrame(); });
    }
    static long long lastStep(const QSignalSpy& spy) {
        return spy.last().at(0).value<SnapshotPtr>()->step;
    }

private slots:
    void loadPublishesTheStart() {
        SimulationController controller;
        QSignalSpy snapshots(&controller, &SimulationController::snapshotReady);
        QSignalSpy loaded(&controller, &SimulationController::loaded);
        controller.load(lbdem::studio::test::smallCase());
        QVERIFY(snapshots.wait(20000));
        QCOMPARE(loaded.count(), 1);
        QCOMPARE(lastStep(snapshots), 0LL);
        QVERIFY(snapshots.last().at(0).value<SnapshotPtr>()->grains.size() > 0);
        QCOMPARE(controller.state(), RunState::Ready);
    }

    void runPauseReset() {
        SimulationController controller;
        releaseEach(controller);
        QSignalSpy snapshots(&controller, &SimulationController::snapshotReady);
        QSignalSpy states(&controller, &SimulationController::stateChanged);
        controller.load(lbdem::studio::test::smallCase());
        QVERIFY(snapshots.wait(20000));
        controller.run();
        QTRY_VERIFY_WITH_TIMEOUT(snapshots.count() >= 4, 20000);
        QVERIFY(lastStep(snapshots) > 0);

        QElapsedTimer pausing;
        pausing.start();
        controller.pause();
        while (controller.state() != RunState::Paused)
            QVERIFY(states.wait(5000));
        qInfo("pause took effect after %lld ms (one batch is about %d ms of stepping)",
              static_cast<long long>(pausing.elapsed()), lbdem::studio::SimulationWorker::kBatchMs);
        QTest::qWait(200); // the final frame of the pause may still be on its way
        const int countAtPause = snapshots.count();
        const long long stepAtPause = lastStep(snapshots);
        QTest::qWait(500);
        QCOMPARE(snapshots.count(), countAtPause);
        QCOMPARE(lastStep(snapshots), stepAtPause);

        controller.reset();
        QTRY_VERIFY_WITH_TIMEOUT(snapshots.count() > countAtPause, 20000);
        QCOMPARE(lastStep(snapshots), 0LL);
        QTRY_COMPARE_WITH_TIMEOUT(controller.state(), RunState::Ready, 5000);
    }

    void stepTakesOneStep() {
        SimulationController controller;
        releaseEach(controller);
        QSignalSpy snapshots(&controller, &SimulationController::snapshotReady);
        controller.load(lbdem::studio::test::smallCase());
        QVERIFY(snapshots.wait(20000));
        // The step index is the Simulation's own count (it may count DEM sub-steps), so one
        // step() shows as one increase of it.
        controller.step();
        QVERIFY(snapshots.wait(10000));
        const long long first = lastStep(snapshots);
        QVERIFY(first > 0);
        controller.step();
        QVERIFY(snapshots.wait(10000));
        QVERIFY(lastStep(snapshots) > first);
        QCOMPARE(snapshots.count(), 3);
    }

    void framesAreSkippedNotQueued() {
        SimulationController controller;
        QSignalSpy snapshots(&controller, &SimulationController::snapshotReady);
        QSignalSpy progress(&controller, &SimulationController::progressed);
        controller.load(lbdem::studio::test::smallCase());
        QVERIFY(snapshots.wait(20000));
        controller.run();
        // Nobody releases the first frame: the worker keeps stepping but sends nothing more.
        QTRY_VERIFY_WITH_TIMEOUT(
            !progress.isEmpty() && progress.last().at(0).value<RunProgress>().step > 5, 20000);
        QCOMPARE(snapshots.count(), 1);
        controller.releaseFrame();
        QVERIFY(snapshots.wait(20000));
        QCOMPARE(snapshots.count(), 2);
        QVERIFY(lastStep(snapshots) > 5);
    }

    void runStepsStopsAtTheCount() {
        SimulationController controller;
        releaseEach(controller);
        QSignalSpy snapshots(&controller, &SimulationController::snapshotReady);
        QSignalSpy completed(&controller, &SimulationController::runCompleted);
        controller.load(lbdem::studio::test::smallCase());
        controller.run(25);
        QVERIFY(completed.wait(30000));
        const long long reached = completed.last().at(0).toLongLong();
        QVERIFY(reached > 0);
        // The final state is published after the run: the last snapshot is not before it.
        QTRY_VERIFY_WITH_TIMEOUT(lastStep(snapshots) >= reached, 5000);
        QCOMPARE(controller.state(), RunState::Paused);
    }

    void runStepsEndsAtTheEndOfTheCase() {
        SimulationController controller;
        releaseEach(controller);
        QSignalSpy completed(&controller, &SimulationController::runCompleted);
        // An end time of a few steps: the counted run must still report its completion.
        controller.load(
            lbdem::studio::test::smallCase({"run.end_tc=0.001", "run.output_interval_tc=0.001"}));
        controller.run(1000000);
        QVERIFY(completed.wait(30000));
        QTRY_COMPARE_WITH_TIMEOUT(controller.state(), RunState::Finished, 5000);
        QVERIFY(completed.last().at(0).toLongLong() < 1000000);
    }

    // The solver thread's OpenMP team is the case's run.threads, whatever the GUI thread's
    // default is; 0 means all cores but one, at least one.
    void runThreadsSizeTheSolverTeam_data() {
        QTest::addColumn<int>("requested");
        QTest::newRow("1") << 1;
        QTest::newRow("3") << 3;
        QTest::newRow("default") << 0;
    }
    void runThreadsSizeTheSolverTeam() {
#ifndef _OPENMP
        QSKIP("built without OpenMP");
#else
        QFETCH(int, requested);
        const int expected = requested > 0 ? requested : std::max(1, omp_get_num_procs() - 1);
        QCOMPARE(lbdem::studio::SimulationWorker::teamSizeFor(requested), expected);
        const int guiThreads = omp_get_max_threads();
        SimulationController controller;
        releaseEach(controller);
        QSignalSpy progress(&controller, &SimulationController::progressed);
        controller.load(
            lbdem::studio::test::smallCase({"run.threads=" + std::to_string(requested)}));
        QVERIFY(progress.wait(20000));
        QCOMPARE(progress.last().at(0).value<RunProgress>().threads, expected);
        controller.run(5);
        QTRY_VERIFY_WITH_TIMEOUT(controller.state() == RunState::Paused, 20000);
        QCOMPARE(progress.last().at(0).value<RunProgress>().threads, expected);
        QCOMPARE(omp_get_max_threads(), guiThreads); // the GUI thread's own count is untouched
#endif
    }

    // Progress carries the end time, and an ETA only once a run has gone on for a while.
    void progressShowsTheEndAndALateEta() {
        SimulationController controller;
        releaseEach(controller);
        QSignalSpy progress(&controller, &SimulationController::progressed);
        QSignalSpy loaded(&controller, &SimulationController::loaded);
        controller.load(lbdem::studio::test::smallCase({"run.end_tc=5"}));
        QVERIFY(progress.wait(20000));
        const auto first = progress.last().at(0).value<RunProgress>();
        QCOMPARE(first.end_time_over_tc, 5.0);
        QVERIFY(first.eta_seconds < 0);
        controller.run();
        QTRY_VERIFY_WITH_TIMEOUT(progress.last().at(0).value<RunProgress>().eta_seconds > 0, 20000);
        const auto late = progress.last().at(0).value<RunProgress>();
        QVERIFY(late.step >= lbdem::studio::SimulationWorker::kEtaMinSteps);
        for (const auto& arguments : progress) {
            const auto report = arguments.at(0).value<RunProgress>();
            if (report.eta_seconds >= 0)
                QVERIFY(report.step >= lbdem::studio::SimulationWorker::kEtaMinSteps);
        }
        controller.pause();
        QTRY_COMPARE_WITH_TIMEOUT(controller.state(), RunState::Paused, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(progress.last().at(0).value<RunProgress>().eta_seconds < 0, 5000);
    }

    void badCaseReportsFailure() {
        SimulationController controller;
        QSignalSpy failed(&controller, &SimulationController::failed);
        lbdem::solver::CaseSpec spec = lbdem::studio::test::smallCase();
        spec.scene = lbdem::solver::SceneKind::SettlingDisc; // a scene only `lbdem verify` runs:
                                                             // building it fails
        controller.load(spec);
        QVERIFY(failed.wait(20000));
        QVERIFY(!failed.last().at(0).toString().isEmpty());
        QCOMPARE(controller.state(), RunState::Failed);
    }

    void shutdownJoinsTheThreadMidRun() {
        SimulationController controller;
        releaseEach(controller);
        QSignalSpy snapshots(&controller, &SimulationController::snapshotReady);
        controller.load(lbdem::studio::test::smallCase());
        controller.run();
        QTRY_VERIFY_WITH_TIMEOUT(snapshots.count() >= 2, 20000);
        QVERIFY(controller.isThreadRunning());
        QElapsedTimer timer;
        timer.start();
        controller.shutdown();
        qInfo("shutdown mid-run took %lld ms", static_cast<long long>(timer.elapsed()));
        QVERIFY(!controller.isThreadRunning());
        controller.run(); // requests after shutdown are dropped, not crashes
        controller.shutdown();
    }
};

QTEST_GUILESS_MAIN(SimulationControllerTest)
#include "SimulationControllerTest.moc"
