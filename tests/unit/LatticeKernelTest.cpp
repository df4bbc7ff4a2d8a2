// The bulk stream-collide kernel against the collision operator applied node by node.
#include "solver/lattice/Collision.h"
#include "solver/lattice/Lattice.h"
#include "tests/support/CollisionModelRows.h"

#include <QtTest>
#include <cmath>
#include <random>

using namespace lbdem::solver;
using namespace lbdem::solver::lattice;

class LatticeKernelTest : public QObject {
    Q_OBJECT
private slots:
    void eachNodeCollidesAsTheOperatorAlone_data();
    void eachNodeCollidesAsTheOperatorAlone();
};

void LatticeKernelTest::eachNodeCollidesAsTheOperatorAlone_data() {
    lbdem::support::addCollisionModelRows();
}

void LatticeKernelTest::eachNodeCollidesAsTheOperatorAlone() {
    // Random populations (deviations of 1e-2 from rest, so that every node has its own LES rate)
    // on a periodic 150 x 5 lattice: rows long enough for every vector width and a remainder,
    // and the wrapped first and last columns. Two steps, both parities of the AA pattern: each
    // node's post-collision populations must be those of the operator applied to the
    // populations that arrived there, however the kernel vectorises and orders the nodes
    // (one population stored to the wrong direction showed at ~1e-3).
    QFETCH(int, model);
    QFETCH(double, force);
    LatticeSetup setup;
    setup.nx = 150;
    setup.ny = 5;
    setup.left.type = setup.right.type = setup.bottom.type = setup.top.type = SideType::Periodic;
    setup.collision.model = static_cast<CollisionModel>(model);
    setup.collision.tau = 0.506;
    setup.fx = force;
    setup.fy = -0.6 * force;
    Lattice lattice(setup);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> deviation(-1e-2, 1e-2);
    std::vector<double> start(static_cast<std::size_t>(kQ * lattice.cells()));
    for (std::size_t k = 0; k < start.size(); ++k)
        start[k] = kW[k / lattice.cells()] * (1 + deviation(random));
    lattice.importPopulations(start);
    for (int s = 0; s < 2; ++s) {
        std::vector<double> arrived(start.size());
        for (long long c = 0; c < lattice.cells(); ++c)
            for (int q = 0; q < kQ; ++q)
                arrived[c * kQ + q] = lattice.population(lattice.inSlot(c, q), q);
        lattice.step();
        // The operator alone, in place on what arrived at each node.
        withCollision(setup.collision, setup.fx, setup.fy, [&](const auto& collide) {
            for (long long c = 0; c < lattice.cells(); ++c)
                collide(&arrived[c * kQ]);
        });
        double gap = 0;
        for (long long c = 0; c < lattice.cells(); ++c)
            for (int q = 0; q < kQ; ++q)
                gap = std::max(gap, std::abs(lattice.population(lattice.postSlot(c, q), q) -
                                             arrived[c * kQ + q]));
        // The same expressions in the same order: equal to round-off.
        QVERIFY2(
            gap <= 1e-15,
            qPrintable(QString("step %1: kernel - operator %2").arg(s + 1).arg(gap, 0, 'g', 3)));
    }
}

QTEST_APPLESS_MAIN(LatticeKernelTest)
#include "LatticeKernelTest.moc"
