// Edit distance and nearest-key suggestions.
#include "solver/core/TextDistance.h"

#include <QtTest>

using namespace lbdem::solver;

class TextDistanceTest : public QObject {
    Q_OBJECT
private slots:
    void distance_data();
    void distance();
    void nearest();
};

void TextDistanceTest::distance_data() {
    QTest::addColumn<QString>("a");
    QTest::addColumn<QString>("b");
    QTest::addColumn<int>("expected");
    QTest::newRow("equal") << "tau"
                           << "tau" << 0;
    QTest::newRow("substitution") << "tau"
                                  << "tan" << 1;
    QTest::newRow("transposition") << "fluid.tua"
                                   << "fluid.tau" << 2;
    QTest::newRow("insertion") << "flud"
                               << "fluid" << 1;
    QTest::newRow("empty") << ""
                           << "abc" << 3;
    QTest::newRow("kitten") << "kitten"
                            << "sitting" << 3;
}

void TextDistanceTest::distance() {
    QFETCH(QString, a);
    QFETCH(QString, b);
    QFETCH(int, expected);
    QCOMPARE(editDistance(a.toStdString(), b.toStdString()), expected);
}

void TextDistanceTest::nearest() {
    const std::vector<std::string> keys{"fluid.tau", "fluid.target_mach", "grains.count"};
    QCOMPARE(QString::fromStdString(nearestWord("fluid.tua", keys)), QString("fluid.tau"));
    QCOMPARE(QString::fromStdString(nearestWord("grains.cuont", keys)), QString("grains.count"));
    QVERIFY(nearestWord("something.unrelated.entirely", keys).empty());
}

QTEST_APPLESS_MAIN(TextDistanceTest)
#include "TextDistanceTest.moc"
