// The sweep report on a synthetic sweep folder: table rows, Markdown links and the PNG figures.
#include "campaign/SweepReport.h"
#include "campaign/figures/SweepFigures.h"

#ifdef LBDEM_HAS_VIS
#include "tests/render/ImageBaseline.h"

#include <vtkImageData.h>
#endif

#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace lbdem;
namespace fs = std::filesystem;

namespace {

/// Whole text of a file ("" when missing).
std::string readText(const fs::path& path) {
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

/// A case of the synthetic sweep.
campaign::SweepEntry entry(const fs::path& out, double packing, double slope, bool submerged) {
    campaign::SweepEntry e;
    char name[64];
    std::snprintf(name, sizeof name, "%s_%gdeg_%s", packing > 0.81 ? "dense" : "loose", slope,
                  submerged ? "submerged" : "dry");
    e.spec.name = name;
    e.spec.grains.packing = packing;
    e.spec.domain.slope_deg = slope;
    e.spec.fluid.enabled = submerged;
    e.dir = out / name;
    return e;
}

/// The final runout the synthetic case reports: grows with slope, dense dry longest.
double finalRunout(const campaign::SweepEntry& e) {
    return 1.0 + 0.1 * e.spec.domain.slope_deg + (e.spec.grains.packing > 0.81 ? 0.5 : 0.0) -
           (e.spec.fluid.enabled ? 0.3 : 0.0);
}

/// Writes timeseries.csv (t/tau_c 0..4) and summary.json of one case as `lbdem run` would.
void writeCase(const campaign::SweepEntry& e, bool finished) {
    fs::create_directories(e.dir);
    const double runout = finalRunout(e);
    std::ofstream series(e.dir / "timeseries.csv");
    const double initialWidth = 0.05; // L_i: the front starts there
    series << "t_s,t_over_tc,step,ke_over_ep0,runout_m,runout_normalised"
           << (e.spec.fluid.enabled ? ",froude_densimetric" : "") << "\n";
    for (int k = 0; k <= 16; ++k) {
        const double t = 0.25 * k;
        series << 0.01 * t << "," << t << "," << 100 * k << "," << 0.1 * runout * t * std::exp(-t)
               << "," << initialWidth * (1 + runout * (1 - std::exp(-t))) << ","
               << runout * (1 - std::exp(-t));
        if (e.spec.fluid.enabled) series << "," << 0.5 * runout * t * std::exp(-t);
        series << "\n";
    }
    std::ofstream summary(e.dir / "summary.json");
    summary << "{\"finished\": " << (finished ? "true" : "false")
            << ", \"runout_final\": " << runout
            << ", \"ke_peak\": 0.0736, \"t_ke_peak_over_tc\": 1.0, \"packing_final\": 0.8, "
               "\"wall_s\": 12.0, "
               "\"mlups\": 250.0}\n";
}

#ifdef LBDEM_HAS_VIS
/// Pixels within 40 per channel of the colour (r, g, b).
int pixelsNear(vtkImageData* image, int r, int g, int b) {
    int dims[3];
    image->GetDimensions(dims);
    int count = 0;
    for (int y = 0; y < dims[1]; ++y)
        for (int x = 0; x < dims[0]; ++x) {
            const auto* p = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
            count += std::abs(p[0] - r) < 40 && std::abs(p[1] - g) < 40 && std::abs(p[2] - b) < 40;
        }
    return count;
}
#endif

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
                entries.push_back(entry(m_out, packing, slope, submerged));
                // dense 5 deg dry in a short domain: its front reaches the end (0.12 m less one
                // largest diameter, 2.16 mm) at t/tau_c = 1.134, so the row at 1.25 is the first.
                if (packing > 0.81 && slope > 0 && !submerged)
                    entries.back().spec.domain.width_m = 0.12;
                writeCase(entries.back(), true);
            }
    entries.push_back(entry(m_out, 0.83, 7.5, true)); // interrupted: summary says not finished
    writeCase(entries.back(), false);
    entries.push_back(entry(m_out, 0.79, 7.5, true)); // never started: no folder
    m_result = campaign::writeSweepReport("synthetic", entries, m_out, campaign::writeSweepFigures);
}

void SweepReportTest::tableRows() {
    const std::string csv = readText(m_out / "sweep.csv");
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
    const std::string md = readText(m_out / "sweep.md");
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
        QVERIFY2(pixelsNear(image, 31, 119, 180) > 200, png);
        QVERIFY2(pixelsNear(image, 255, 127, 14) > 200, png);
    }
#else
    QVERIFY(m_result.note.find("no VTK") != std::string::npos);
    QCOMPARE(m_result.files.size(), std::size_t(2));
#endif
}

QTEST_GUILESS_MAIN(SweepReportTest)
#include "SweepReportTest.moc"
