// The grid-scale share of vorticity on synthetic fields whose answers are known exactly.
#include "solver/diagnostics/GridNoise.h"
#include "solver/core/OpenMp.h"

#include <QtTest>
#include <cmath>
#include <random>
#include <vector>

using namespace lbdem::solver;

namespace {

/// A velocity field and solid mask of nx x ny nodes.
struct Field {
    int nx, ny;
    std::vector<double> ux, uy;
    std::vector<std::uint8_t> solid;
    bool periodic = true;
    Field(int x, int y) : nx(x), ny(y), ux(x * y), uy(x * y), solid(x * y) {}
    std::size_t at(int i, int j) const { return static_cast<std::size_t>(j) * nx + i; }
    GridNoiseField view() const {
        return {nx, ny, ux.data(), uy.data(), solid.data(), periodic, periodic};
    }
};

/// u_y = sin(a i) cos(b j): omega = sin(a) cos(a i) cos(b j), whose 3 x 3 box mean is the same
/// mode times (1 + 2 cos a)(1 + 2 cos b) / 9, so the share is |1 - that factor| at every node.
Field mode(int n, double a, double b) {
    Field f(n, n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            f.uy[f.at(i, j)] = std::sin(a * i) * std::cos(b * j);
    return f;
}

double modeShare(double a, double b) {
    return std::abs(1 - (1 + 2 * std::cos(a)) * (1 + 2 * std::cos(b)) / 9);
}

} // namespace

class GridNoiseTest : public QObject {
    Q_OBJECT
private slots:
    void smoothModeIsNearZero();
    void gridScaleModeIsNearOne();
    void randomVelocitiesGiveTheirExpectedShare();
    void fieldWithoutVorticityHasNoNoise();
    void solidsAndTheirMarginAreLeftOut();
    void closedEdgesCountAsSolid();
    void independentOfThreadCount();
};

void GridNoiseTest::smoothModeIsNearZero() {
    // One period over 64 nodes: share (2/3)(1 - cos(2 pi / 64)) = 0.00321.
    const double k = 2 * M_PI / 64;
    const GridNoise noise = gridNoise(mode(64, k, 0).view());
    QCOMPARE(noise.nodes, 64LL * 64);
    QVERIFY(std::abs(noise.share - modeShare(k, 0)) < 1e-12);
    QVERIFY(std::abs(noise.share - 2.0 / 3 * (1 - std::cos(k))) < 1e-12);
    QVERIFY(noise.share < 0.004);
}

void GridNoiseTest::gridScaleModeIsNearOne() {
    // A period of 4 nodes along both axes, the shortest that central differences see: 8/9.
    const GridNoise noise = gridNoise(mode(64, M_PI / 2, M_PI / 2).view());
    QVERIFY(std::abs(noise.share - 8.0 / 9) < 1e-12);
}

void GridNoiseTest::randomVelocitiesGiveTheirExpectedShare() {
    // Independent velocities of variance s^2: var(omega) = s^2, cov(omega, box) = s^2 / 9,
    // var(box) = 6 s^2 / 81, so share^2 = 1 - 2/9 + 6/81 = 69/81. Over 256^2 nodes the sampling
    // error is well under 0.01.
    Field f(256, 256);
    std::mt19937 random(7);
    std::normal_distribution<double> normal(0.0, 1.0);
    for (std::size_t k = 0; k < f.ux.size(); ++k) {
        f.ux[k] = normal(random);
        f.uy[k] = normal(random);
    }
    const GridNoise noise = gridNoise(f.view());
    QVERIFY2(std::abs(noise.share - std::sqrt(69.0 / 81)) < 0.01,
             qPrintable(QString::number(noise.share)));
}

void GridNoiseTest::fieldWithoutVorticityHasNoNoise() {
    Field f(32, 32);
    for (double& u : f.ux)
        u = 0.1; // uniform flow
    const GridNoise noise = gridNoise(f.view());
    QCOMPARE(noise.nodes, 32LL * 32);
    QCOMPARE(noise.share, 0.0);
}

void GridNoiseTest::solidsAndTheirMarginAreLeftOut() {
    // Wild velocities on a 3 x 3 block of solid nodes (a covered node's leftovers) leave the
    // smooth mode's share as it was: the measured nodes are those whose 5 x 5 block holds no
    // solid node, 7 x 7 nodes fewer.
    const double k = 2 * M_PI / 64;
    Field f = mode(64, k, 0);
    const int ci = 30, cj = 20;
    for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
            f.solid[f.at(ci + di, cj + dj)] = 1;
            f.ux[f.at(ci + di, cj + dj)] = (di + dj) % 2 ? 1e3 : -1e3;
        }
    const GridNoise noise = gridNoise(f.view());
    QCOMPARE(noise.nodes, 64LL * 64 - 49);
    QVERIFY(std::abs(noise.share - modeShare(k, 0)) < 1e-12);
    // A wild fluid node three nodes from the block is measured.
    f.ux[f.at(ci + 4, cj)] = 1e3;
    QVERIFY(gridNoise(f.view()).share > 0.5);
}

void GridNoiseTest::closedEdgesCountAsSolid() {
    Field f = mode(40, 2 * M_PI / 40, 0);
    f.periodic = false;
    QCOMPARE(gridNoise(f.view()).nodes, 36LL * 36); // two nodes off each edge
    Field tiny(4, 4);
    tiny.periodic = false;
    QVERIFY(std::isnan(gridNoise(tiny.view()).share)); // no node qualifies
}

void GridNoiseTest::independentOfThreadCount() {
    Field f(200, 150);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    for (std::size_t k = 0; k < f.ux.size(); ++k) {
        f.ux[k] = uniform(random);
        f.uy[k] = uniform(random);
        f.solid[k] = uniform(random) > 0.98;
    }
    const int threads = ompMaxThreads();
    ompSetThreads(1);
    const double one = gridNoise(f.view()).share;
    ompSetThreads(4);
    const double four = gridNoise(f.view()).share;
    ompSetThreads(threads);
    QCOMPARE(four, one); // bit for bit
}

QTEST_APPLESS_MAIN(GridNoiseTest)
#include "GridNoiseTest.moc"
