// Grain mapping of the bounce-back coupling: thread-count independence, hostile positions, and
// the covered nodes and links of slow grains against their geometric definition.
#include "solver/coupling/BounceBackCoupling.h"
#include "solver/lattice/D2Q9.h"
#include "tests/unit/CouplingFixtures.h"

#include <QElapsedTimer>
#include <QtTest>
#include <cmath>
#include <omp.h>

using namespace lbdem::solver;
using coupling::CouplingMethod;
using test::kPi;
using test::latticeUnits;
using test::periodicBox;

class CouplingMappingTest : public QObject {
    Q_OBJECT
private slots:
    void threadCountDoesNotMatter();
    void farGrainsScanNoFurtherThanTheLattice();
    void slowGrainsCoverExactlyTheirDiscs();
};

void CouplingMappingTest::threadCountDoesNotMatter() {
    // 120 moving grains on a 320 x 320 lattice: enough surface nodes (over 4096) and cells for the
    // mapping and the kernel to run in parallel. One and two threads must give the same
    // populations and loads bit for bit (the links run row by row, the loads sum in a fixed order).
    auto run = [](int threads, std::vector<double>& f, std::vector<double>& loads) {
        omp_set_num_threads(threads);
        lattice::LatticeSetup s = periodicBox(320);
        s.left.type = s.right.type = lattice::SideType::Wall; // walls and periodic sides both
        lattice::Lattice lat(s);
        lat.initialise([](double x, double y, double& rho, double& ux, double& uy) {
            rho = 1;
            ux = 0.03 * std::sin(2 * kPi * y / 320);
            uy = 0.02 * std::cos(2 * kPi * x / 320);
        });
        dem::DemSystem dem;
        for (int k = 0; k < 120; ++k) {
            const std::size_t p =
                dem.addDisc(20.3 + 25.1 * (k % 12), 14.7 + 30.2 * (k / 12), 8.4 + 0.1 * (k % 5));
            dem.particles().vx[p] = 0.05 * std::sin(k);
            dem.particles().vy[p] = 0.05 * std::cos(3 * k);
            dem.particles().omega[p] = 0.002 * (k % 3 - 1);
        }
        const auto linkOwned =
            coupling::makeCoupling(lat, dem, latticeUnits(CouplingMethod::BounceBack));
        coupling::Coupling& link = *linkOwned;
        for (int step = 0; step < 12; ++step) {
            link.mapGrains();
            lat.step();
            link.collectForces();
            for (std::size_t p = 0; p < dem.particles().size(); ++p) {
                dem.particles().x[p] += dem.particles().vx[p];
                dem.particles().y[p] += dem.particles().vy[p];
            }
        }
        QVERIFY(link.boundaryCount() > 4096);
        f = lat.exportPopulations();
        loads.clear();
        for (std::size_t p = 0; p < dem.particles().size(); ++p) {
            const auto l = link.latticeLoad(p);
            loads.insert(loads.end(), {l.fx, l.fy, l.torque});
        }
    };
    const int before = omp_get_max_threads();
    std::vector<double> f1, f2, l1, l2;
    run(1, f1, l1);
    run(2, f2, l2);
    omp_set_num_threads(before);
    QVERIFY(f1 == f2);
    QVERIFY(l1 == l2);
}

void CouplingMappingTest::farGrainsScanNoFurtherThanTheLattice() {
    // A hostile checkpoint may put grains anywhere. A grain mapped inside the lattice, then moved
    // 5e8 nodes away (its old and new boxes would span 5e8 columns), one at 1e300 and one at NaN:
    // the scans are clipped to the lattice (one period across periodic sides), so mapping takes
    // no longer than for grains inside, and nothing outside is covered.
    for (bool periodic : {false, true}) {
        lattice::LatticeSetup s = periodicBox(60);
        if (!periodic)
            s.left.type = s.right.type = s.bottom.type = s.top.type = lattice::SideType::Wall;
        lattice::Lattice lat(s);
        dem::DemSystem dem;
        dem.addDisc(30.2, 30.7, 6.5);
        dem.addDisc(12.4, 40.1, 5.5);
        dem.addDisc(45.4, 12.1, 5.5);
        coupling::BounceBackCoupling link(lat, dem, latticeUnits(CouplingMethod::BounceBack));
        link.mapGrains();
        lat.step();
        link.collectForces();
        auto& g = dem.particles();
        g.x[0] = 5e8;
        g.y[1] = 1e300;
        g.x[2] = std::nan("");
        QElapsedTimer clock;
        clock.start();
        for (int step = 0; step < 3; ++step) {
            link.mapGrains();
            lat.step();
            link.collectForces();
        }
        QVERIFY2(clock.elapsed() < 2000, qPrintable(QString("%1 ms").arg(clock.elapsed())));
        long long covered = 0;
        for (std::int32_t owner : link.owners())
            covered += owner >= 0;
        if (!periodic) QCOMPARE(covered, 0LL); // all three grains left the walled lattice
        QVERIFY(covered < lat.cells());
    }
}

