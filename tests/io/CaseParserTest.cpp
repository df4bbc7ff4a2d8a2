// Case parser: each kind of bad input gives one sentence naming file, line and key.
#include "solver/core/InputError.h"
#include "solver/io/CaseLoader.h"
#include "solver/io/CaseWriter.h"
#include "solver/scene/CaseSchema.h"

#include <QtTest>

using namespace lbdem;

class CaseParserTest : public QObject {
    Q_OBJECT
private slots:
    void badCase_data();
    void badCase();
    void defaultsRoundTrip();
    void overrides();
    void badOverride_data();
    void badOverride();
    void everyKeyDocumented();
};

void CaseParserTest::badCase_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("line");
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("hint");
    QTest::newRow("misspelt key") << "misspelt_key.toml" << 5 << "fluid.tua"
                                  << "did you mean 'fluid.tau'?";
    QTest::newRow("out of range") << "out_of_range.toml" << 4 << "grains.packing"
                                  << "allowed 0.5 to 0.9";
    QTest::newRow("wrong type") << "wrong_type.toml" << 4 << "grains.count"
                                << "expected a whole number, got a string";
    QTest::newRow("unknown section") << "unknown_section.toml" << 3 << "flud"
                                     << "did you mean [fluid]?";
    QTest::newRow("bad choice") << "bad_choice.toml" << 4 << "fluid.collision"
                                << "one of bgk, mrt, mrt_les";
    QTest::newRow("invalid toml") << "invalid_toml.toml" << 3 << ""
                                  << "is not valid TOML";
    QTest::newRow("missing schema") << "missing_schema.toml" << 1 << "schema"
                                    << "schema = 1";
    QTest::newRow("tau below half") << "tau_below_half.toml" << 4 << "fluid.tau"
                                    << "must exceed 0.5";
    QTest::newRow("fractional integer") << "fractional_integer.toml" << 4 << "grains.count"
                                        << "expected a whole number";
}

void CaseParserTest::badCase() {
    QFETCH(QString, file);
    QFETCH(int, line);
    QFETCH(QString, key);
    QFETCH(QString, hint);
    const std::string path = LBDEM_SOURCE_DIR "/tests/data/bad_cases/" + file.toStdString();
    try {
        io::loadCase(path);
        QFAIL("the bad case was accepted");
    } catch (const solver::InputError& error) {
        const QString message = QString::fromStdString(error.what());
        QVERIFY2(message.contains(file + ":" + QString::number(line) + ":"), qPrintable(message));
        if (!key.isEmpty()) QVERIFY2(message.contains("'" + key + "'"), qPrintable(message));
        QVERIFY2(message.contains(hint), qPrintable(message));
        QVERIFY2(!message.contains('\n'), "the message must be one line");
    }
}

void CaseParserTest::defaultsRoundTrip() {
    solver::CaseSpec changed = solver::defaultCase();
    changed.name = "round_trip-2.v1"; // every character a case name may hold
    changed.fluid.tau = 0.5123;
    changed.grains.count = 321;
    changed.fluid.enabled = false;
    changed.coupling.method = solver::coupling::CouplingMethod::Psm;
    const std::string text = io::formatCase(changed);
    const solver::CaseSpec back = io::parseCase(text, "roundtrip.toml");
    for (const auto& decl : solver::CaseSchema::instance().params())
        QVERIFY2(decl.get(back) == decl.get(changed),
                 qPrintable(QString::fromStdString(decl.path())));
}

void CaseParserTest::overrides() {
    const auto spec = io::parseCase("schema = 1\n[fluid]\ntau = 0.51\n", "o.toml",
                                    {"fluid.tau=0.52", "grains.count=40", "fluid.enabled=false",
                                     "fluid.collision=bgk", "name=\"quoted\""});
    QCOMPARE(spec.fluid.tau, 0.52);
    QCOMPARE(spec.grains.count, 40);
    QCOMPARE(spec.fluid.enabled, false);
    QCOMPARE(spec.fluid.collision, solver::lattice::CollisionModel::Bgk);
    QCOMPARE(QString::fromStdString(spec.name), QString("quoted"));
}

void CaseParserTest::badOverride_data() {
    QTest::addColumn<QString>("assignment");
    QTest::addColumn<QString>("hint");
    QTest::newRow("unknown") << "fluid.tua=0.5"
                             << "did you mean 'fluid.tau'?";
    QTest::newRow("type") << "grains.count=abc"
                          << "expected a whole number";
    QTest::newRow("range") << "grains.packing=2"
                           << "out of range";
    QTest::newRow("no equals") << "fluid.tau"
                               << "expected section.key=value";
    QTest::newRow("cross-key") << "fluid.tau=0.4"
                               << "must exceed 0.5";
}

void CaseParserTest::badOverride() {
    QFETCH(QString, assignment);
    QFETCH(QString, hint);
    try {
        io::parseCase("schema = 1\n", "o.toml", {assignment.toStdString()});
        QFAIL("the bad override was accepted");
    } catch (const solver::InputError& error) {
        const QString message = QString::fromStdString(error.what());
        QVERIFY2(message.contains(hint), qPrintable(message));
        QVERIFY2(message.contains("--set"), qPrintable(message));
    }
}

void CaseParserTest::everyKeyDocumented() {
    for (const auto& decl : solver::CaseSchema::instance().params()) {
        QVERIFY2(!decl.doc.empty(), decl.path().c_str());
        QVERIFY2(!decl.unit.empty(), decl.path().c_str());
        QVERIFY2(decl.check(decl.defaultValue()).empty(), decl.path().c_str());
    }
}

QTEST_APPLESS_MAIN(CaseParserTest)
#include "CaseParserTest.moc"
