// The DEM's stability guard and the restore-time grain checks: an unstable DEM stops with a
// diagnosis naming the DEM instead of crashing; impossible restored grains are refused.
#include "solver/dem/DemGuard.h"
#include "solver/core/InputError.h"
#include "solver/scene/ColumnScene.h"
#include "tests/support/SmallDryColumn.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <limits>

using namespace lbdem::solver;

class DemGuardTest : public QObject {
    Q_OBJECT
private slots:
    void stableStepIsBelowContactDuration();
    void quietGrainsPass();
    void nonFiniteGrainStops();
    void fastGrainStops();
    void unstableColumnStopsNamingTheDem();
    void restoredGrainsOutsideAreRefused();
};

namespace {

dem::Particles twoGrains() {
    dem::Particles p;
    p.add(0.01, 0.01, 0.001, 1.0);
    p.add(0.02, 0.01, 0.001, 1.0);
    return p;
}

} // namespace

void DemGuardTest::stableStepIsBelowContactDuration() {
    // Undamped (e = 1): the Verlet limit is 2 / omega, the contact lasts pi / omega.
    const double k = 1.6e6, m = 1e-3;
    QVERIFY(std::abs(stableDemStep(k, m, 1.0) - 2.0 / std::sqrt(k / m)) < 1e-15);
    QVERIFY(std::abs(stableDemStep(k, m, 1.0) / contactDuration(k, m, 1.0) - 2.0 / M_PI) < 1e-9);
    // Damping lowers the limit.
    QVERIFY(stableDemStep(k, m, 0.5) < stableDemStep(k, m, 1.0));
}

void DemGuardTest::quietGrainsPass() {
    auto p = twoGrains();
    p.vx[0] = 0.5; // 0.5 m/s for 1e-6 s: 5e-7 m, 0.05 % of the radius
    dem::checkGrainMotion(p, 1e-6, 0.0);
}

void DemGuardTest::nonFiniteGrainStops() {
    auto p = twoGrains();
    p.vy[1] = std::numeric_limits<double>::quiet_NaN();
    try {
        dem::checkGrainMotion(p, 1e-6, 0.25);
        QFAIL("a NaN velocity must stop the run");
    } catch (const SimulationError& error) {
        const std::string what = error.what();
        QVERIFY2(what.find("DEM") != std::string::npos && what.find("grain 1") != std::string::npos,
                 error.what());
    }
}

void DemGuardTest::fastGrainStops() {
    auto p = twoGrains();
    p.vx[0] = 300; // 3e-4 m in one step of 1e-6 s: 0.3 of the radius
    QVERIFY_EXCEPTION_THROWN(dem::checkGrainMotion(p, 1e-6, 0.0), SimulationError);
    p.vx[0] = 200; // 0.2 of the radius: below the limit
    dem::checkGrainMotion(p, 1e-6, 0.0);
}

void DemGuardTest::unstableColumnStopsNamingTheDem() {
    // A dry column stepped 30 times beyond the integrator's limit: before the guard, the grains'
    // coordinates overflowed and the neighbour grid crashed; now the run stops with a diagnosis.
    const CaseSpec spec = lbdem::support::smallDryColumn(0.79);
    QTemporaryDir dir;
    Plan plan = makePlan(spec);
    plan.dem_dt_s = 30 * plan.dem_dt_stable_s;
    ColumnScene scene(spec, plan, lbdem::support::packingIn(dir));
    try {
        for (int k = 0; k < 100000; ++k)
            scene.step();
        QFAIL("the unstable DEM was not stopped");
    } catch (const SimulationError& error) {
        QVERIFY2(std::string(error.what()).find("the DEM became unstable") != std::string::npos,
                 error.what());
    }
}

void DemGuardTest::restoredGrainsOutsideAreRefused() {
    auto p = twoGrains();
    dem::checkRestoredGrains(p, 0.2, 0.1);
    p.x[0] = 1e300;
    QVERIFY_EXCEPTION_THROWN(dem::checkRestoredGrains(p, 0.2, 0.1), InputError);
    p.x[0] = std::numeric_limits<double>::infinity();
    QVERIFY_EXCEPTION_THROWN(dem::checkRestoredGrains(p, 0.2, 0.1), InputError);
    p = twoGrains();
    p.vx.pop_back();
    QVERIFY_EXCEPTION_THROWN(dem::checkRestoredGrains(p, 0.2, 0.1), InputError);
}

QTEST_APPLESS_MAIN(DemGuardTest)
#include "DemGuardTest.moc"
