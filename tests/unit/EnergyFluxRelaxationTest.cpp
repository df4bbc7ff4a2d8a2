// Re-relaxing the energy flux of chosen nodes gives what colliding them at that s_q gives.
#include "solver/lattice/EnergyFluxRelaxation.h"

#include <QtTest>
#include <cmath>
#include <stdexcept>

using namespace lbdem::solver;
using namespace lbdem::solver::lattice;

namespace {

/// A periodic 24 x 24 box with a sheared, compressed flow (every moment off equilibrium after
/// a step), MRT at tau = 0.503 and the given s_q.
Lattice box(double sq, PopulationStorage storage) {
    LatticeSetup setup;
    setup.nx = setup.ny = 24;
    setup.left.type = setup.right.type = setup.bottom.type = setup.top.type = SideType::Periodic;
    setup.collision.model = CollisionModel::Mrt;
    setup.collision.tau = 0.503;
    setup.collision.s_q = sq;
    setup.storage = storage;
    Lattice lattice(setup);
    const double k = 2 * M_PI / 24;
    lattice.initialise([=](double x, double y, double& rho, double& ux, double& uy) {
        ux = 0.05 * std::sin(k * y) + 0.02 * std::cos(3 * k * x);
        uy = 0.03 * std::cos(2 * k * x + k * y);
        rho = 1 + 0.01 * std::sin(k * (x + 2 * y));
    });
    lattice.step();
    lattice.step(); // both parities of the AA layout
    return lattice;
}

/// Largest |difference| between the populations of two lattices of one size.
double largestDifference(const Lattice& a, const Lattice& b) {
    const auto fa = a.exportPopulations(), fb = b.exportPopulations();
    double worst = 0;
    for (std::size_t k = 0; k < fa.size(); ++k)
        worst = std::max(worst, std::abs(fa[k] - fb[k]));
    return worst;
}

} // namespace

class EnergyFluxRelaxationTest : public QObject {
    Q_OBJECT
private slots:
    void rescaledNodesMatchTheirOwnRate();
    void factorOneChangesNothing();
    void bulkRateOfOneIsRefused();
};

void EnergyFluxRelaxationTest::rescaledNodesMatchTheirOwnRate() {
    // One step at s_q = 1.9 then the last collision's q rescaled to s_q = 0.0159 (Lambda = 3/16 at
    // tau = 0.503), against a lattice whose last step collided at 0.0159: the same to round-off.
    const double bulk = 1.9, local = 0.0159;
    Lattice a = box(bulk, PopulationStorage::Double);
    Lattice reference = a;
    CollisionParams params = reference.setup().collision;
    params.s_q = local;
    reference.setCollision(params);
    a.step();
    reference.step();
    QVERIFY(largestDifference(a, reference) > 1e-6); // the two rates differ measurably
    std::vector<long long> cells;
    for (long long c = 0; c < a.cells(); ++c)
        cells.push_back(c);
    rescaleEnergyFlux(a, cells, energyFluxFactor(bulk, local));
    QVERIFY2(largestDifference(a, reference) < 1e-14,
             qPrintable(QString::number(largestDifference(a, reference))));
}

void EnergyFluxRelaxationTest::factorOneChangesNothing() {
    Lattice a = box(1.9, PopulationStorage::Float);
    const Lattice before = a;
    std::vector<long long> cells{0, 5, 100, 300};
    rescaleEnergyFlux(a, cells, 1.0);
    QCOMPARE(largestDifference(a, before), 0.0);
}

void EnergyFluxRelaxationTest::bulkRateOfOneIsRefused() {
    QVERIFY_EXCEPTION_THROWN(energyFluxFactor(1.0, 0.5), std::invalid_argument);
}

QTEST_APPLESS_MAIN(EnergyFluxRelaxationTest)
#include "EnergyFluxRelaxationTest.moc"