void CouplingMappingTest::slowGrainsCoverExactlyTheirDiscs() {
    // Grains at rest, creeping, trembling and closing on each other and on a wall: a grain within
    // its quiet reach is not rescanned, so after every mapping the owners must still be exactly
    // the geometric ones (a node is covered by the lowest-index grain whose circle holds it) and
    // the links exactly those of the covered nodes with an open neighbour, counted afresh.
    lattice::LatticeSetup s = periodicBox(120);
    s.ny = 80;
    s.left.type = s.right.type = s.bottom.type = s.top.type = lattice::SideType::Wall;
    lattice::Lattice lat(s);
    dem::DemSystem dem;
    const double start[][3] = {{20.3, 20.6, 6.4},  {40.1, 21.2, 7.1}, {60.7, 40.4, 6.2},
                               {73.9, 40.9, 6.6},  {95.2, 60.3, 5.8}, {30.4, 60.8, 6.9},
                               {100.6, 20.1, 7.3}, {12.2, 8.4, 5.3}};
    for (const auto& d : start)
        dem.addDisc(d[0], d[1], d[2]);
    coupling::BounceBackCoupling link(lat, dem, latticeUnits(CouplingMethod::BounceBack));
    auto& g = dem.particles();
    std::size_t quietSteps = 0;
    for (int step = 0; step < 600; ++step) {
        const double t = step;
        g.x[1] = start[1][0] + 1e-4 * t; // creeping
        // Grain 2 presses into grain 3, at rest, takes some of its nodes and leaves them again.
        g.x[2] = start[2][0] + 0.8 * (1 - std::cos(2 * kPi * t / 300));
        g.x[4] = start[4][0] + 0.02 * std::sin(2 * kPi * t / 50);  // trembling
        g.y[5] = start[5][1] + 1e-5 * std::sin(2 * kPi * t / 300); // all but still
        g.x[6] = start[6][0] + 2e-2 * t;                           // into the wall
        g.y[7] = start[7][1] - 1e-3 * t;                           // onto the floor
        link.mapGrains();
        quietSteps += link.unmovedGrains();
        lat.step();
        link.collectForces();
        long long wrong = 0, links = 0;
        const auto& owner = link.owners();
        for (int j = 0; j < lat.ny(); ++j)
            for (int i = 0; i < lat.nx(); ++i) {
                const long long c = lat.index(i, j);
                std::int32_t expected = -1;
                for (std::size_t p = 0; p < g.size() && expected < 0; ++p) {
                    const double dx = lat.nodeX(i) - g.x[p], dy = lat.nodeY(j) - g.y[p];
                    if (lat.isFluid(c) && dx * dx + dy * dy < g.radius[p] * g.radius[p])
                        expected = static_cast<std::int32_t>(p);
                }
                wrong += owner[c] != expected;
                if (owner[c] < 0) continue;
                for (int q = 1; q < lattice::kQ; ++q) {
                    const int ni = i + lattice::kCx[q], nj = j + lattice::kCy[q];
                    if (ni < 0 || nj < 0 || ni >= lat.nx() || nj >= lat.ny()) continue;
                    const long long n = lat.index(ni, nj);
                    links += lat.isFluid(n) && owner[n] < 0;
                }
            }
        QVERIFY2(wrong == 0, qPrintable(QString("step %1: %2 nodes").arg(step).arg(wrong)));
        QCOMPARE(static_cast<long long>(link.boundaryCount()), links);
    }
    // The quiet path was taken: grains 0, 3 and 5 are at rest or all but, most of the time.
    QVERIFY2(quietSteps > 1200, qPrintable(QString("%1 grain-steps").arg(quietSteps)));
}

QTEST_APPLESS_MAIN(CouplingMappingTest)
#include "CouplingMappingTest.moc"
