// motionRms tells sound from incompressible flow: a plane sound wave carries u = c_s rho'/rho_0
// (linear acoustics), so its acoustic speed equals its speed; a shear wave carries no density
// excess to first order, so its acoustic speed is a small fraction of its speed.
#include "solver/lattice/D2Q9.h"
#include "solver/lattice/FluidMotion.h"
#include "solver/lattice/Lattice.h"

#include <QtTest>
#include <cmath>
#include <vector>

using namespace lbdem::solver;
using namespace lbdem::solver::lattice;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A periodic box, MRT + LES at the column scene's tau = 0.503 (sample_cases/default.toml).
LatticeSetup periodicBox(int nx, int ny) {
    LatticeSetup setup;
    setup.nx = nx;
    setup.ny = ny;
    setup.left.type = setup.right.type = setup.top.type = setup.bottom.type = SideType::Periodic;
    setup.collision.model = CollisionModel::MrtLes;
    setup.collision.tau = 0.503;
    return setup;
}

std::vector<long long> everyFluidNode(const Lattice& lattice) {
    std::vector<long long> cells;
    for (long long cell = 0; cell < lattice.cells(); ++cell)
        if (lattice.isFluid(cell)) cells.push_back(cell);
    return cells;
}

} // namespace

class LatticeFluidMotionTest : public QObject {
    Q_OBJECT
private slots:
    void soundWaveIsAllAcoustic();
    void shearWaveIsNotAcoustic();
    void noNodesGiveZero();
};

void LatticeFluidMotionTest::soundWaveIsAllAcoustic() {
    // A right-going wave rho' = A cos(k x), u_x = c_s rho', followed for half a period.
    const int nx = 128;
    Lattice lattice(periodicBox(nx, 4));
    const double amplitude = 1e-4, k = 2 * kPi / nx, cs = std::sqrt(kCs2);
    lattice.initialise([&](double x, double, double& rho, double& ux, double& uy) {
        rho = 1 + amplitude * std::cos(k * x);
        ux = cs * amplitude * std::cos(k * x);
        uy = 0;
    });
    for (int s = 0; s < static_cast<int>(nx / (2 * cs)); ++s)
        lattice.step();
    const MotionRms motion = motionRms(lattice, everyFluidNode(lattice));
    qInfo("sound wave: rms speed %.4g, acoustic %.4g (A c_s / sqrt 2 = %.4g)", motion.speed,
          motion.acoustic, amplitude * cs / std::sqrt(2.0));
    QVERIFY(motion.speed > 0.9 * amplitude * cs / std::sqrt(2.0)); // the wave is still there
    QVERIFY2(std::abs(motion.acoustic / motion.speed - 1) < 0.02,
             qPrintable(QString("acoustic / speed = %1").arg(motion.acoustic / motion.speed)));
}

void LatticeFluidMotionTest::shearWaveIsNotAcoustic() {
    // u_y = A sin(k x) at uniform density: a decaying shear wave, incompressible in the limit.
    const int nx = 64;
    Lattice lattice(periodicBox(nx, 4));
    const double amplitude = 1e-3, k = 2 * kPi / nx;
    lattice.initialise([&](double x, double, double& rho, double& ux, double& uy) {
        rho = 1;
        ux = 0;
        uy = amplitude * std::sin(k * x);
    });
    for (int s = 0; s < 200; ++s)
        lattice.step();
    const MotionRms motion = motionRms(lattice, everyFluidNode(lattice));
    qInfo("shear wave: rms speed %.4g, acoustic %.4g", motion.speed, motion.acoustic);
    QVERIFY(motion.speed > 0.5 * amplitude / std::sqrt(2.0));
    QVERIFY2(motion.acoustic < 0.01 * motion.speed,
             qPrintable(QString("acoustic / speed = %1").arg(motion.acoustic / motion.speed)));
}

void LatticeFluidMotionTest::noNodesGiveZero() {
    const Lattice lattice(periodicBox(8, 8));
    const MotionRms motion = motionRms(lattice, {});
    QCOMPARE(motion.speed, 0.0);
    QCOMPARE(motion.acoustic, 0.0);
}

QTEST_APPLESS_MAIN(LatticeFluidMotionTest)
#include "LatticeFluidMotionTest.moc"
