// Each lattice boundary condition against a flow it must reproduce exactly or nearly so.
#include "solver/core/InputError.h"
#include "solver/lattice/Lattice.h"
#include "solver/lattice/StabilityGuard.h"

#include <QtTest>
#include <cmath>
#include <limits>

using namespace lbdem::solver;
using namespace lbdem::solver::lattice;

class LatticeBoundaryTest : public QObject {
    Q_OBJECT
private slots:
    void couetteBounceBackAndMovingWall_data();
    void couetteBounceBackAndMovingWall();
    void periodicConservesMomentum();
    void freeSlipKeepsPlugFlow();
    void zouHeImposesVelocityAndPressure();
    void pressureBoundaryRelaxesDensity();
    void closedBoxConservesMass_data();
    void closedBoxConservesMass();
    void guardNamesStepAndCause();
    void guardFindsTheFirstBadNode_data();
    void guardFindsTheFirstBadNode();

private:
    static double meanUx(const Lattice& lattice, int j);
};

double LatticeBoundaryTest::meanUx(const Lattice& lattice, int j) {
    double sum = 0;
    for (int i = lattice.firstFluidX(); i < lattice.firstFluidX() + lattice.setup().nx; ++i) {
        double ux, uy;
        lattice.velocity(lattice.index(i, j), ux, uy);
        sum += ux;
    }
    return sum / lattice.setup().nx;
}

void LatticeBoundaryTest::couetteBounceBackAndMovingWall_data() {
    QTest::addColumn<int>("model");
    QTest::newRow("bgk") << int(CollisionModel::Bgk);
    QTest::newRow("mrt") << int(CollisionModel::Mrt);
}

void LatticeBoundaryTest::couetteBounceBackAndMovingWall() {
    // Couette flow u(y) = U y / H: half-way bounce-back is exact for a linear profile, so the
    // resting wall gives u = 0 and the moving wall u = U at the half-way wall positions.
    QFETCH(int, model);
    LatticeSetup setup;
    setup.nx = 4;
    setup.ny = 16;
    setup.left.type = setup.right.type = SideType::Periodic;
    setup.top.ux = 0.05;
    setup.collision.model = static_cast<CollisionModel>(model);
    setup.collision.tau = 1.0;
    Lattice lattice(setup);
    for (int s = 0; s < 6000; ++s)
        lattice.step();
    for (int j = 0; j < setup.ny; ++j) {
        const double y = j + 0.5, exact = 0.05 * y / setup.ny;
        QVERIFY2(std::abs(meanUx(lattice, lattice.firstFluidY() + j) - exact) < 1e-6,
                 qPrintable(QString("row %1: %2 vs %3")
                                .arg(j)
                                .arg(meanUx(lattice, lattice.firstFluidY() + j) - exact)
                                .arg(exact)));
    }
}

void LatticeBoundaryTest::periodicConservesMomentum() {
    // A shear wave in a fully periodic box: streaming across every edge conserves momentum.
    LatticeSetup setup;
    setup.nx = 24;
    setup.ny = 16;
    setup.left.type = setup.right.type = setup.bottom.type = setup.top.type = SideType::Periodic;
    setup.collision.model = CollisionModel::MrtLes;
    Lattice lattice(setup);
    lattice.initialise([](double x, double y, double& rho, double& ux, double& uy) {
        rho = 1.0 + 0.01 * std::sin(0.3 * x);
        ux = 0.03 + 0.02 * std::sin(2 * M_PI * y / 16);
        uy = -0.01 + 0.02 * std::cos(2 * M_PI * x / 24);
    });
    auto momentum = [&](double& px, double& py) {
        px = py = 0;
        for (long long c = 0; c < lattice.cells(); ++c) {
            double ux, uy;
            lattice.velocity(c, ux, uy);
            px += lattice.density(c) * ux;
            py += lattice.density(c) * uy;
        }
    };
    double px0, py0, px1, py1;
    momentum(px0, py0);
    for (int s = 0; s < 500; ++s)
        lattice.step();
    momentum(px1, py1);
    QVERIFY(std::abs(px1 - px0) < 1e-11 * std::abs(px0));
    QVERIFY(std::abs(py1 - py0) < 1e-11 * std::abs(py0));
}

