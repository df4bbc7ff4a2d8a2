// Ensembles over packing seeds on a synthetic sweep folder: spread per case, findings seed by seed
// (with fronts at the domain's end left undecided), the report's files and the banded figures.
#include "campaign/SweepEnsemble.h"
#include "campaign/SweepFindings.h"
#include "campaign/SweepReport.h"
#include "campaign/SweepVariants.h"
#include "campaign/figures/SweepFigures.h"
#include "solver/core/InputError.h"
#include "tests/support/SyntheticSweep.h"

#ifdef LBDEM_HAS_VIS
#include "tests/render/ImageBaseline.h"

#include <vtkImageData.h>
#endif

#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

using namespace lbdem;
namespace fs = std::filesystem;

namespace {

/// The final runout of a synthetic run. Dense dry 2.0 + 0.1 slope + 0.1 seed; dense submerged
/// 1.5 at 0 deg, and at 5 deg 1.9 (seed 1, shorter than dry), 1.95 (seed 2: its front reaches the
/// domain's end, see initTestCase) and 3.0 (seed 3, longer than dry); loose dry 1.8 + 0.1 slope,
/// loose submerged 1.6 + 0.1 slope.
double finalRunout(const campaign::SweepEntry& e) {
    const double slope = e.spec.domain.slope_deg;
    if (e.spec.grains.packing > 0.81) {
        if (!e.spec.fluid.enabled) return 2.0 + 0.1 * slope + 0.1 * e.seed;
        return slope == 0 ? 1.5 : (e.seed == 1 ? 1.9 : e.seed == 2 ? 1.95 : 3.0);
    }
    return (e.spec.fluid.enabled ? 1.6 : 1.8) + 0.1 * slope;
}

/// timeseries.csv (t/tau_c 0..4, the runout approaching its final value) and summary.json.
void writeRun(const campaign::SweepEntry& e, const char* status) {
    const double runout = finalRunout(e);
    // Pore pressure: dense -100 seed Pa (suction), loose +10 Pa but -5 Pa for seed 1 at 5 deg.
    const bool dense = e.spec.grains.packing > 0.81;
    const double pore =
        dense ? -100.0 * e.seed : (e.spec.domain.slope_deg > 0 && e.seed == 1 ? -5.0 : 10.0);
    support::writeSyntheticSeries(e.dir, runout, true, pore);
    const bool unstable = std::string(status) == "unstable";
    support::writeSyntheticSummary(e.dir, std::string(status) == "finished", runout,
                                   0.1 * runout / std::exp(1.0), dense ? 0.78 : 0.775,
                                   unstable ? ", \"stop_reason\": \"diverged\"" : "");
}

const campaign::Finding* findingOf(const std::vector<campaign::Finding>& findings,
                                   const std::string& statement, const std::string& where) {
    for (const auto& f : findings)
        if (f.statement == statement && f.where == where) return &f;
    return nullptr;
}

} // namespace

class SweepEnsembleTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void spreadAndInterpolation();
    void runsOfASweepWithSeeds();
    void runsOfASweepWithVariants();
    void spreadPerCase();
    void findingsSeedBySeed();
    void reportFiles();
    void figuresHaveBands();

private:
    QTemporaryDir m_dir;
    fs::path m_out;
    std::vector<campaign::SweepEntry> m_entries;
    campaign::SweepReportResult m_result;
};

void SweepEnsembleTest::initTestCase() {
    QVERIFY(m_dir.isValid());
    m_out = m_dir.path().toStdString();
    for (const double packing : {0.83, 0.79})
        for (const double slope : {0.0, 5.0})
            for (const bool submerged : {false, true})
                for (const int seed : {1, 2, 3}) {
                    m_entries.push_back(
                        support::syntheticEntry(m_out, packing, slope, submerged, seed));
                    auto& e = m_entries.back();
                    // dense 5 deg submerged, seed 2: a 0.12 m domain, whose end (less one largest
                    // diameter, 0.1178 m) its front passes (0.05 (1 + 1.95 (1 - e^-4)) = 0.146 m).
                    if (packing > 0.81 && slope > 0 && submerged && seed == 2)
                        e.spec.domain.width_m = 0.12;
                    const bool unstable = packing > 0.81 && slope == 0 && submerged && seed == 3;
                    writeRun(e, unstable ? "unstable" : "finished");
                }
    m_result =
        campaign::writeSweepReport("ensemble", m_entries, m_out, campaign::writeSweepFigures);
}

