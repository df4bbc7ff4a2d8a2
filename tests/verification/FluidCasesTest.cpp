// sample_cases/verification/*.toml describe exactly the cases `lbdem verify` runs.
#include "solver/io/CaseLoader.h"
#include "solver/scene/FlowPlan.h"
#include "solver/scene/Plan.h"
#include "solver/verification/FluidVerification.h"

#include <QtTest>

using namespace lbdem;

class FluidCasesTest : public QObject {
    Q_OBJECT
private slots:
    void sampleMatchesBuilder_data();
    void sampleMatchesBuilder();
};

void FluidCasesTest::sampleMatchesBuilder_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QString>("scene");
    QTest::addColumn<int>("nodes");
    QTest::addColumn<QString>("collision");
    QTest::newRow("poiseuille") << "poiseuille.toml"
                                << "poiseuille" << 16 << "mrt";
    QTest::newRow("taylor_green") << "taylor_green.toml"
                                  << "taylor_green" << 32 << "mrt";
    QTest::newRow("cavity") << "cavity_re100.toml"
                            << "cavity" << 128 << "mrt";
    QTest::newRow("cylinder") << "cylinder_2d1.toml"
                              << "cylinder" << 20 << "mrt";
}

void FluidCasesTest::sampleMatchesBuilder() {
    QFETCH(QString, file);
    QFETCH(QString, scene);
    QFETCH(int, nodes);
    QFETCH(QString, collision);
    const auto fromFile =
        io::loadCase(LBDEM_SOURCE_DIR "/sample_cases/verification/" + file.toStdString());
    const auto built = solver::fluidCase(
        solver::enumFromWord<solver::SceneKind>(scene.toStdString()).value(), nodes,
        solver::enumFromWord<solver::lattice::CollisionModel>(collision.toStdString()).value());
    const auto a = solver::flowScales(fromFile), b = solver::flowScales(built);
    QCOMPARE(fromFile.scene, built.scene);
    QCOMPARE(fromFile.fluid.collision, built.fluid.collision);
    QCOMPARE(a.nx, b.nx);
    QCOMPARE(a.ny, b.ny);
    QCOMPARE(a.steps, b.steps);
    QVERIFY(std::abs(a.tau - b.tau) < 1e-12);
    QVERIFY(std::abs(a.u_peak - b.u_peak) < 1e-12);
    QVERIFY(std::abs(a.dt_s - b.dt_s) < 1e-12 * b.dt_s);
    QVERIFY(std::abs(fromFile.fluid.s_q - built.fluid.s_q) < 1e-12);
    QVERIFY(std::abs(fromFile.fluid.density_kg_m3 - built.fluid.density_kg_m3) < 1e-12);
    QVERIFY(solver::makePlan(fromFile).steps > 0);
}

QTEST_APPLESS_MAIN(FluidCasesTest)
#include "FluidCasesTest.moc"
