// Sweep progress lines: each running case's t/tau_c read from its timeseries.csv, and an ETA
// worked out by hand from the paces the synthetic cases are given.
#include "campaign/SweepProgress.h"

#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>
#include <fstream>

using namespace lbdem;
namespace fs = std::filesystem;

namespace {

/// A case of end_tc 4, with or without fluid, writing into out/name.
campaign::SweepEntry entry(const fs::path& out, const std::string& name, bool fluid) {
    campaign::SweepEntry e;
    e.spec.name = name;
    e.spec.fluid.enabled = fluid;
    e.spec.run.end_tc = 4;
    e.dir = out / name;
    return e;
}

/// Write a timeseries.csv whose rows reach t/tau_c = lastTc in steps of 0.25.
void writeSeries(const fs::path& dir, double lastTc) {
    fs::create_directories(dir);
    std::ofstream series(dir / "timeseries.csv");
    series << "t_s,t_over_tc,step,runout_normalised\n";
    for (int k = 0; 0.25 * k <= lastTc + 1e-12; ++k)
        series << 0.01 * k << "," << 0.25 * k << "," << 10 * k << ",0\n";
}

} // namespace

class SweepProgressTest : public QObject {
    Q_OBJECT
private slots:
    void progressIsTheLastRowsTime() {
        QTemporaryDir tmp;
        const fs::path dir = tmp.path().toStdString();
        QCOMPARE(campaign::runProgressTc(dir / "absent"), 0.0);
        writeSeries(dir / "case", 1.5);
        QCOMPARE(campaign::runProgressTc(dir / "case"), 1.5);
    }

    void etaFromEachCasesPaceAndItsKinds() {
        QTemporaryDir tmp;
        const fs::path out = tmp.path().toStdString();
        const auto a = entry(out, "a", true), b = entry(out, "b", true), c = entry(out, "c", false);
        writeSeries(a.dir, 0.5); // a resumed case: its pace counts from 0.5 on
        campaign::SweepProgress progress({a, b, c}, 1, 1);
        QCOMPARE(QString::fromStdString(progress.line({{0, 5.0}})),
                 QString("1/4 done; running a t/tc 0.50/4; ETA once a case has run 20s"));

        // a has advanced 1.0 tau_c in 100 s: 250 s left; b (same kind, not started) 400 s;
        // c has no fluid and no case of its kind has run yet: counted, not guessed.
        writeSeries(a.dir, 1.5);
        QCOMPARE(QString::fromStdString(progress.line({{0, 100.0}})),
                 QString("1/4 done; running a t/tc 1.50/4; ETA 10m50s + 1 case(s) not timed yet"));

        // a finished 3.5 tau_c in 250 s; b, just started (under 20 s), goes at a's pace: 4 / 0.014.
        progress.finished(0, 250.0);
        QCOMPARE(QString::fromStdString(progress.line({{1, 10.0}})),
                 QString("2/4 done; running b t/tc 0.00/4; ETA 4m45s + 1 case(s) not timed yet"));
    }
};

QTEST_GUILESS_MAIN(SweepProgressTest)
#include "SweepProgressTest.moc"
