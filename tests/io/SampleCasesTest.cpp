// Every file in sample_cases/ parses and plans without error (docs/style.md, Style §5).
#include "solver/io/CaseLoader.h"
#include "solver/scene/Plan.h"

#include <QDirIterator>
#include <QtTest>
#include <cmath>

using namespace lbdem;

class SampleCasesTest : public QObject {
    Q_OBJECT
private slots:
    void parsesAndPlans_data();
    void parsesAndPlans();
};

void SampleCasesTest::parsesAndPlans_data() {
    QTest::addColumn<QString>("path");
    const QString root = QStringLiteral(LBDEM_SOURCE_DIR "/sample_cases");
    QDirIterator it(root, {"*.toml"}, QDir::Files, QDirIterator::Subdirectories);
    int count = 0;
    while (it.hasNext()) {
        const QString path = it.next();
        if (path.contains("/studies/") || QFileInfo(path).fileName().startsWith("sweep"))
            continue; // not case files
        QTest::newRow(qPrintable(path.mid(root.size() + 1))) << path;
        ++count;
    }
    QVERIFY2(count > 0, "no sample cases found");
}

void SampleCasesTest::parsesAndPlans() {
    QFETCH(QString, path);
    const solver::CaseSpec spec = io::loadCase(path.toStdString());
    const solver::Plan plan = solver::makePlan(spec);
    QVERIFY(plan.steps > 0);
    QVERIFY(std::isfinite(plan.dt_s) && plan.dt_s > 0);
    if (plan.has_fluid) QVERIFY(plan.nx > 0 && plan.ny > 0 && plan.tau > 0.5);
}

QTEST_APPLESS_MAIN(SampleCasesTest)
#include "SampleCasesTest.moc"
