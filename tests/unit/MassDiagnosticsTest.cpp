// Diagnostics of the granular mass on arrangements whose answers are known exactly.
#include "solver/diagnostics/MassDiagnostics.h"

#include <QtTest>
#include <cmath>

using namespace lbdem::solver;

namespace {

/// Discs of radius r, unit density, on given centres, with velocities vx.
struct Discs {
    std::vector<Real> x, y, r, vx, vy, omega, mass, inertia;
    void add(double cx, double cy, double radius, double u = 0, double w = 0) {
        x.push_back(cx);
        y.push_back(cy);
        r.push_back(radius);
        vx.push_back(u);
        vy.push_back(0);
        omega.push_back(w);
        mass.push_back(M_PI * radius * radius);
        inertia.push_back(0.5 * M_PI * radius * radius * radius * radius);
    }
    GrainArrays view() const {
        return {x.size(),  x.data(),     y.data(),    r.data(),      vx.data(),
                vy.data(), omega.data(), mass.data(), inertia.data()};
    }
};

MassDiagnosticsParams params(double columnWidth) {
    MassDiagnosticsParams p;
    p.contact_gap_m = 1e-6;
    p.bridge_gap_m = 1.0 + 2e-6; // one diameter of the unit discs below plus two contact gaps
    p.column_width_m = columnWidth;
    p.bin_width_m = 1.0;
    p.front_length_m = 2.0;
    p.initial_potential_j_m = 1.0;
    return p;
}

} // namespace

class MassDiagnosticsTest : public QObject {
    Q_OBJECT
private slots:
    void runoutIgnoresDetachedGrains();
    void kineticEnergyIncludesRotation();
    void squarePackingIsPiOverFour();
    void potentialEnergyOnSlope();
    void froudeNumberOfUniformFront();
    void froudeNumberOfFlowingLayerOnly();
    void loneDiscLeavingAChainDoesNotCutIt();
    void tipDiscPartingOrRejoiningMovesFrontByItsDiameter();
};

void MassDiagnosticsTest::runoutIgnoresDetachedGrains() {
    Discs d;
    for (int i = 0; i < 10; ++i)
        d.add(0.5 + i, 0.5, 0.5); // a touching row from x = 0 to 10
    d.add(20.0, 0.5, 0.5);        // a lone grain far ahead
    const auto result = computeMassDiagnostics(d.view(), params(4.0));
    QCOMPARE(result.main_mass_grains, std::size_t(10));
    QVERIFY(std::abs(result.front_x_m - 10.0) < 1e-12);
    QVERIFY(std::abs(result.runout_normalised - 1.5) < 1e-12); // (10 - 4) / 4
}

void MassDiagnosticsTest::kineticEnergyIncludesRotation() {
    Discs d;
    d.add(0, 0, 1.0, 2.0, 3.0); // m = pi, I = pi/2
    const auto result = computeMassDiagnostics(d.view(), params(1.0));
    QVERIFY(std::abs(result.kinetic_energy_j_m - (0.5 * M_PI * 4 + 0.5 * 0.5 * M_PI * 9)) < 1e-12);
}

void MassDiagnosticsTest::squarePackingIsPiOverFour() {
    // Discs of diameter 1 on a square lattice fill pi/4 of the area under their flat top.
    Discs d;
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 10; ++j)
            d.add(0.5 + i, 0.5 + j, 0.5);
    const auto result = computeMassDiagnostics(d.view(), params(20.0));
    QVERIFY2(std::abs(result.packing_fraction - M_PI / 4) < 1e-9,
             qPrintable(QString::number(result.packing_fraction)));
    QVERIFY(std::abs(result.height_m - 10.0) < 1e-12);
}

void MassDiagnosticsTest::potentialEnergyOnSlope() {
    // E_p0 = sum m g h, h the height normal to the slope base, with the full g and no
    // along-slope term (Kumar's thesis): the same disc further downslope has the same energy.
    Discs d;
    d.add(2.0, 1.0, 0.5);
    d.add(7.0, 3.0, 0.5);
    const double m = M_PI * 0.25;
    QVERIFY(std::abs(potentialEnergy(d.view(), 9.81) - m * 9.81 * (1.0 + 3.0)) < 1e-12);
}

