// Dry column-collapse scene: the gate opens at t = 0, the column spreads, snapshots are consistent.
#include "solver/scene/ColumnScene.h"
#include "tests/support/SmallDryColumn.h"

#include <QTemporaryDir>
#include <QtTest>
#include <algorithm>
#include <cmath>

using namespace lbdem::solver;

class DemColumnSceneTest : public QObject {
    Q_OBJECT
private slots:
    void gravityTiltsAndBuoys();
    void columnCollapsesPastGate();
};

void DemColumnSceneTest::gravityTiltsAndBuoys() {
    CaseSpec spec = defaultCase();
    spec.domain.slope_deg = 30;
    spec.fluid.enabled = false;
    const Vec2 dry = grainGravity(spec);
    QVERIFY(std::abs(dry.x() - 9.81 * 0.5) < 1e-12);
    QVERIFY(std::abs(dry.y() + 9.81 * std::sqrt(3.0) / 2) < 1e-12);
    spec.fluid.enabled = true;
    const Vec2 wet = grainGravity(spec);
    QVERIFY(std::abs(wet.x() / dry.x() - (1 - 1000.0 / 2650.0)) < 1e-12);
}

void DemColumnSceneTest::columnCollapsesPastGate() {
    CaseSpec spec = lbdem::support::smallDryColumn(0.82);
    spec.domain.slope_deg = 5;
    QTemporaryDir dir;
    const Plan plan = makePlan(spec);
    ColumnScene scene(spec, plan, lbdem::support::packingIn(dir));
    QCOMPARE(scene.demTimeStep(), plan.dem_dt_s);
    QVERIFY(!scene.system().walls()[scene.gateWall()].active);
    QVERIFY(std::abs(scene.packing().fraction - 0.82) <= 0.005);
    const double tc = std::sqrt(scene.initialHeight() / spec.domain.gravity_m_s2);
    while (scene.time() < 1.5 * tc)
        scene.step();
    const auto& p = scene.system().particles();
    double front = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        front = std::max(front, p.x[i] + p.radius[i]);
    QVERIFY(front > scene.initialWidth() + spec.grains.d_min_m);

    Snapshot snapshot;
    scene.fillSnapshot(snapshot);
    QCOMPARE(snapshot.grains.size(), p.size());
    QVERIFY(snapshot.grains.hydro_fx.empty());
    QVERIFY(snapshot.contacts.size() > 0);
    for (std::size_t k = 0; k < snapshot.contacts.size(); ++k) {
        QVERIFY(snapshot.contacts.i[k] >= 0 && snapshot.contacts.i[k] < static_cast<int>(p.size()));
        QVERIFY(snapshot.contacts.j[k] >= -1 &&
                snapshot.contacts.j[k] < static_cast<int>(p.size()));
    }
    QCOMPARE(snapshot.walls.size(), std::size_t(3)); // floor, left and right; the gate is gone
    bool wallContact = false;
    for (std::size_t k = 0; k < snapshot.contacts.size(); ++k)
        if (snapshot.contacts.j[k] == -1)
            wallContact = wallContact || std::abs(snapshot.contacts.wy[k]) < 1e-6f;
    QVERIFY(wallContact);
}

QTEST_APPLESS_MAIN(DemColumnSceneTest)
#include "DemColumnSceneTest.moc"