void SweepEnsembleTest::spreadAndInterpolation() {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto s = campaign::spreadOf({1.0, nan, 2.0, 3.0});
    QCOMPARE(s.count, 3);
    QCOMPARE(s.mean, 2.0);
    QCOMPARE(s.sd, 1.0); // sample standard deviation: sqrt((1 + 0 + 1) / 2)
    QCOMPARE(s.min, 1.0);
    QCOMPARE(s.max, 3.0);
    QVERIFY(std::isnan(campaign::spreadOf({4.0}).sd));
    QCOMPARE(campaign::spreadOf({}).count, 0);
    QCOMPARE(campaign::interpolate({0, 1, 2}, {0, 10, 30}, 1.5), 20.0);
    QCOMPARE(campaign::interpolate({0, 1, 2}, {0, 10, 30}, 2.0), 30.0);
    QVERIFY(std::isnan(campaign::interpolate({0, 1, 2}, {0, 10, 30}, 2.5)));
}

void SweepEnsembleTest::runsOfASweepWithSeeds() {
    io::SweepSpec sweep;
    sweep.cases = {LBDEM_SOURCE_DIR "/sample_cases/paper/loose_0deg_dry.toml"};
    sweep.overrides = {"grains.count=150"};
    const auto runs = campaign::planSweepRuns(sweep, campaign::firstSeeds(3), "/tmp/S");
    QCOMPARE(runs.size(), std::size_t(3));
    for (int k = 0; k < 3; ++k) {
        QCOMPARE(runs[k].entry.dir.string(), "/tmp/S/loose_0deg_dry_s" + std::to_string(k + 1));
        QCOMPARE(runs[k].entry.seed, k + 1);
        QCOMPARE(runs[k].entry.spec.grains.seed, k + 1);
        QCOMPARE(runs[k].entry.spec.grains.count, 150);
        QCOMPARE(runs[k].overrides.back(), "grains.seed=" + std::to_string(k + 1));
    }
    io::SweepSpec twice = sweep; // one case name twice: one output folder for two cases
    twice.cases.push_back(sweep.cases.front());
    QVERIFY_EXCEPTION_THROWN(campaign::planSweepRuns(twice, campaign::firstSeeds(2), "/tmp/S"),
                             solver::InputError);
    const auto single = campaign::planSweepRuns(sweep, {}, "/tmp/S");
    QCOMPARE(single.size(), std::size_t(1));
    QCOMPARE(single[0].entry.dir.string(), std::string("/tmp/S/loose_0deg_dry"));
    QCOMPARE(single[0].entry.seed, 0);
}

void SweepEnsembleTest::runsOfASweepWithVariants() {
    io::SweepSpec sweep;
    sweep.cases = {LBDEM_SOURCE_DIR "/sample_cases/paper/loose_0deg_dry.toml",
                   LBDEM_SOURCE_DIR "/sample_cases/paper/dense_0deg_dry.toml"};
    sweep.overrides = {"grains.count=150", "grains.contact_torque=true"};
    sweep.variants = {{"paper", {}}, {"no_torque", {"grains.contact_torque=false"}}};
    const auto runs = campaign::planSweepRuns(sweep, campaign::firstSeeds(2), "/tmp/S");
    // Variant by variant (the reference first), each variant's cases in order, then seeds.
    const std::vector<std::string> folders{
        "loose_0deg_dry__paper_s1",     "loose_0deg_dry__paper_s2",
        "dense_0deg_dry__paper_s1",     "dense_0deg_dry__paper_s2",
        "loose_0deg_dry__no_torque_s1", "loose_0deg_dry__no_torque_s2",
        "dense_0deg_dry__no_torque_s1", "dense_0deg_dry__no_torque_s2"};
    QCOMPARE(runs.size(), folders.size());
    for (std::size_t k = 0; k < runs.size(); ++k) {
        const auto& entry = runs[k].entry;
        QCOMPARE(entry.dir.string(), "/tmp/S/" + folders[k]);
        QCOMPARE(entry.variant, std::string(k < 4 ? "paper" : "no_torque"));
        QCOMPARE(entry.spec.grains.contact_torque, k < 4);
        QCOMPARE(entry.spec.grains.count, 150);
        QCOMPARE(entry.seed, static_cast<int>(k % 2) + 1);
        QCOMPARE(entry.spec.name + "_s" + std::to_string(entry.seed), folders[k]);
        // The run is started with the case's name carrying the variant, so its own files agree.
        QVERIFY(std::find(runs[k].overrides.begin(), runs[k].overrides.end(),
                          "name=" + entry.spec.name) != runs[k].overrides.end());
    }
    // The findings are those of the first variant: the second only adds rows to the tables.
    std::vector<campaign::SweepEntry> entries;
    for (const auto& run : runs)
        entries.push_back(run.entry);
    auto cases = campaign::gatherEnsemble(entries);
    QCOMPARE(cases.size(), std::size_t(4));
    QCOMPARE(cases[1].variant, std::string("paper"));
    QCOMPARE(cases[2].variant, std::string("no_torque"));
    for (auto& c : cases) { // every run finished; no_torque's figures twice the reference's
        c.finished = static_cast<int>(c.runs.size());
        for (std::size_t m = 0; m < campaign::kEnsembleMetrics; ++m)
            c.spread[m] = campaign::spreadOf(
                std::vector<double>(2, c.packing * (c.variant == "paper" ? 1 : 2)));
        for (auto& run : c.runs) {
            run.status = "finished";
            run.values.fill(c.packing);
        }
    }
    const auto findings = campaign::computeFindings(cases);
    for (const auto& finding : findings)
        QCOMPARE(finding.seeds(), 2);
    QVERIFY(!findings.empty());
    // The controlled-experiment table: each variant against the reference of its own case.
    const std::string md = campaign::variantsMarkdown(cases);
    QVERIFY(md.find("| loose_0deg_dry | paper | 2/2 | 0.7900 ± 0.0000 |") != std::string::npos);
    QVERIFY(md.find("| dense_0deg_dry | no_torque | 2/2 | 1.6600 ± 0.0000 (x2.00) |") !=
            std::string::npos);
    const std::string csv = campaign::variantsCsv(cases);
    QVERIFY(csv.rfind("case,variant,runs,finished,unstable,front_at_end,ke_peak,", 0) == 0);
    QVERIFY(csv.find("\nloose_0deg_dry,no_torque,2,2,0,0,1.58,2,") != std::string::npos);
}

