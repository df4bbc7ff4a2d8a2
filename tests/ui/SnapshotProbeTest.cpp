// The probe: fluid values of the nearest node and the disc covering the point.
#include "ui/studio/SnapshotProbe.h"

#include <QTest>

using lbdem::solver::Snapshot;
using lbdem::studio::probeSnapshot;

namespace {

// A 3 x 2 fluid grid with spacing 0.01 m whose values encode the node index, and one disc.
Snapshot makeSnapshot() {
    Snapshot s;
    s.domain_width_m = 0.02;
    s.domain_height_m = 0.01;
    lbdem::solver::SnapshotFluid fluid;
    fluid.nx = 3;
    fluid.ny = 2;
    fluid.spacing_m = 0.01f;
    for (int k = 0; k < 6; ++k) {
        fluid.ux.push_back(float(k));
        fluid.uy.push_back(float(-k));
        fluid.pressure.push_back(float(100 * k));
        fluid.vorticity.push_back(0.f);
        fluid.solid.push_back(k == 4 ? 1.f : 0.f);
    }
    s.fluid = fluid;
    auto& g = s.grains;
    g.x = {0.01f};
    g.y = {0.01f};
    g.radius = {0.002f};
    g.vx = {3.f};
    g.vy = {4.f};
    g.omega = {1.f};
    g.fx = {0.f};
    g.fy = {2.f};
    return s;
}

} // namespace

class SnapshotProbeTest : public QObject {
    Q_OBJECT
private slots:
    void nearestNode_data() {
        QTest::addColumn<double>("x");
        QTest::addColumn<double>("y");
        QTest::addColumn<float>("pressure");
        QTest::newRow("origin") << 0.0 << 0.0 << 0.f;
        QTest::newRow("next to node 1") << 0.0108 << 0.0041 << 100.f;
        QTest::newRow("top right") << 0.0199 << 0.0099 << 500.f;
    }
    void nearestNode() {
        QFETCH(double, x);
        QFETCH(double, y);
        QFETCH(float, pressure);
        const auto result = probeSnapshot(makeSnapshot(), x, y);
        QVERIFY(result.inDomain);
        QVERIFY(result.pressure.has_value());
        QCOMPARE(*result.pressure, pressure);
        QCOMPARE(*result.ux, pressure / 100);
    }
    void grainUnderThePoint() {
        const auto inside = probeSnapshot(makeSnapshot(), 0.0115, 0.0100);
        QVERIFY(inside.grain.has_value());
        QCOMPARE(inside.grainSpeed, 5.f);
        QCOMPARE(inside.grainForce, 2.f);
        QVERIFY(lbdem::studio::describeProbe(inside).contains("grain 0"));
        const auto outside = probeSnapshot(makeSnapshot(), 0.0125, 0.0100);
        QVERIFY(!outside.grain.has_value());
    }
    void outsideTheDomain() {
        const auto result = probeSnapshot(makeSnapshot(), -0.001, 0.005);
        QVERIFY(!result.inDomain);
        QCOMPARE(lbdem::studio::describeProbe(result), QString("outside the domain"));
    }
};

QTEST_GUILESS_MAIN(SnapshotProbeTest)
#include "SnapshotProbeTest.moc"
