// Quick (or, with LBDEM_VERIFY_LONG, long) variants of every coupling verification case must pass
// with both coupling methods.
#include "solver/verification/CouplingVerification.h"

#include <QtTest>
#include <set>

using namespace lbdem::solver;

class CouplingVerificationTest : public QObject {
    Q_OBJECT
private slots:
    void casePasses_data();
    void casePasses();
};

void CouplingVerificationTest::casePasses_data() {
    QTest::addColumn<QString>("name");
    for (const char* name : {"settling-disc", "gebart-square", "disc-shear", "permeability", "near-contact"})
        QTest::newRow(name) << QString(name);
}

void CouplingVerificationTest::casePasses() {
    QFETCH(QString, name);
    VerificationOptions options;
    options.long_run = qEnvironmentVariableIsSet("LBDEM_VERIFY_LONG");
    std::set<std::string> methods;
    for (const auto& c : verificationCases()) {
        if (c.name != name.toStdString()) continue;
        for (const auto& r : c.run(options)) {
            methods.insert(r.method);
            qInfo("%s [%s]: %s = %.6g (reference %.6g, error %.3g, tolerance %.3g, %.1f s)", r.name.c_str(),
                  r.method.c_str(), r.quantity.c_str(), r.value, r.reference, r.error, r.tolerance, r.wall_s);
            QVERIFY2(r.passed, qPrintable(QString::fromStdString(r.method + ": " + r.quantity + ": " + r.source)));
        }
    }
    QCOMPARE(methods, (std::set<std::string>{"bounce_back", "psm"}));
}

QTEST_APPLESS_MAIN(CouplingVerificationTest)
#include "CouplingVerificationTest.moc"
