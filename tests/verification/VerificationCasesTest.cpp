// Every case `lbdem verify --list` names passes: the quick variants by default, the long ones (and
// the cases marked slow) with LBDEM_VERIFY_LONG set. One data row per registered case; CTest
// runs the rows in shards (LBDEM_VERIFY_SHARD) so that they share its parallel slots.
#include "solver/verification/Verification.h"

#include <QtTest>
#include <algorithm>
#include <set>

using namespace lbdem::solver;

class VerificationCasesTest : public QObject {
    Q_OBJECT
private slots:
    void casePasses_data();
    void casePasses();
};

namespace {
bool longRun() {
    return qEnvironmentVariableIsSet("LBDEM_VERIFY_LONG");
}

/// LBDEM_VERIFY_SHARD = "k/n": run only every n-th selected case starting at the k-th (from 0),
/// so that CTest can spread the cases over its parallel slots; unset: every case.
bool inShard(int selected) {
    const QStringList parts = qEnvironmentVariable("LBDEM_VERIFY_SHARD").split('/');
    if (parts.size() != 2) return true;
    const int k = parts[0].toInt(), n = std::max(parts[1].toInt(), 1);
    return selected % n == k;
}
} // namespace

void VerificationCasesTest::casePasses_data() {
    QTest::addColumn<int>("index");
    const auto& cases = verificationCases();
    int selected = 0;
    for (std::size_t k = 0; k < cases.size(); ++k) {
        if (!longRun() && cases[k].slow) continue;
        if (inShard(selected++)) QTest::newRow(cases[k].name.c_str()) << static_cast<int>(k);
    }
}

void VerificationCasesTest::casePasses() {
    QFETCH(int, index);
    const VerificationCase& c = verificationCases().at(static_cast<std::size_t>(index));
    VerificationOptions options;
    options.long_run = longRun();
    const auto results = c.run(options);
    QVERIFY2(!results.empty(), "the case compared nothing");
    std::set<std::string> methods;
    for (const auto& r : results) {
        qInfo("%s [%s]: %s = %.6g (reference %.6g, error %.3g, tolerance %.3g, %.1f s)",
              r.name.c_str(), r.method.c_str(), r.quantity.c_str(), r.value, r.reference, r.error,
              r.tolerance, r.wall_s);
        QVERIFY2(!r.source.empty(),
                 qPrintable(QString::fromStdString(r.quantity + ": no source cited")));
        QVERIFY2(r.passed,
                 qPrintable(QString::fromStdString(r.method + " " + r.quantity + ": " + r.source)));
        methods.insert(r.method);
    }
    // A coupling case runs both methods side by side.
    if (methods.count("bounce_back") || methods.count("psm"))
        QCOMPARE(methods, (std::set<std::string>{"bounce_back", "psm"}));
}

QTEST_APPLESS_MAIN(VerificationCasesTest)
#include "VerificationCasesTest.moc"