void SweepEnsembleTest::spreadPerCase() {
    const auto cases = campaign::gatherEnsemble(m_entries);
    QCOMPARE(cases.size(), std::size_t(8));
    const auto& denseDry0 = cases[0];
    QCOMPARE(denseDry0.name, std::string("dense_0deg_dry"));
    QCOMPARE(denseDry0.finished, 3);
    const auto& runout =
        denseDry0.spread[static_cast<std::size_t>(campaign::EnsembleMetric::RunoutFinal)];
    QVERIFY(std::abs(runout.mean - 2.2) < 1e-12 && std::abs(runout.sd - 0.1) < 1e-12);
    QVERIFY(std::abs(runout.min - 2.1) < 1e-12 && std::abs(runout.max - 2.3) < 1e-12);
    // At 3 tau_c the synthetic runout is R (1 - e^-3), between the rows at 3.0 (exactly a row).
    const auto& at3 =
        denseDry0.spread[static_cast<std::size_t>(campaign::EnsembleMetric::RunoutAt3Tc)];
    QVERIFY(std::abs(at3.mean - 2.2 * (1 - std::exp(-3.0))) < 1e-5);
    QCOMPARE(
        denseDry0.spread[static_cast<std::size_t>(campaign::EnsembleMetric::FroudeAt3Tc)].count,
        0); // dry
    const auto& denseWet0 = cases[1];
    QCOMPARE(denseWet0.finished, 2);
    QCOMPARE(denseWet0.unstable, 1);
    QCOMPARE(cases[3].name, std::string("dense_5deg_submerged"));
    QCOMPARE(cases[3].endReached, 1);
    const std::string csv = support::readText(m_out / "sweep.csv");
    QVERIFY2(
        csv.rfind(
            "case,packing,slope_deg,medium,seeds,finished,unstable,front_at_end,runout_final_mean,"
            "runout_final_sd,runout_final_min,runout_final_max,ke_peak_mean,",
            0) == 0,
        csv.c_str());
    QVERIFY2(csv.find("\ndense_0deg_dry,0.83,0.0,dry,3,3,0,0,2.2,0.1,2.1,2.3,") !=
                 std::string::npos,
             csv.c_str());
    QVERIFY2(csv.find("\ndense_0deg_submerged,0.83,0.0,submerged,3,2,1,0,1.5,0,1.5,1.5,") !=
                 std::string::npos,
             csv.c_str());
    // Pore pressure at 1 tau_c of its two finished seeds, -100 and -200 Pa: sd 70.71 Pa.
    QVERIFY2(csv.find(",-150,70.7107,-200,-100\n") != std::string::npos, csv.c_str());
}

