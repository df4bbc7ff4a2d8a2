// The studio's ensemble band: for a case with finished runs in a sweep folder, the live plots
// shade their min-max (and hold their mean) behind the live curves; without a finished ensemble
// there is no band; an unfinished run is left out.
#include "ui/studio/LivePlots.h"
#include "ui/studio/PlotWidget.h"

#include <QImage>
#include <QTemporaryDir>
#include <QTest>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using lbdem::studio::LivePlots;
using lbdem::studio::PlotWidget;

namespace {

/// A run folder of the sweep: summary.json and a timeseries.csv whose runout is scale * t and
/// whose E_k/E_p0 is 0.1 * scale, at t/tau_c = 0, 0.5, ..., 2.
void writeRun(const fs::path& dir, bool finished, double scale) {
    fs::create_directories(dir);
    std::ofstream(dir / "summary.json")
        << "{\"finished\": " << (finished ? "true" : "false") << "}\n";
    std::ofstream series(dir / "timeseries.csv");
    series << "t_s,t_over_tc,runout_normalised,ke_over_ep0\n";
    for (int k = 0; k <= 4; ++k) {
        const double t = 0.5 * k;
        series << 0.01 * t << ',' << t << ',' << scale * t << ',' << 0.1 * scale << '\n';
    }
}

/// How many pixels of the band's colour the widget paints.
int bandPixels(const PlotWidget& plot) {
    const QImage image = const_cast<PlotWidget&>(plot).grab().toImage();
    int count = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            count += image.pixelColor(x, y) == PlotWidget::bandColor();
    return count;
}

} // namespace

class EnsembleBandPlotTest : public QObject {
    Q_OBJECT
private slots:
    void bandOfTheFinishedRuns() {
        QTemporaryDir sweep;
        const fs::path out = sweep.path().toStdString();
        writeRun(out / "column_s1", true, 1.0);
        writeRun(out / "column_s2", true, 3.0);
        writeRun(out / "column_s3", false, 100.0); // unfinished: not in the band
        writeRun(out / "other_s1", true, 50.0);    // another case
        LivePlots plots;
        plots.resize(900, 220);
        QCOMPARE(plots.showEnsemble(out, "column"), 2);
        const PlotWidget* runout = plots.plot(LivePlots::kRunout);
        QVERIFY(runout);
        QCOMPARE(runout->bandSize(), 5);
        QVERIFY(runout->bandLabel().contains("2 seed"));
        QVERIFY(plots.plot(LivePlots::kFroude)->bandSize() == 0); // no such column
        QVERIFY(bandPixels(*runout) > 100);

        // The live curve is drawn over the band, and a new run keeps it.
        plots.clear();
        QVERIFY(bandPixels(*runout) > 100);

        plots.clearEnsemble();
        QCOMPARE(runout->bandSize(), 0);
        QCOMPARE(bandPixels(*runout), 0);
    }

    void noEnsembleNoBand() {
        QTemporaryDir sweep;
        const fs::path out = sweep.path().toStdString();
        writeRun(out / "column_s1", false, 1.0);
        LivePlots plots;
        QCOMPARE(plots.showEnsemble(out, "column"), 0);
        QCOMPARE(plots.showEnsemble(out / "missing", "column"), 0);
        QCOMPARE(plots.plot(LivePlots::kRunout)->bandSize(), 0);
        QCOMPARE(plots.plot(LivePlots::kKineticEnergy)->bandSize(), 0);
    }
};

QTEST_MAIN(EnsembleBandPlotTest)
#include "EnsembleBandPlotTest.moc"
