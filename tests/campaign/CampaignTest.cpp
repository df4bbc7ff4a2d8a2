// The campaign library on its own: each scene's declared study defaults resolve against what its
// runs report, and the band of a finished ensemble is read back from a synthetic sweep folder.
#include "campaign/EnsembleBand.h"
#include "campaign/StudyMetrics.h"
#include "solver/io/CaseLoader.h"
#include "solver/scene/CaseSchema.h"
#include "solver/scene/SceneKind.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

using namespace lbdem;
namespace fs = std::filesystem;

namespace {

/// A run folder: summary.json (finished or not) and a timeseries.csv whose runout column is
/// scale * t/tau_c at t/tau_c = 0, 0.5, ..., lastTc.
void writeRun(const fs::path& dir, bool finished, double scale, double lastTc) {
    fs::create_directories(dir);
    std::ofstream(dir / "summary.json")
        << "{\"finished\": " << (finished ? "true" : "false") << "}\n";
    std::ofstream series(dir / "timeseries.csv");
    series << "t_s,t_over_tc,step,runout_normalised\n";
    for (int k = 0; 0.5 * k <= lastTc + 1e-12; ++k)
        series << 0.1 * k << "," << 0.5 * k << "," << 10 * k << "," << scale * 0.5 * k << "\n";
}

/// A sample case of the repository, with overrides.
solver::CaseSpec sampleCase(const std::string& file, const std::vector<std::string>& set = {}) {
    return io::loadCase(std::string(LBDEM_SOURCE_DIR) + "/sample_cases/" + file, set);
}

} // namespace

class CampaignTest : public QObject {
    Q_OBJECT
private slots:
    void everySceneDeclaresItsStudyDefaults() {
        const std::map<solver::SceneKind, std::string> samples{
            {solver::SceneKind::ColumnCollapse, "default.toml"},
            {solver::SceneKind::Poiseuille, "verification/poiseuille.toml"},
            {solver::SceneKind::TaylorGreen, "verification/taylor_green.toml"},
            {solver::SceneKind::Cavity, "verification/cavity_re100.toml"},
            {solver::SceneKind::Cylinder, "verification/cylinder_2d1.toml"}};
        QCOMPARE(solver::enumValues<solver::SceneKind>().size(), solver::sceneDecls().size());
        for (const auto& decl : solver::sceneDecls()) {
            QCOMPARE(solver::sceneDecl(decl.kind).kind, decl.kind); // in enum order
            const auto sample = samples.find(decl.kind);
            // Only the scenes `lbdem run` can run are studied; each has a sample case.
            QCOMPARE(decl.studyMetric.empty(), sample == samples.end());
            if (sample == samples.end()) continue;
            QVERIFY2(solver::CaseSchema::instance().find(decl.resolutionKey),
                     decl.resolutionKey.c_str());
            const auto spec = sampleCase(sample->second);
            QCOMPARE(spec.scene, decl.kind);
            const std::string metric = campaign::defaultStudyMetric(spec);
            QCOMPARE(metric, decl.studyMetric);
            QCOMPARE(campaign::resolveStudyMetric(spec, metric).name, metric);
        }
    }

    void cavityAwayFromGhiaFallsBack() {
        QCOMPARE(campaign::defaultStudyMetric(sampleCase("verification/cavity_re100.toml")),
                 std::string("ghia_max_deviation"));
        const auto re400 = sampleCase("verification/cavity_re100.toml", {"flow.reynolds=400"});
        QCOMPARE(campaign::defaultStudyMetric(re400), std::string("max_mach"));
        QCOMPARE(campaign::resolveStudyMetric(re400, "max_mach").name, std::string("max_mach"));
    }

    void bandOfAFinishedEnsemble() {
        QTemporaryDir tmp;
        const fs::path out = tmp.path().toStdString();
        writeRun(out / "dense_s1", true, 1.0, 2.0);
        writeRun(out / "dense_s2", true, 3.0, 2.0);
        writeRun(out / "dense_s10", true, 2.0, 1.5);        // covers less: the band stops at 1.5
        writeRun(out / "dense_s3", false, 100.0, 2.0);      // unfinished: left out
        writeRun(out / "dense_sx", true, 100.0, 2.0);       // not a seed folder
        writeRun(out / "dense_loose_s1", true, 100.0, 2.0); // another case
        const auto runs = campaign::finishedEnsembleRuns(out, "dense");
        QCOMPARE(runs.size(), std::size_t(3));
        QCOMPARE(runs[0].filename().string(), std::string("dense_s1"));
        QCOMPARE(runs[1].filename().string(), std::string("dense_s2"));
        QCOMPARE(runs[2].filename().string(), std::string("dense_s10"));

        const auto band = campaign::loadEnsembleBand(out, "dense", "runout_normalised");
        QCOMPARE(band.runs, 3);
        const std::vector<double> times{0, 0.5, 1.0, 1.5};
        QCOMPARE(band.t_over_tc, times);
        for (std::size_t k = 0; k < times.size(); ++k) {
            // Runouts 1, 3 and 2 times t/tau_c: mean 2t, min t, max 3t.
            QVERIFY(std::abs(band.mean[k] - 2 * times[k]) < 1e-12);
            QVERIFY(std::abs(band.min[k] - times[k]) < 1e-12);
            QVERIFY(std::abs(band.max[k] - 3 * times[k]) < 1e-12);
        }
        QCOMPARE(campaign::loadEnsembleBand(out, "dense", "no_such_column").runs, 0);
        QCOMPARE(campaign::loadEnsembleBand(out, "absent", "runout_normalised").runs, 0);
        QCOMPARE(campaign::loadEnsembleBand(out / "missing", "dense", "runout_normalised").runs, 0);
    }
};

QTEST_GUILESS_MAIN(CampaignTest)
#include "CampaignTest.moc"