void MassDiagnosticsTest::froudeNumberOfUniformFront() {
    // Square packing moving at U = 1, thickness 4: Fr = U / sqrt((rho_m/rho_w - 1) g H).
    Discs d;
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 4; ++j)
            d.add(0.5 + i, 0.5 + j, 0.5, 1.0);
    auto p = params(10.0);
    p.fluid_density = 1000;
    p.grain_density = 2650;
    const auto result = computeMassDiagnostics(d.view(), p);
    const double phi = M_PI / 4, mixture = phi * 2650 + (1 - phi) * 1000;
    const double expected = 1.0 / std::sqrt((mixture / 1000 - 1) * 9.81 * 4.0);
    QVERIFY2(std::abs(result.froude_densimetric - expected) < 1e-9,
             qPrintable(QString::number(result.froude_densimetric)));
}

void MassDiagnosticsTest::froudeNumberOfFlowingLayerOnly() {
    // Four rows of a square packing; the upper two slide at U = 1 over the two at rest: H is the
    // flowing layer's thickness, 2, not the deposit's 4, and rho_m that of the layer (phi = pi/4).
    Discs d;
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 4; ++j)
            d.add(0.5 + i, 0.5 + j, 0.5, j >= 2 ? 1.0 : 0.0);
    auto p = params(10.0);
    p.fluid_density = 1000;
    p.grain_density = 2650;
    p.slope_rad = 0.1;
    const auto result = computeMassDiagnostics(d.view(), p);
    const double phi = M_PI / 4, mixture = phi * 2650 + (1 - phi) * 1000;
    const double expected = 1.0 / std::sqrt((mixture / 1000 - 1) * 9.81 * 2.0 * std::cos(0.1));
    QVERIFY(std::abs(result.front_thickness_m - 2.0) < 1e-12);
    QVERIFY(std::abs(result.front_packing_fraction - phi) < 1e-12);
    QVERIFY2(std::abs(result.froude_densimetric - expected) < 1e-9,
             qPrintable(QString::number(result.froude_densimetric)));
}

void MassDiagnosticsTest::loneDiscLeavingAChainDoesNotCutIt() {
    // A touching row from x = 0 to 10 on the floor; disc 5 is lifted out of it. The hole it
    // leaves is one diameter wide: the row stays one mass and the front stays at 10.
    Discs d;
    for (int i = 0; i < 10; ++i)
        d.add(0.5 + i, 0.5, 0.5);
    d.y[5] = 5.0;
    const auto result = computeMassDiagnostics(d.view(), params(4.0));
    QVERIFY2(std::abs(result.front_x_m - 10.0) < 1e-12,
             qPrintable(QString::number(result.front_x_m)));
    QCOMPARE(result.main_mass_grains, std::size_t(9));
}

void MassDiagnosticsTest::tipDiscPartingOrRejoiningMovesFrontByItsDiameter() {
    // The front disc of a touching row rolls ahead: as soon as it stops touching, the front falls
    // back by its own diameter and no more, however far it goes; touching again, it counts again.
    Discs d;
    for (int i = 0; i < 10; ++i)
        d.add(0.5 + i, 0.5, 0.5);
    for (const double gap : {0.0, 0.3, 0.9, 5.0}) {
        d.x[9] = 9.5 + gap;
        const auto result = computeMassDiagnostics(d.view(), params(4.0));
        const double expected = gap < 1e-6 ? 10.0 : 9.0;
        QVERIFY2(std::abs(result.front_x_m - expected) < 1e-12,
                 qPrintable(QString("gap %1: front %2").arg(gap).arg(result.front_x_m)));
    }
}

QTEST_APPLESS_MAIN(MassDiagnosticsTest)
#include "MassDiagnosticsTest.moc"
