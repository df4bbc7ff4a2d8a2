// Planning: the paper's numbers follow from its SI parameters (docs/design.md §4, §5b).
#include "solver/scene/Plan.h"
#include "solver/core/InputError.h"

#include <QtTest>
#include <algorithm>
#include <cmath>

using namespace lbdem::solver;

class PlanTest : public QObject {
    Q_OBJECT
private slots:
    void paperTimeStepFromTau();
    void tauFromMach();
    void dryScenePlansNoLattice();
    void columnHoldsGrainsAtTargetPacking();
    void contactDurationUndamped();
    void warnsWhenTauNearHalfWithoutLes();
    void saysHowFarAFrontCanRun();
    void demStepIsTheOneUsed();
    void substepsBeyondStabilityRefused();
    void estimatesOutputBytes();
};

void PlanTest::paperTimeStepFromTau() {
    // Kumar et al.: h = 0.1 mm, tau = 0.506, nu = 1e-6 m^2/s  =>  dt = 2e-5 s, 2000 x 1000 nodes.
    CaseSpec spec = defaultCase();
    spec.grains.d_min_m = 1e-3;
    spec.fluid.resolution = 10;
    spec.fluid.tau = 0.506;
    const Plan plan = makePlan(spec);
    QVERIFY(plan.has_fluid);
    QCOMPARE(plan.nx, 2000);
    QCOMPARE(plan.ny, 1000);
    QVERIFY(std::abs(plan.dt_s - 2e-5) < 1e-12);
    QVERIFY(std::abs(plan.nu_lattice - 0.002) < 1e-12);
    // c_s = h / (sqrt(3) dt) = 1e-4 / (sqrt(3) 2e-5) = 2.887 m/s; K = rho_f c_s^2 = 1000 * 25/3.
    QVERIFY(std::abs(plan.sound_speed_m_s - 5.0 / std::sqrt(3.0)) < 1e-9);
    QVERIFY(std::abs(plan.bulk_modulus_pa - spec.fluid.density_kg_m3 * 25.0 / 3.0) < 1e-6);
}

void PlanTest::tauFromMach() {
    CaseSpec spec = defaultCase();
    spec.fluid.tau = 0;
    spec.fluid.target_mach = 0.1;
    const Plan plan = makePlan(spec);
    QVERIFY(std::abs(plan.mach - 0.1) < 1e-9);
    QVERIFY(plan.tau > 0.5);
    // tau = 1/2 + 3 nu dt / h^2 must hold both ways.
    QVERIFY(std::abs(plan.tau - (0.5 + 3 * spec.fluid.viscosity_m2_s * plan.dt_s /
                                           (plan.h_m * plan.h_m))) < 1e-12);
}

void PlanTest::dryScenePlansNoLattice() {
    CaseSpec spec = defaultCase();
    spec.fluid.enabled = false;
    const Plan plan = makePlan(spec);
    QVERIFY(!plan.has_fluid);
    QCOMPARE(plan.nx, 0);
    QCOMPARE(plan.substeps, 1);
    QCOMPARE(plan.dt_s, plan.dem_dt_s);
    QVERIFY(plan.memory_bytes < 1024 * 1024);
}

void PlanTest::columnHoldsGrainsAtTargetPacking() {
    GrainSpec grains;
    grains.count = 1000;
    grains.d_min_m = 1e-3;
    grains.size_ratio = 1.0;
    grains.packing = 0.8;
    grains.aspect_ratio = 0.5;
    const ColumnGeometry column = columnGeometry(grains);
    const double area = 1000 * M_PI * 1e-6 / 4;
    QVERIFY(std::abs(column.width_m * column.height_m * 0.8 - area) < 1e-12);
    QVERIFY(std::abs(column.height_m / column.width_m - 0.5) < 1e-12);
}

void PlanTest::contactDurationUndamped() {
    // e = 1: t_c = pi sqrt(m / k), the half period of the undamped oscillator.
    QVERIFY(std::abs(contactDuration(100.0, 1.0, 1.0) - M_PI / 10.0) < 1e-12);
    QVERIFY(contactDuration(100.0, 1.0, 0.5) > M_PI / 10.0);
}

