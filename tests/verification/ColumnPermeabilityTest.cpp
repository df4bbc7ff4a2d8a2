// The column-permeability measurement: disc areas in a window, and the pressure-driven window
// flow against the periodic body-force measurement of the same square cylinder array.
#include "solver/verification/ColumnPermeability.h"
#include "solver/core/Constants.h"
#include "solver/verification/CouplingVerification.h"

#include <QtTest>
#include <cmath>

using namespace lbdem::solver;

class ColumnPermeabilityTest : public QObject {
    Q_OBJECT
private slots:
    void discAreaInRectangle_data();
    void discAreaInRectangle();
    void squareArrayMatchesPeriodicBodyForce_data();
    void squareArrayMatchesPeriodicBodyForce();
};

void ColumnPermeabilityTest::discAreaInRectangle_data() {
    QTest::addColumn<double>("cx");
    QTest::addColumn<double>("cy");
    QTest::addColumn<double>("fraction"); // of pi r^2, r = 1, rectangle [0, 10] x [0, 10]
    QTest::newRow("inside") << 5.0 << 5.0 << 1.0;
    QTest::newRow("half, cut by x = 0") << 0.0 << 5.0 << 0.5;
    QTest::newRow("quarter, corner") << 10.0 << 10.0 << 0.25;
    QTest::newRow("outside") << -1.5 << 5.0 << 0.0;
    // A segment: centre 0.5 outside, the area beyond a chord at distance 0.5 is
    // (acos(0.5) - 0.5 sqrt(0.75)) / pi of the disc.
    QTest::newRow("segment") << -0.5 << 5.0 << (std::acos(0.5) - 0.5 * std::sqrt(0.75)) / kPi;
}

void ColumnPermeabilityTest::discAreaInRectangle() {
    QFETCH(double, cx);
    QFETCH(double, cy);
    QFETCH(double, fraction);
    const double area = lbdem::solver::discAreaInRectangle(cx, cy, 1.0, 0, 10, 0, 10);
    QVERIFY2(std::abs(area - fraction * kPi) < 1e-4, qPrintable(QString::number(area / kPi)));
}

void ColumnPermeabilityTest::squareArrayMatchesPeriodicBodyForce_data() {
    QTest::addColumn<int>("method");
    QTest::newRow("bounce_back") << static_cast<int>(coupling::CouplingMethod::BounceBack);
    QTest::newRow("psm") << static_cast<int>(coupling::CouplingMethod::Psm);
}

// A row of cylinders at solid fraction 0.5 between free-slip planes through the array's symmetry
// lines, with a pressure drop along it, is the periodic square array: its K must equal the one
// the periodic body-force case measures (gebart-square) with the same lattice. This checks the
// mirror-plane sides, the pressure fit and the flux that the column windows rely on.
void ColumnPermeabilityTest::squareArrayMatchesPeriodicBodyForce() {
    QFETCH(int, method);
    const auto m = static_cast<coupling::CouplingMethod>(method);
    const int cell = 40, cells = 6;
    const double tau = 0.8, radius = std::sqrt(0.5 / kPi) * cell;
    WindowFlowSetup s;
    s.nx = (cells + 2) * cell; // one empty cell before and after the array
    s.ny = cell;
    for (int k = 0; k < cells; ++k)
        s.discs.push_back({cell * (k + 1.5), cell / 2.0, radius});
    s.collision.model = lattice::CollisionModel::Mrt;
    s.collision.tau = tau;
    s.collision.s_q = 1.0 / (0.5 + (3.0 / 16.0) / (tau - 0.5)); // as gebart-square
    s.method = m;
    s.hydro_radius_ratio = 1;
    s.fit_x0 = 2 * cell; // four whole periods in the middle
    s.fit_x1 = 6 * cell;
    s.slab = cell;
    s.gradient = 1e-7;
    s.tolerance = 1e-4;
    const WindowFlowResult window = measureWindowPermeability(s);
    const CouplingRun periodic = gebartSquare(m, cell, 0.5);
    const double kWindow = window.k / (radius * radius);
    qInfo("K/R^2: window %.6f (%lld steps), periodic %.6f", kWindow, window.steps, periodic.value);
    QVERIFY(window.converged);
    QVERIFY(std::abs(kWindow / periodic.value - 1) < 0.01);
}

QTEST_APPLESS_MAIN(ColumnPermeabilityTest)
#include "ColumnPermeabilityTest.moc"
