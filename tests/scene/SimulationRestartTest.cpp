// Checkpoint/restart: 2N steps equal N steps, save, load into a new Simulation, N steps — bit for
// bit.
#include "solver/core/InputError.h"
#include "solver/io/CaseLoader.h"
#include "solver/io/CaseWriter.h"
#include "solver/io/Checkpoint.h"
#include "solver/scene/Simulation.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cstring>

using namespace lbdem;

namespace {

/// A small loose column (150 discs; too few to reach the dense 0.83) in a small domain, dry or
/// submerged, quick enough for the default suite.
solver::CaseSpec smallColumn(bool submerged, const std::string& method = "bounce_back",
                             const std::string& storage = "double") {
    return io::parseCase(
        "schema = 1\nname = \"restart\"\n", "restart.toml",
        {"grains.count=150", "grains.packing=0.79", "domain.width_m=0.08", "domain.height_m=0.04",
         "fluid.enabled=" + std::string(submerged ? "true" : "false"), "fluid.resolution=4",
         "coupling.method=" + method, "fluid.storage=" + storage});
}

bool sameArchive(const solver::StateArchive& a, const solver::StateArchive& b, QString& why) {
    for (const auto& [name, values] : a.reals) {
        const auto& other = b.real(name);
        if (other.size() != values.size() ||
            std::memcmp(other.data(), values.data(), values.size() * sizeof(double)) != 0) {
            why = QString::fromStdString(name);
            return false;
        }
    }
    for (const auto& [name, values] : a.integers)
        if (b.integer(name) != values) {
            why = QString::fromStdString(name);
            return false;
        }
    return a.reals.size() == b.reals.size() && a.integers.size() == b.integers.size();
}

} // namespace

class SimulationRestartTest : public QObject {
    Q_OBJECT
private slots:
    void restartIsBitForBit_data();
    void restartIsBitForBit();
    void dryColumnAllocatesNoFluid();
    void olderPopulationLayoutIsRefused();
    void storageMismatchIsRefused();
};

void SimulationRestartTest::restartIsBitForBit_data() {
    QTest::addColumn<bool>("submerged");
    QTest::addColumn<QString>("method");
    QTest::addColumn<int>("steps");
    QTest::addColumn<QString>("storage");
    QTest::newRow("dry") << false << "bounce_back" << 400 << "double";
    QTest::newRow("submerged bounce-back") << true << "bounce_back" << 20 << "double";
    // An odd step count: the in-place (AA) lattice keeps its populations in the other layout.
    QTest::newRow("submerged bounce-back, odd step") << true << "bounce_back" << 21 << "double";
    QTest::newRow("submerged psm") << true << "psm" << 20 << "double";
    // Float storage: the checkpoint keeps the stored f_i - w_i exactly (widened to double).
    QTest::newRow("float storage, bounce-back, odd step") << true << "bounce_back" << 21 << "float";
    QTest::newRow("float storage, psm") << true << "psm" << 20 << "float";
}

void SimulationRestartTest::restartIsBitForBit() {
    QFETCH(bool, submerged);
    QFETCH(QString, method);
    QFETCH(int, steps);
    QFETCH(QString, storage);
    const auto spec = smallColumn(submerged, method.toStdString(), storage.toStdString());
    const auto plan = solver::makePlan(spec);

    solver::Simulation straight(spec, plan);
    for (int s = 0; s < 2 * steps; ++s)
        straight.step();

    solver::Simulation first(spec, plan);
    for (int s = 0; s < steps; ++s)
        first.step();
    QTemporaryDir dir;
    const std::string path = dir.filePath("checkpoint.h5").toStdString();
    io::writeCheckpoint(path, {io::formatCase(spec), first.saveState()});

    const auto data = io::readCheckpoint(path);
    const auto resumedSpec = io::parseCase(data.case_toml, path);
    solver::Simulation resumed(resumedSpec, solver::makePlan(resumedSpec));
    resumed.restoreState(data.state);
    QCOMPARE(resumed.stepIndex(), static_cast<long long>(steps));
    for (int s = 0; s < steps; ++s)
        resumed.step();

    QString why;
    QVERIFY2(sameArchive(straight.saveState(), resumed.saveState(), why),
             qPrintable("differs in " + why));
    QCOMPARE(resumed.time(), straight.time());
}

void SimulationRestartTest::dryColumnAllocatesNoFluid() {
    const auto spec = smallColumn(false);
    solver::Simulation simulation(spec, solver::makePlan(spec));
    simulation.step();
    const auto snapshot = simulation.snapshot();
    QVERIFY(!snapshot->fluid.has_value());
    QCOMPARE(simulation.saveState().reals.count("lattice/f"), std::size_t(0));
    QCOMPARE(snapshot->grains.size(), std::size_t(150));
}

void SimulationRestartTest::olderPopulationLayoutIsRefused() {
    // A checkpoint of the two-lattice solver has no "lattice/layout"; read as in-place
    // populations it would silently scramble the flow, so restoring it must fail with a reason.
    const auto spec = smallColumn(true);
    solver::Simulation first(spec, solver::makePlan(spec));
    first.step();
    auto state = first.saveState();
    QCOMPARE(state.integers.count("lattice/layout"), std::size_t(1));
    state.integers.erase("lattice/layout");
    solver::Simulation resumed(spec, solver::makePlan(spec));
    try {
        resumed.restoreState(state);
        QFAIL("a checkpoint without the population layout was accepted");
    } catch (const std::runtime_error& error) {
        QVERIFY2(std::string(error.what()).find("older lbdem") != std::string::npos, error.what());
    }
}

void SimulationRestartTest::storageMismatchIsRefused() {
    // Float storage's checkpoint holds f_i - w_i; read into double storage it would be wrong by
    // w_i everywhere, so a case whose fluid.storage differs must refuse it and say why.
    const auto single = smallColumn(true, "bounce_back", "float");
    solver::Simulation first(single, solver::makePlan(single));
    first.step();
    const auto state = first.saveState();
    const auto spec = smallColumn(true);
    solver::Simulation resumed(spec, solver::makePlan(spec));
    try {
        resumed.restoreState(state);
        QFAIL("a float-storage checkpoint was restored into double storage");
    } catch (const solver::InputError& error) {
        QVERIFY2(std::string(error.what()).find("fluid.storage = \"float\"") != std::string::npos,
                 error.what());
    }
}

QTEST_APPLESS_MAIN(SimulationRestartTest)
#include "SimulationRestartTest.moc"
