// The absorbing layer: a pressure pulse leaves through the open sides instead of coming back.
#include "solver/core/InputError.h"
#include "solver/lattice/AbsorbingLayer.h"
#include "solver/lattice/Lattice.h"

#include <QtTest>
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

using namespace lbdem::solver;
using namespace lbdem::solver::lattice;

namespace {

// The column scene's fluid: MRT + LES at tau = 0.503 (sample_cases/default.toml), where sound
// is barely damped by viscosity, so whatever comes back is the boundary's doing.
CollisionParams columnCollision() {
    CollisionParams c;
    c.model = CollisionModel::MrtLes;
    c.tau = 0.503;
    return c;
}

// Density excess at one node after each of `steps` steps, the layer (if any) applied after each.
template <class Init>
std::vector<double> probeSeries(const LatticeSetup& setup,
                                const std::optional<AbsorbingLayerSetup>& layerSetup,
                                const Init& init, int probeX, int probeY, int steps) {
    Lattice lattice(setup);
    lattice.initialise(init);
    std::optional<AbsorbingLayer> layer;
    if (layerSetup) layer.emplace(lattice, *layerSetup);
    const long long probe =
        lattice.index(lattice.firstFluidX() + probeX, lattice.firstFluidY() + probeY);
    std::vector<double> series;
    for (int s = 0; s < steps; ++s) {
        lattice.step();
        if (layer) layer->apply(lattice);
        series.push_back(lattice.density(probe) - 1.0);
    }
    return series;
}

double maxAbs(const std::vector<double>& v, std::size_t from, std::size_t to) {
    double m = 0;
    for (std::size_t k = from; k < std::min(to, v.size()); ++k)
        m = std::max(m, std::abs(v[k]));
    return m;
}

} // namespace

class LatticeAbsorbingLayerTest : public QObject {
    Q_OBJECT
private slots:
    void strengthRisesTowardTheOpenSides();
    void rejectsBadSetup();
    void planeWaveLeavesTheOpenSide();
    void circularPulseLeavesTheOpenCorner();
};

void LatticeAbsorbingLayerTest::strengthRisesTowardTheOpenSides() {
    // Walls left and bottom, pressure top and right: only the top rows and right columns are in
    // the layer, and sigma grows toward the side as ((N - d) / N)^2.
    LatticeSetup setup;
    setup.nx = 40;
    setup.ny = 30;
    setup.top.type = setup.right.type = SideType::Pressure;
    Lattice lattice(setup);
    AbsorbingLayer layer(lattice, {8, 0.5, 1.0});
    QCOMPARE(layer.nodeCount(), std::size_t(40 * 30 - 32 * 22));
    for (std::size_t k = 0; k < layer.nodeCount(); ++k) {
        const long long cell = layer.cellAt(k);
        const int i = static_cast<int>(cell % lattice.nx()) - lattice.firstFluidX();
        const int j = static_cast<int>(cell / lattice.nx()) - lattice.firstFluidY();
        const double d = std::min(39 - i, 29 - j) + 0.5, depth = (8 - d) / 8;
        QVERIFY(std::abs(layer.strengthAt(k) - 0.5 * depth * depth) < 1e-12);
    }
    // Nothing to absorb where no side is open.
    LatticeSetup closed = setup;
    closed.top.type = closed.right.type = SideType::Wall;
    QCOMPARE(AbsorbingLayer(Lattice(closed), {8, 0.5, 1.0}).nodeCount(), std::size_t(0));
}

void LatticeAbsorbingLayerTest::rejectsBadSetup() {
    LatticeSetup setup;
    setup.nx = setup.ny = 8;
    setup.top.type = SideType::Pressure;
    Lattice lattice(setup);
    QVERIFY_EXCEPTION_THROWN(AbsorbingLayer(lattice, {-1, 0.3, 1.0}), InputError);
    QVERIFY_EXCEPTION_THROWN(AbsorbingLayer(lattice, {4, 1.5, 1.0}), InputError);
}

