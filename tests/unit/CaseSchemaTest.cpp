// The case model: typed keys parsed from one word table per enum, defaults only in the schema,
// and one relaxation-time rule and one set of stability warnings for every scene.
#include "solver/scene/CaseSchema.h"
#include "solver/scene/FluidFields.h"
#include "solver/scene/FluidStability.h"
#include "solver/scene/Plan.h"

#include <QtTest>
#include <cmath>

using namespace lbdem::solver;

class CaseSchemaTest : public QObject {
    Q_OBJECT
private slots:
    void wordTablesRoundTrip();
    void choiceKeysStoreTheirEnum();
    void defaultCaseHoldsTheSchemaDefaults();
    void relaxationTimeImposedOrDerived();
    void oneTauWarningForEveryScene();
    void magicLambdaSetsTheEnergyFluxRate();
};

namespace {

template <class E> void checkTable() {
    for (const E value : enumValues<E>())
        QCOMPARE(enumFromWord<E>(enumWord(value)), std::optional<E>(value));
    QVERIFY(!enumFromWord<E>("no_such_word"));
}

ParamValue word(const char* text) {
    return std::string(text);
}

} // namespace

void CaseSchemaTest::wordTablesRoundTrip() {
    checkTable<SceneKind>();
    checkTable<lattice::CollisionModel>();
    checkTable<lattice::PopulationStorage>();
    checkTable<lattice::SideType>();
    checkTable<coupling::CouplingMethod>();
    checkTable<coupling::PsmWeight>();
}

void CaseSchemaTest::choiceKeysStoreTheirEnum() {
    const auto& schema = CaseSchema::instance();
    CaseSpec spec = defaultCase();
    schema.find("scene")->set(spec, word("cavity"));
    schema.find("domain.top")->set(spec, word("free_slip"));
    schema.find("fluid.collision")->set(spec, word("bgk"));
    schema.find("fluid.storage")->set(spec, word("float"));
    schema.find("coupling.method")->set(spec, word("psm"));
    schema.find("coupling.psm_weight")->set(spec, word("eps"));
    QCOMPARE(spec.scene, SceneKind::Cavity);
    QCOMPARE(spec.domain.top, lattice::SideType::FreeSlip);
    QCOMPARE(spec.fluid.collision, lattice::CollisionModel::Bgk);
    QCOMPARE(spec.fluid.storage, lattice::PopulationStorage::Float);
    QCOMPARE(spec.coupling.method, coupling::CouplingMethod::Psm);
    QCOMPARE(spec.coupling.psm_weight, coupling::PsmWeight::Eps);
    QCOMPARE(schema.find("fluid.collision")->get(spec), word("bgk"));
    // A case file's sides are the four of the lattice's word table without the Zou-He ones.
    QCOMPARE(schema.find("domain.right")->describeRange(),
             std::string("one of wall, free_slip, pressure, periodic"));
    QVERIFY(!schema.find("domain.right")->check(word("zou_he_pressure")).empty());
}

void CaseSchemaTest::defaultCaseHoldsTheSchemaDefaults() {
    const CaseSpec spec = defaultCase();
    for (const auto& decl : CaseSchema::instance().params())
        QVERIFY2(decl.get(spec) == decl.defaultValue(), decl.path().c_str());
    // A few of the paper's values, through the typed fields.
    QCOMPARE(spec.scene, SceneKind::ColumnCollapse);
    QCOMPARE(spec.fluid.tau, 0.506);
    QCOMPARE(spec.fluid.collision, lattice::CollisionModel::MrtLes);
    QCOMPARE(spec.domain.right, lattice::SideType::Pressure);
    QCOMPARE(spec.coupling.psm_weight, coupling::PsmWeight::Nt);
    QCOMPARE(spec.grains.count, 1000);
}

void CaseSchemaTest::relaxationTimeImposedOrDerived() {
    QVERIFY(imposesTau(0.506));
    QVERIFY(!imposesTau(0.0));
    QCOMPARE(relaxationTime(0.8, 1.0, 1.0, 1.0), 0.8);
    // tau = 1/2 + 3 nu dt / h^2: nu = 1e-6 m^2/s, h = 1e-4 m, dt = 2e-5 s gives 0.506.
    QVERIFY(std::abs(relaxationTime(0.0, 1e-6, 2e-5, 1e-4) - 0.506) < 1e-12);
    QCOMPARE(relaxationTime(0.0, 0.1, 1.0, 1.0), 0.5 + 3 * 0.1);
}

void CaseSchemaTest::oneTauWarningForEveryScene() {
    // The same tau - 1/2 without LES draws the same warning from the column and a flow plan.
    CaseSpec column = defaultCase();
    column.fluid.collision = lattice::CollisionModel::Bgk;
    column.fluid.tau = 0.505;
    CaseSpec cavity = column;
    cavity.scene = SceneKind::Cavity;
    cavity.grains.count = 0;
    cavity.flow.tau = 0.505;
    cavity.flow.reynolds = 0;
    const auto tauWarning = [](const Plan& plan) {
        for (const auto& w : plan.warnings)
            if (w.find("without LES") != std::string::npos) return w;
        return std::string();
    };
    const std::string fromColumn = tauWarning(makePlan(column));
    QVERIFY(!fromColumn.empty());
    QCOMPARE(tauWarning(makePlan(cavity)), fromColumn);
    column.fluid.collision = cavity.fluid.collision = lattice::CollisionModel::MrtLes;
    QVERIFY(tauWarning(makePlan(column)).empty());
    QVERIFY(tauWarning(makePlan(cavity)).empty());
}

void CaseSchemaTest::magicLambdaSetsTheEnergyFluxRate() {
    auto spec = defaultCase();
    spec.fluid.s_q = 1.9;
    QCOMPARE(collisionOf(spec, 0.503).s_q, 1.9); // 0: s_q as given
    spec.fluid.magic_lambda = lattice::kHalfWayLambda;
    for (const double tau : {0.503, 0.506, 0.8}) {
        const double sq = collisionOf(spec, tau).s_q;
        // Ginzburg & d'Humieres (2003): Lambda = (tau - 1/2)(1/s_q - 1/2) = 3/16 puts the wall
        // half-way; the rate follows tau so that Lambda stays put.
        QVERIFY(std::abs((tau - 0.5) * (1 / sq - 0.5) - 3.0 / 16) < 1e-12);
    }
    QVERIFY(std::abs(collisionOf(spec, 0.503).s_q - 0.0158730) < 1e-6); // as in sweep_controlled
}

QTEST_GUILESS_MAIN(CaseSchemaTest)
#include "CaseSchemaTest.moc"
