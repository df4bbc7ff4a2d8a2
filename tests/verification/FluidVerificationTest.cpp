// Quick variants of every fluid verification case (lbdem verify NAME) must pass.
#include "solver/verification/FluidVerification.h"

#include <QtTest>

using namespace lbdem::solver;

class FluidVerificationTest : public QObject {
    Q_OBJECT
private slots:
    void casePasses_data();
    void casePasses();
};

void FluidVerificationTest::casePasses_data() {
    QTest::addColumn<QString>("name");
    for (const char* name : {"poiseuille", "taylor-green", "cavity-re100", "cylinder-2d1", "stability"})
        QTest::newRow(name) << QString(name);
}

void FluidVerificationTest::casePasses() {
    QFETCH(QString, name);
    VerificationOptions options;
    options.long_run = qEnvironmentVariableIsSet("LBDEM_VERIFY_LONG");
    int checked = 0;
    for (const auto& c : fluidVerificationCases()) {
        if (c.name != name.toStdString()) continue;
        for (const auto& r : c.run(options)) {
            ++checked;
            qInfo("%s: %s = %.6g (reference %.6g, error %.3g, tolerance %.3g, %.1f s)", r.name.c_str(),
                  r.quantity.c_str(), r.value, r.reference, r.error, r.tolerance, r.wall_s);
            QVERIFY2(r.passed, qPrintable(QString::fromStdString(r.quantity + ": " + r.source)));
        }
    }
    QVERIFY(checked > 0);
}

QTEST_APPLESS_MAIN(FluidVerificationTest)
#include "FluidVerificationTest.moc"
