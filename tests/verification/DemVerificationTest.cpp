// The quick DEM verification cases (restitution, incline, packing) pass at their tolerances.
#include "solver/verification/Verification.h"

#include <QtTest>

using namespace lbdem::solver;

class DemVerificationTest : public QObject {
    Q_OBJECT
private slots:
    void passes_data();
    void passes();
};

void DemVerificationTest::passes_data() {
    QTest::addColumn<QString>("name");
    QTest::newRow("restitution") << "restitution";
    QTest::newRow("incline") << "incline";
    QTest::newRow("packing") << "packing";
}

void DemVerificationTest::passes() {
    QFETCH(QString, name);
    const VerificationCase* found = nullptr;
    for (const auto& c : verificationCases())
        if (c.name == name.toStdString()) found = &c;
    QVERIFY(found);
    VerificationOptions options;
    options.threads = 1;
    const auto results = found->run(options);
    QVERIFY(!results.empty());
    for (const auto& r : results) {
        qInfo("%s %s: value %.6g ref %.6g err %.3g tol %.3g", r.name.c_str(), r.quantity.c_str(), r.value,
              r.reference, r.error, r.tolerance);
        QVERIFY2(r.passed, r.quantity.c_str());
        QVERIFY(!r.source.empty());
    }
}

QTEST_APPLESS_MAIN(DemVerificationTest)
#include "DemVerificationTest.moc"