void SweepEnsembleTest::findingsSeedBySeed() {
    const auto findings = campaign::computeFindings(campaign::gatherEnsemble(m_entries));
    const auto* dense0 = findingOf(findings, "dense: dry runout longer than submerged", "0 deg");
    const auto* dense5 = findingOf(findings, "dense: dry runout longer than submerged", "5 deg");
    QVERIFY(dense0 && dense5);
    QCOMPARE(dense0->holds, 2); // seed 3 of the submerged case was unstable: left out
    QCOMPARE(dense0->seeds(), 2);
    QCOMPARE(dense5->holds, 1);     // seed 1: 2.6 against 1.9
    QCOMPARE(dense5->undecided, 1); // seed 2: 2.7 against a front at the end (>= 1.95)
    QCOMPARE(dense5->fails, 1);     // seed 3: 2.8 against 3.0
    const auto* loose = findingOf(findings, "loose: submerged runout longer than dry", "5 deg");
    QVERIFY(loose);
    QCOMPARE(loose->fails, 3);
    const auto* grows =
        findingOf(findings, "dense, dry: runout grows with slope", "0 deg to 5 deg");
    QVERIFY(grows);
    QCOMPARE(grows->holds, 3);
    const auto* packing =
        findingOf(findings, "dry: dense and loose end within 0.01 in packing", "0 deg");
    QVERIFY(packing);
    QCOMPARE(packing->holds, 3); // 0.78 against 0.775
    const auto* suction = findingOf(
        findings, "dense, submerged: pore pressure on the failure plane negative at 1 tau_c",
        "0 deg");
    const auto* excess = findingOf(
        findings, "loose, submerged: pore pressure on the failure plane positive at 1 tau_c",
        "5 deg");
    QVERIFY(suction && excess);
    QCOMPARE(suction->holds, 2);
    QCOMPARE(suction->seeds(), 2);
    QCOMPARE(excess->holds, 2);
    QCOMPARE(excess->fails, 1);
    const std::string csv = support::readText(m_out / "findings.csv");
    QVERIFY2(csv.find("\"dense: dry runout longer than submerged\",5 deg,1,1,1,3\n") !=
                 std::string::npos,
             csv.c_str());
}

void SweepEnsembleTest::reportFiles() {
    const std::string md = support::readText(m_out / "sweep.md");
    QVERIFY2(md.find("## Ensemble over packing seeds") != std::string::npos, md.c_str());
    QVERIFY2(md.find("| dense_0deg_dry | 3 | 3 | 0 | 2.200 ± 0.100 | 2.100–2.300 |") !=
                 std::string::npos,
             md.c_str());
    QVERIFY2(
        md.find("| dense_5deg_submerged | 3 | 3 | 0 | 2.283 ± 0.621 (end: 1) | 1.900–3.000 |") !=
            std::string::npos,
        md.c_str());
    QVERIFY2(md.find("| dense: dry runout longer than submerged | 5 deg | holds for 1 of 3 seeds "
                     "(1 undecided: a "
                     "front at the domain's end) |") != std::string::npos,
             md.c_str());
    QVERIFY2(md.find("## Runs") != std::string::npos &&
                 md.find("| dense_5deg_submerged_s2 |") != std::string::npos,
             md.c_str());
    const std::string runs = support::readText(m_out / "runs.csv");
    QCOMPARE(std::count(runs.begin(), runs.end(), '\n'), 25L); // header + 24 runs
    QVERIFY2(runs.find("\ndense_0deg_submerged_s3,0.83,0.0,submerged,unstable,") !=
                 std::string::npos,
             runs.c_str());
}

void SweepEnsembleTest::figuresHaveBands() {
#ifdef LBDEM_HAS_VIS
    QVERIFY2(m_result.note.empty(), m_result.note.c_str());
    const auto image = support::readPng((m_out / "runout_dense.png").string());
    QVERIFY(image);
    // The band of the 5 deg submerged case (1.9 to 3.0 at the end), where no other band lies:
    // Tableau orange (255, 127, 14) at alpha 60/255 over white.
    const int band = support::pixelsNear(image, 255, 225, 198, 10);
    QVERIFY2(band > 3000, std::to_string(band).c_str());
    const auto slope = support::readPng((m_out / "runout_vs_slope.png").string());
    QVERIFY(slope);
    // The dense bands: Tableau blue (31, 119, 180) at alpha 60/255 over white.
    QVERIFY2(support::pixelsNear(slope, 202, 223, 237, 10) > 3000,
             "no band in runout_vs_slope.png");
#else
    QVERIFY(m_result.note.find("no VTK") != std::string::npos);
#endif
}

QTEST_GUILESS_MAIN(SweepEnsembleTest)
#include "SweepEnsembleTest.moc"