void LatticeBoundaryTest::freeSlipKeepsPlugFlow() {
    // Free-slip walls exert no shear and let no mass through: a plug flow stays a plug flow.
    LatticeSetup setup;
    setup.nx = 8;
    setup.ny = 8;
    setup.left.type = setup.right.type = SideType::Periodic;
    setup.bottom.type = setup.top.type = SideType::FreeSlip;
    setup.collision.model = CollisionModel::Mrt;
    Lattice lattice(setup);
    lattice.initialise([](double, double, double& rho, double& ux, double& uy) {
        rho = 1;
        ux = 0.05;
        uy = 0;
    });
    for (int s = 0; s < 2000; ++s)
        lattice.step();
    for (long long c = 0; c < lattice.cells(); ++c) {
        if (!lattice.isFluid(c)) continue;
        double ux, uy;
        lattice.velocity(c, ux, uy);
        QVERIFY(std::abs(ux - 0.05) < 1e-12);
        QVERIFY(std::abs(uy) < 1e-12);
    }
}

void LatticeBoundaryTest::zouHeImposesVelocityAndPressure() {
    // Zou-He inlet (u = 0.04) and outlet (rho = 1) with free-slip walls: a uniform stream.
    LatticeSetup setup;
    setup.nx = 20;
    setup.ny = 6;
    setup.left.type = SideType::ZouHeVelocity;
    setup.left.ux = 0.04;
    setup.right.type = SideType::ZouHePressure;
    setup.right.rho = 1.0;
    setup.bottom.type = setup.top.type = SideType::FreeSlip;
    setup.collision.model = CollisionModel::Mrt;
    Lattice lattice(setup);
    // Start from the expected stream: Zou-He sides reflect sound, so a start from rest rings.
    lattice.initialise([](double, double, double& rho, double& ux, double& uy) {
        rho = 1;
        ux = 0.04;
        uy = 0;
    });
    const long long slot = lattice.index(5, 3); // the rest population of node (5, 3)
    lattice.setPopulation(
        slot, 0, lattice.population(slot, 0) + 1e-3); // a disturbance the boundaries must clear
    for (int s = 0; s < 4000; ++s)
        lattice.step();
    for (int j = lattice.firstFluidY(); j < lattice.firstFluidY() + setup.ny; ++j) {
        double ux, uy;
        lattice.velocity(lattice.index(0, j), ux, uy);
        QVERIFY2(std::abs(ux - 0.04) < 1e-9, qPrintable(QString::number(ux)));
        QVERIFY(std::abs(uy) < 1e-9);
        QVERIFY(std::abs(lattice.density(lattice.index(lattice.nx() - 1, j)) - 1.0) < 1e-9);
        lattice.velocity(lattice.index(lattice.nx() / 2, j), ux, uy);
        QVERIFY2(std::abs(ux - 0.04) < 1e-5,
                 qPrintable(QString("row %1: %2 %3").arg(j).arg(ux - 0.04).arg(uy)));
    }
}

void LatticeBoundaryTest::pressureBoundaryRelaxesDensity() {
    // A closed box with an open top at rho = 1: an initial overpressure drains out.
    LatticeSetup setup;
    setup.nx = 16;
    setup.ny = 16;
    setup.top.type = SideType::Pressure;
    setup.top.rho = 1.0;
    setup.collision.model = CollisionModel::Mrt;
    Lattice lattice(setup);
    lattice.initialise([](double, double, double& rho, double& ux, double& uy) {
        rho = 1.01;
        ux = uy = 0;
    });
    const double initial = lattice.totalMass() / (16 * 16);
    for (int s = 0; s < 8000; ++s)
        lattice.step();
    const double mean = lattice.totalMass() / (16 * 16);
    QVERIFY(std::abs(initial - 1.01) < 1e-12);
    QVERIFY2(std::abs(mean - 1.0) < 1e-4, qPrintable(QString::number(mean, 'g', 12)));
}

void LatticeBoundaryTest::closedBoxConservesMass_data() {
    QTest::addColumn<int>("model");
    QTest::newRow("bgk") << int(CollisionModel::Bgk);
    QTest::newRow("mrt") << int(CollisionModel::Mrt);
    QTest::newRow("mrt_les") << int(CollisionModel::MrtLes);
}

void LatticeBoundaryTest::closedBoxConservesMass() {
    // Resting bounce-back walls conserve mass exactly; only rounding remains (double).
    QFETCH(int, model);
    LatticeSetup setup;
    setup.nx = 32;
    setup.ny = 24;
    setup.collision.model = static_cast<CollisionModel>(model);
    setup.collision.tau = 0.6;
    Lattice box(setup);
    box.initialise([](double x, double y, double& rho, double& ux, double& uy) {
        rho = 1.0 + 0.02 * std::cos(0.4 * x) * std::sin(0.3 * y);
        ux = 0.05 * std::sin(0.2 * y);
        uy = -0.03 * std::cos(0.25 * x);
    });
    const double before = box.totalMass();
    for (int s = 0; s < 2000; ++s)
        box.step();
    const double after = box.totalMass();
    QVERIFY2(std::abs(after - before) / before < 1e-12,
             qPrintable(QString("relative change %1").arg(std::abs(after - before) / before)));
}

