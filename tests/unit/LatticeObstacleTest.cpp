// Fixed obstacles: solid marking, interpolated bounce-back and momentum-exchange force.
#include "solver/lattice/Lattice.h"

#include <QtTest>
#include <cmath>

using namespace lbdem::solver::lattice;

class LatticeObstacleTest : public QObject {
    Q_OBJECT
private slots:
    void forceBalancesBodyForce_data();
    void forceBalancesBodyForce();
    void polygonMarksItsInterior();
};

void LatticeObstacleTest::forceBalancesBodyForce_data() {
    QTest::addColumn<bool>("polygon");
    QTest::newRow("disc") << false;
    QTest::newRow("square") << true;
}

void LatticeObstacleTest::forceBalancesBodyForce() {
    // Fully periodic box with one obstacle, driven by a body force F per node: in the steady
    // state the obstacle carries all of it, so the momentum-exchange force is F x (fluid nodes).
    // Interpolated links are not exactly momentum conserving; 0.5 % is allowed.
    QFETCH(bool, polygon);
    LatticeSetup setup;
    setup.nx = 40;
    setup.ny = 30;
    setup.left.type = setup.right.type = setup.bottom.type = setup.top.type = SideType::Periodic;
    setup.collision.model = CollisionModel::Mrt;
    setup.collision.tau = 0.8;
    setup.fx = 2e-6;
    Lattice lattice(setup);
    const int owner =
        polygon ? lattice.addPolygon({{15.3, 10.2}, {24.7, 10.2}, {24.7, 19.8}, {15.3, 19.8}})
                : lattice.addDisc(20.0, 15.0, 5.3);
    long long fluid = 0;
    for (long long c = 0; c < lattice.cells(); ++c)
        fluid += lattice.isFluid(c) ? 1 : 0;
    for (int s = 0; s < 8000; ++s)
        lattice.step();
    const ObstacleLoad& load = lattice.obstacleLoad(owner);
    const double expected = setup.fx * fluid;
    QVERIFY2(std::abs(load.fx - expected) < 5e-3 * expected,
             qPrintable(QString("drag %1, body force %2").arg(load.fx).arg(expected)));
    QVERIFY(std::abs(load.fy) < 1e-3 * expected);     // symmetric about y = 15
    QVERIFY(std::abs(load.torque) < 1e-2 * expected); // about the centre of the symmetric body
}

void LatticeObstacleTest::polygonMarksItsInterior() {
    LatticeSetup setup;
    setup.nx = 20;
    setup.ny = 20;
    Lattice lattice(setup);
    // Node centres sit at half-integers: the square [4, 10] x [4, 10] holds 6 x 6 of them.
    lattice.addPolygon({{4.0, 4.0}, {10.0, 4.0}, {10.0, 10.0}, {4.0, 10.0}});
    long long solid = 0;
    for (int j = lattice.firstFluidY(); j < lattice.firstFluidY() + 20; ++j)
        for (int i = lattice.firstFluidX(); i < lattice.firstFluidX() + 20; ++i)
            solid += lattice.isFluid(lattice.index(i, j)) ? 0 : 1;
    QCOMPARE(solid, 36LL);
}

QTEST_APPLESS_MAIN(LatticeObstacleTest)
#include "LatticeObstacleTest.moc"
