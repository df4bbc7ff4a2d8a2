// The metrics declared in SceneMetrics.h are exactly those the flow scenes report, and every
// metric declared with a reference reports NAME_reference (what `lbdem study` relies on).
#include "solver/scene/SceneMetrics.h"
#include "solver/io/CaseLoader.h"
#include "solver/scene/FlowScene.h"
#include "solver/scene/Plan.h"

#include <QtTest>

#include <set>

using namespace lbdem;

class SceneMetricsTest : public QObject {
    Q_OBJECT
private slots:
    void declaredMatchesReported_data();
    void declaredMatchesReported();
};

void SceneMetricsTest::declaredMatchesReported_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<QStringList>("overrides");
    QTest::addColumn<bool>("hasReference");
    const QString steps = "flow.steps=10";
    QTest::newRow("poiseuille") << "poiseuille.toml" << QStringList{"flow.nodes=8", steps} << true;
    QTest::newRow("taylor_green") << "taylor_green.toml" << QStringList{"flow.nodes=8", steps}
                                  << true;
    QTest::newRow("cavity Re 100")
        << "cavity_re100.toml" << QStringList{"flow.nodes=16", steps} << true;
    QTest::newRow("cavity, other Re")
        << "stability.toml" << QStringList{"flow.nodes=16", steps} << false;
    QTest::newRow("cylinder 2D-1")
        << "cylinder_2d1.toml" << QStringList{"flow.nodes=8", steps} << true;
    QTest::newRow("cylinder, Re 40")
        << "cylinder_2d1.toml" << QStringList{"flow.nodes=8", steps, "flow.reynolds=40"} << false;
}

void SceneMetricsTest::declaredMatchesReported() {
    QFETCH(QString, file);
    QFETCH(QStringList, overrides);
    QFETCH(bool, hasReference);
    std::vector<std::string> sets;
    for (const auto& o : overrides)
        sets.push_back(o.toStdString());
    const auto spec =
        io::loadCase(LBDEM_SOURCE_DIR "/sample_cases/verification/" + file.toStdString(), sets);
    const auto plan = solver::makePlan(spec);
    solver::FlowScene scene(spec, plan);
    scene.runToEnd();
    const auto reported = scene.metrics();
    std::set<std::string> reportedNames, declaredNames;
    for (const auto& [name, value] : reported)
        reportedNames.insert(name);
    bool anyReference = false;
    for (const auto& decl : solver::sceneMetrics(spec)) {
        declaredNames.insert(decl.name);
        anyReference = anyReference || decl.reference != solver::MetricReference::None;
        if (decl.reference == solver::MetricReference::Field)
            QVERIFY2(reported.count(decl.name + solver::kReferenceSuffix), decl.name.c_str());
    }
    const auto join = [](const std::set<std::string>& names) {
        QStringList list;
        for (const auto& name : names)
            list << QString::fromStdString(name);
        return list.join(", ");
    };
    QCOMPARE(join(declaredNames), join(reportedNames));
    QCOMPARE(anyReference, hasReference);
}

QTEST_APPLESS_MAIN(SceneMetricsTest)
#include "SceneMetricsTest.moc"