void PlanTest::warnsWhenTauNearHalfWithoutLes() {
    CaseSpec spec = defaultCase();
    spec.fluid.tau = 0.506;
    spec.fluid.collision = lattice::CollisionModel::Bgk;
    QVERIFY(!makePlan(spec).warnings.empty());
    spec.fluid.collision = lattice::CollisionModel::MrtLes;
    for (const auto& warning : makePlan(spec).warnings)
        QVERIFY(warning.find("LES") == std::string::npos);
}

void PlanTest::saysHowFarAFrontCanRun() {
    // Room for the front: Delta L = (width - layer - L_i) / L_i, against the thesis's longest
    // submerged runout (Delta L ~ 3.1): the paper's 0.2 m falls short, 0.4 m leaves room.
    CaseSpec spec = defaultCase();
    spec.fluid.resolution = 6; // h = 0.2 mm: the default 24-node layer is 4.8 mm thick
    Plan plan = makePlan(spec);
    const double li = plan.column.width_m;
    QCOMPARE(plan.absorbing_layer_nodes, 24);
    QVERIFY(std::abs(plan.runout_room - (0.2 - 24 * 0.2e-3 - li) / li) < 1e-9);
    QCOMPARE(plan.notes.size(), std::size_t(1));
    QVERIFY(plan.notes[0].find("short of") != std::string::npos);
    spec.domain.width_m = 0.4;
    plan = makePlan(spec);
    QVERIFY(plan.runout_room > 5);
    QVERIFY(plan.notes.at(0).find("beyond") != std::string::npos);
    // No layer without an open side: the front meets the end wall.
    spec.domain.right = spec.domain.top = lattice::SideType::Wall;
    plan = makePlan(spec);
    QCOMPARE(plan.absorbing_layer_nodes, 0);
    QVERIFY(std::abs(plan.runout_room - (0.4 - li) / li) < 1e-9);
    QVERIFY(plan.notes.at(0).find("the end of the domain") != std::string::npos);
}

void PlanTest::demStepIsTheOneUsed() {
    // A coupled run advances the DEM by dt / substeps: that is the step the plan reports.
    CaseSpec spec = defaultCase();
    const Plan plan = makePlan(spec);
    QVERIFY(plan.substeps > 1);
    QCOMPARE(plan.dem_dt_s, plan.dt_s / plan.substeps);
    QVERIFY(plan.dem_dt_s <= plan.dem_dt_safe_s);
    QVERIFY(plan.dem_dt_safe_s < plan.dem_dt_stable_s);
}

void PlanTest::substepsBeyondStabilityRefused() {
    CaseSpec spec = defaultCase();
    spec.coupling.substeps = 1;
    try {
        makePlan(spec);
        QFAIL("one DEM sub-step per fluid step must be refused");
    } catch (const InputError& error) {
        QCOMPARE(QString::fromStdString(error.key()), QString("coupling.substeps"));
        QVERIFY2(std::string(error.what()).find("stability limit") != std::string::npos,
                 error.what());
    }
    // Between the safety factor and the stability limit: planned, with a warning.
    const Plan automatic = makePlan(defaultCase());
    spec.coupling.substeps =
        static_cast<int>(std::ceil(automatic.dt_s / automatic.dem_dt_stable_s)) + 1;
    const Plan plan = makePlan(spec);
    QVERIFY(plan.dem_dt_s > plan.dem_dt_safe_s);
    QCOMPARE(std::count_if(plan.warnings.begin(), plan.warnings.end(),
                           [](const std::string& w) {
                               return w.find("coupling.substeps") != std::string::npos;
                           }),
             std::ptrdiff_t(1));
}

void PlanTest::estimatesOutputBytes() {
    CaseSpec spec = defaultCase();
    const Plan every = makePlan(spec);
    QVERIFY(every.output_bytes > 0);
    QVERIFY(every.memory_bytes > every.output_bytes / 100);
    spec.output.vtk = false;
    const Plan none = makePlan(spec);
    QVERIFY(none.output_bytes < every.output_bytes / 5); // VTK dominates
    spec.fluid.resolution *= 2;
    QVERIFY(makePlan(spec).memory_bytes > 3 * every.memory_bytes); // four times the nodes
}

QTEST_APPLESS_MAIN(PlanTest)
#include "PlanTest.moc"
