// The sweep report on a synthetic sweep folder: table rows, Markdown links and the PNG figures.
#include "campaign/SweepReport.h"
#include "campaign/figures/SweepFigures.h"
#include "tests/support/SyntheticSweep.h"

#ifdef LBDEM_HAS_VIS
#include "tests/render/ImageBaseline.h"

#include <vtkImageData.h>
#endif

#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <filesystem>

using namespace lbdem;
namespace fs = std::filesystem;

namespace {

/// The final runout the synthetic case reports: grows with slope, dense dry longest.
double finalRunout(const campaign::SweepEntry& e) {
    return 1.0 + 0.1 * e.spec.domain.slope_deg + (e.spec.grains.packing > 0.81 ? 0.5 : 0.0) -
           (e.spec.fluid.enabled ? 0.3 : 0.0);
}

/// Writes timeseries.csv (t/tau_c 0..4) and summary.json of one case as `lbdem run` would.
void writeCase(const campaign::SweepEntry& e, bool finished) {
    const double runout = finalRunout(e);
    support::writeSyntheticSeries(e.dir, runout, e.spec.fluid.enabled, std::nullopt);
    support::writeSyntheticSummary(e.dir, finished, runout, 0.0736, 0.8,
                                   ", \"wall_s\": 12.0, \"mlups\": 250.0");
}

} // namespace

class SweepReportTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void tableRows();
    void markdownLinksFiguresAndNamesSkipped();
    void figuresAreDrawn();

private:
    QTemporaryDir m_dir;
    fs::path m_out;
    campaign::SweepReportResult m_result;
};

void SweepReportTest::initTestCase() {
    QVERIFY(m_dir.isValid());
    m_out = m_dir.path().toStdString();
    std::vector<campaign::SweepEntry> entries;
    for (const double packing : {0.83, 0.79})
        for (const double slope : {0.0, 5.0})
            for (const bool submerged : {false, true}) {
                entries.push_back(support::syntheticEntry(m_out, packing, slope, submerged));
                // dense 5 deg dry in a short domain: its front reaches the end (0.12 m less one
                // largest diameter, 2.16 mm) at t/tau_c = 1.134, so the row at 1.25 is the first.
                if (packing > 0.81 && slope > 0 && !submerged)
                    entries.back().spec.domain.width_m = 0.12;
                writeCase(entries.back(), true);
            }
    entries.push_back(
        support::syntheticEntry(m_out, 0.83, 7.5, true)); // interrupted: summary says not finished
    writeCase(entries.back(), false);
    entries.push_back(support::syntheticEntry(m_out, 0.79, 7.5, true)); // never started: no folder
    m_result = campaign::writeSweepReport("synthetic", entries, m_out, campaign::writeSweepFigures);
}

void SweepReportTest::tableRows() {
    const std::string csv = support::readText(m_out / "sweep.csv");
    QCOMPARE(std::count(csv.begin(), csv.end(), '\n'), 11L); // header + 10 cases
    QVERIFY2(csv.find("dense_5deg_dry,0.83,5.0,dry,finished,2,1.25,") != std::string::npos,
             csv.c_str());
    QVERIFY2(csv.find("loose_5deg_submerged,0.79,5.0,submerged,finished,1.2,,") !=
                 std::string::npos,
             csv.c_str());
    QVERIFY2(csv.find("dense_7.5deg_submerged,0.83,7.5,submerged,unfinished,") != std::string::npos,
             csv.c_str());
    QVERIFY2(csv.find("loose_7.5deg_submerged,0.79,7.5,submerged,missing,") != std::string::npos,
             csv.c_str());
}

void SweepReportTest::markdownLinksFiguresAndNamesSkipped() {
    const std::string md = support::readText(m_out / "sweep.md");
    QVERIFY2(md.find("| dense_0deg_dry | 0.83 | 0.0 | dry | finished | 1.500 | never |") !=
                 std::string::npos,
             md.c_str());
    QVERIFY2(md.find("| dense_5deg_dry | 0.83 | 5.0 | dry | finished | 2.000 (end) | 1.25 |") !=
                 std::string::npos,
             md.c_str());
    QVERIFY2(md.find("## Figures") != std::string::npos, md.c_str());
    QVERIFY2(md.find("Not in the figures: dense_7.5deg_submerged (unfinished), "
                     "loose_7.5deg_submerged (missing)") != std::string::npos ||
                 md.find("No figures: this build has no VTK") != std::string::npos,
             md.c_str());
#ifdef LBDEM_HAS_VIS
    for (const char* png : {"runout_dense.png", "runout_loose.png", "energy_dense.png",
                            "energy_loose.png", "runout_vs_slope.png", "froude.png"})
        QVERIFY2(md.find(std::string("](") + png + ")") != std::string::npos, png);
#endif
}

void SweepReportTest::figuresAreDrawn() {
#ifdef LBDEM_HAS_VIS
    QVERIFY2(m_result.note.empty(), m_result.note.c_str());
    QCOMPARE(m_result.files.size(), std::size_t(8)); // sweep.csv, sweep.md and six figures
    for (const char* png : {"runout_dense.png", "runout_loose.png", "energy_dense.png",
                            "energy_loose.png", "runout_vs_slope.png", "froude.png"}) {
        const auto image = support::readPng((m_out / png).string());
        QVERIFY2(image, png);
        int dims[3];
        image->GetDimensions(dims);
        QCOMPARE(dims[0], 900);
        QCOMPARE(dims[1], 600);
        QVERIFY2(support::distinctColours(image) > 20, png);
        // Tableau blue and orange: the first two slopes (or packings) of the sweep.
        QVERIFY2(support::pixelsNear(image, 31, 119, 180, 39) > 200, png);
        QVERIFY2(support::pixelsNear(image, 255, 127, 14, 39) > 200, png);
    }
#else
    QVERIFY(m_result.note.find("no VTK") != std::string::npos);
    QCOMPARE(m_result.files.size(), std::size_t(2));
#endif
}

QTEST_GUILESS_MAIN(SweepReportTest)
#include "SweepReportTest.moc"