void LatticeBoundaryTest::guardNamesStepAndCause() {
    LatticeSetup setup;
    setup.nx = 8;
    setup.ny = 8;
    setup.collision.model = CollisionModel::Bgk;
    setup.collision.tau = 0.5001;
    const StabilityGuard guard(1e-3);
    // The guard must stop `lattice` with a message holding every one of `parts`.
    auto expectStop = [&guard](const Lattice& lattice, const QStringList& parts) {
        try {
            guard.check(lattice);
        } catch (const SimulationError& error) {
            const QString message = error.what();
            for (const QString& part : parts)
                QVERIFY2(message.contains(part), qPrintable(message));
            return;
        }
        QFAIL(qPrintable("the guard did not stop: expected " + parts.join(", ")));
    };
    Lattice lattice(setup);
    guard.check(lattice); // at rest: fine
    lattice.setPopulation(lattice.index(3, 4), 0,
                          std::numeric_limits<double>::quiet_NaN()); // rest population of (3, 4)
    expectStop(lattice, {"step 0", "(3, 4)", "too close to 0.5"});
    // A node at rest with 60 % of its mass gone (a drained sealed pore) stops the run too.
    Lattice drained(setup);
    const long long cell = drained.index(5, 2);
    for (int q = 0; q < kQ; ++q)
        drained.setPopulation(drained.postSlot(cell, q), q, 0.4 * kW[q]);
    expectStop(drained, {"(5, 2)", "density is 0.4", "seal off"});
}

void LatticeBoundaryTest::guardFindsTheFirstBadNode_data() {
    QTest::addColumn<int>("storage");
    QTest::addColumn<int>("steps");
    for (int storage : {int(PopulationStorage::Double), int(PopulationStorage::Float)})
        for (int steps : {0, 1})
            QTest::newRow(
                qPrintable(QString("%1, %2 steps")
                               .arg(storage == int(PopulationStorage::Float) ? "float" : "double")
                               .arg(steps)))
                << storage << steps;
}

void LatticeBoundaryTest::guardFindsTheFirstBadNode() {
    // The guard scans edge nodes through the lattice's accessors and the others at fixed slot
    // offsets of the step's parity; either way it must name the first bad fluid node in cell
    // order. Periodic sides: the lattice's edge columns and rows are fluid.
    QFETCH(int, storage);
    QFETCH(int, steps);
    LatticeSetup setup;
    setup.nx = 12;
    setup.ny = 10;
    setup.left.type = setup.right.type = setup.bottom.type = setup.top.type = SideType::Periodic;
    setup.storage = static_cast<PopulationStorage>(storage);
    const StabilityGuard guard(1e-3);
    auto firstBad = [&guard](const Lattice& lattice) -> QString {
        try {
            guard.check(lattice);
        } catch (const SimulationError& error) {
            const QString message = error.what();
            const int at = message.indexOf("node (");
            return message.mid(at, message.indexOf(')', at) - at + 1);
        }
        return "none";
    };
    // Slow the node down to a stop and scale its mass: rho = scale, u = 0.
    auto setDensity = [](Lattice& lattice, int i, int j, double scale) {
        const long long cell = lattice.index(i, j);
        for (int q = 0; q < kQ; ++q)
            lattice.setPopulation(lattice.postSlot(cell, q), q, scale * kW[q]);
    };
    Lattice lattice(setup);
    for (int s = 0; s < steps; ++s)
        lattice.step();
    QCOMPARE(firstBad(lattice), QString("none"));
    setDensity(lattice, 6, 7, 2.5); // interior, too dense
    QCOMPARE(firstBad(lattice), QString("node (6, 7)"));
    setDensity(lattice, 11, 4, 0.3); // the right edge column, earlier in cell order
    QCOMPARE(firstBad(lattice), QString("node (11, 4)"));
    setDensity(lattice, 3, 4, 0.45); // interior, in the same row and earlier still
    QCOMPARE(firstBad(lattice), QString("node (3, 4)"));
    setDensity(lattice, 5, 0, 3.0); // the bottom edge row
    QCOMPARE(firstBad(lattice), QString("node (5, 0)"));
    // A node just inside the limits passes.
    Lattice mild(setup);
    for (int s = 0; s < steps; ++s)
        mild.step();
    setDensity(mild, 6, 7, 1.9);
    setDensity(mild, 0, 5, 0.6);
    QCOMPARE(firstBad(mild), QString("none"));
}

QTEST_APPLESS_MAIN(LatticeBoundaryTest)
#include "LatticeBoundaryTest.moc"