void LatticeAbsorbingLayerTest::planeWaveLeavesTheOpenSide() {
    // A right-going Gaussian pulse, rho' = A exp(-(x - x0)^2 / 2 w^2) with u = c_s rho' / rho_0
    // (the simple wave of linear acoustics), in a channel periodic in y with a wall on the left
    // and the constant-pressure side on the right. A probe half-way records the incident pulse,
    // then whatever the right side sends back (a pressure side alone reflects it whole, with the
    // opposite sign). Requirement: reflected amplitude below 5 % of the incident.
    LatticeSetup setup;
    setup.nx = 600;
    setup.ny = 2;
    setup.bottom.type = setup.top.type = SideType::Periodic;
    setup.right.type = SideType::Pressure;
    setup.collision = columnCollision();
    const double amplitude = 1e-3, x0 = 150, width = 8, cs = std::sqrt(kCs2);
    auto pulse = [&](double x, double, double& rho, double& ux, double& uy) {
        const double excess = amplitude * std::exp(-(x - x0) * (x - x0) / (2 * width * width));
        rho = 1 + excess;
        ux = cs * excess;
        uy = 0;
    };
    const int probe = 300;
    // The pulse meets the side after (nx - x0) / c_s steps; its echo passes the probe after
    // (2 nx - x0 - probe) / c_s steps; margins of 5 w.
    const auto atSide = static_cast<std::size_t>((setup.nx - x0) / cs);
    const auto end = static_cast<int>((2 * setup.nx - x0 - probe + 5 * width) / cs);
    const auto open = probeSeries(setup, std::nullopt, pulse, probe, 0, end);
    const auto absorbed = probeSeries(setup, AbsorbingLayerSetup{}, pulse, probe, 0, end);
    const double incident = maxAbs(open, 0, atSide);
    const double reflectedOpen = maxAbs(open, atSide, open.size()) / incident;
    const double reflectedLayer = maxAbs(absorbed, atSide, absorbed.size()) / incident;
    qInfo("plane wave: incident %.3g, reflected %.4f (pressure side alone), %.5f (with the layer)",
          incident, reflectedOpen, reflectedLayer);
    QVERIFY(std::abs(incident - amplitude) < 0.1 * amplitude); // the probe saw the pulse go by
    QVERIFY2(reflectedOpen > 0.5, "the probe must see the echo of the bare pressure side");
    QVERIFY2(reflectedLayer < 0.05,
             qPrintable(QString("reflected %1 of the incident").arg(reflectedLayer)));
}

void LatticeAbsorbingLayerTest::circularPulseLeavesTheOpenCorner() {
    // A Gaussian density bump at rest in a box with walls left and bottom and pressure sides top
    // and right (the column scene's boundaries): the pulse spreads as a ring and meets the open
    // sides at every angle of incidence. The reference is the same pulse in a box whose open
    // sides are too far to be heard within the window; the reflection is the largest difference
    // at a probe between the pulse and the open corner, against the reference's peak there. The
    // probe keeps 40 nodes from the layer (the default 24 nodes thick): what it measures is what
    // comes back, not the layer's own near field. The window lets the echoes of the pulse and
    // of its images in the walls pass the probe.
    const int box = 160, wide = 250, x0 = 48, probe = 72, steps = 560;
    const double amplitude = 1e-3, width = 3;
    auto bump = [&](double x, double y, double& rho, double& ux, double& uy) {
        const double r2 = (x - x0) * (x - x0) + (y - x0) * (y - x0);
        rho = 1 + amplitude * std::exp(-r2 / (2 * width * width));
        ux = uy = 0;
    };
    LatticeSetup setup;
    setup.top.type = setup.right.type = SideType::Pressure;
    setup.collision = columnCollision();
    setup.nx = setup.ny = wide;
    // The reference's far sides send their echo back to the probe after at least
    // (2 wide - x0 - probe) / c_s > steps.
    QVERIFY((2 * wide - x0 - probe) / std::sqrt(kCs2) > steps);
    const auto reference = probeSeries(setup, std::nullopt, bump, probe, probe, steps);
    setup.nx = setup.ny = box;
    const auto open = probeSeries(setup, std::nullopt, bump, probe, probe, steps);
    const auto absorbed = probeSeries(setup, AbsorbingLayerSetup{}, bump, probe, probe, steps);
    const double incident = maxAbs(reference, 0, reference.size());
    double errorOpen = 0, errorLayer = 0;
    for (int s = 0; s < steps; ++s) {
        errorOpen = std::max(errorOpen, std::abs(open[s] - reference[s]) / incident);
        errorLayer = std::max(errorLayer, std::abs(absorbed[s] - reference[s]) / incident);
    }
    qInfo("circular pulse: incident %.3g, reflected %.4f (pressure sides alone), %.5f (with the "
          "layer)",
          incident, errorOpen, errorLayer);
    QVERIFY2(errorOpen > 0.3, "the probe must see the echo of the bare pressure sides");
    QVERIFY2(errorLayer < 0.05,
             qPrintable(QString("reflected %1 of the incident").arg(errorLayer)));
}

QTEST_APPLESS_MAIN(LatticeAbsorbingLayerTest)
#include "LatticeAbsorbingLayerTest.moc"
