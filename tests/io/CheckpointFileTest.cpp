// checkpoint.h5 and timeseries.csv round trips.
#include "solver/core/InputError.h"
#include "solver/io/Checkpoint.h"
#include "solver/io/TimeSeriesWriter.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

using namespace lbdem;

class CheckpointFileTest : public QObject {
    Q_OBJECT
private slots:
    void roundTripIsBitForBit();
    void replacesAtomically();
    void rejectsTornFile();
    void rejectsDamagedArrays();
    void rejectsNonFiniteValues();
    void timeSeriesRoundTrip();
};

void CheckpointFileTest::roundTripIsBitForBit() {
    QTemporaryDir dir;
    io::CheckpointData data;
    data.case_toml = "schema = 1\nname = \"x\"\n";
    data.state.reals["lattice/f"] = {0.1, 1.0 / 3.0, -0.0,
                                     std::numeric_limits<double>::denorm_min(), 1e300};
    data.state.reals["empty"] = {};
    data.state.integers["dem/pairs"] = {1, -2, std::numeric_limits<std::int64_t>::max()};
    const std::string path = dir.filePath("checkpoint.h5").toStdString();
    io::writeCheckpoint(path, data);
    const auto back = io::readCheckpoint(path);
    QCOMPARE(QString::fromStdString(back.case_toml), QString::fromStdString(data.case_toml));
    QCOMPARE(back.state.reals.size(), data.state.reals.size());
    const auto& f = back.state.real("lattice/f");
    QCOMPARE(f.size(), data.state.reals["lattice/f"].size());
    QVERIFY(std::memcmp(f.data(), data.state.reals["lattice/f"].data(),
                        f.size() * sizeof(double)) == 0);
    QVERIFY(back.state.integer("dem/pairs") == data.state.integers["dem/pairs"]);
    QVERIFY(back.state.real("empty").empty());
}

void CheckpointFileTest::replacesAtomically() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("checkpoint.h5").toStdString();
    io::CheckpointData first;
    first.case_toml = "first";
    io::writeCheckpoint(path, first);
    io::CheckpointData second;
    second.case_toml = "second";
    second.state.reals["a"] = std::vector<double>(1000, 2.0);
    io::writeCheckpoint(path, second);
    QCOMPARE(QString::fromStdString(io::readCheckpoint(path).case_toml), QString("second"));
    int files = 0;
    for ([[maybe_unused]] const auto& entry :
         std::filesystem::directory_iterator(dir.path().toStdString()))
        ++files;
    QCOMPARE(files, 1); // no temporary file left behind
}

void CheckpointFileTest::rejectsTornFile() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("torn.h5").toStdString();
    std::ofstream(path) << "not an HDF5 file";
    QVERIFY_EXCEPTION_THROWN(io::readCheckpoint(path), std::runtime_error);
    QVERIFY_EXCEPTION_THROWN(io::readCheckpoint(dir.filePath("missing.h5").toStdString()),
                             std::runtime_error);
}

void CheckpointFileTest::rejectsDamagedArrays() {
    // One flipped byte inside an array's data fails the checksum written with it.
    QTemporaryDir dir;
    const std::string path = dir.filePath("checkpoint.h5").toStdString();
    io::CheckpointData data;
    data.case_toml = "schema = 1\n";
    data.state.reals["lattice/f"] = std::vector<double>(4096, 0.125);
    io::writeCheckpoint(path, data);
    QCOMPARE(io::readCheckpoint(path).state.real("lattice/f").size(), std::size_t(4096));
    std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    const double eighth = 0.125;
    const auto at = bytes.find(std::string(reinterpret_cast<const char*>(&eighth), sizeof eighth));
    QVERIFY(at != std::string::npos);
    file.seekp(static_cast<std::streamoff>(at + 1000 * sizeof(double) + 3));
    file.put('\x5a');
    file.close();
    QVERIFY_EXCEPTION_THROWN(io::readCheckpoint(path), solver::InputError);
}

void CheckpointFileTest::rejectsNonFiniteValues() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("checkpoint.h5").toStdString();
    io::CheckpointData data;
    data.state.reals["dem/x"] = {0.1, std::numeric_limits<double>::infinity()};
    io::writeCheckpoint(path, data);
    QVERIFY_EXCEPTION_THROWN(io::readCheckpoint(path), solver::InputError);
    // Metrics of the last output may be undefined (NaN) and are kept.
    data.state.reals.erase("dem/x");
    data.state.reals["run/last_metric/froude_densimetric"] = {
        std::numeric_limits<double>::quiet_NaN()};
    io::writeCheckpoint(path, data);
    QVERIFY(
        std::isnan(io::readCheckpoint(path).state.real("run/last_metric/froude_densimetric")[0]));
}

void CheckpointFileTest::timeSeriesRoundTrip() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("timeseries.csv").toStdString();
    {
        io::TimeSeriesWriter writer(path);
        writer.append({{"runout_m", 0.5}, {"t_s", 0.0}, {"t_over_tc", 0.0}, {"step", 0}});
        writer.append({{"runout_m", 0.75}, {"t_s", 0.1}, {"t_over_tc", 1.5}, {"step", 10}});
    }
    {
        io::TimeSeriesWriter resumed(path, true); // a resumed run appends under the same header
        resumed.append({{"t_s", 0.2}, {"t_over_tc", 3.0}, {"step", 20}});
    }
    const auto table = io::readTimeSeries(path);
    QCOMPARE(table.columns.front(), std::string("t_s"));
    QCOMPARE(table.rows.size(), std::size_t(3));
    QCOMPARE(table.column("runout_m")[1], 0.75);
    QVERIFY(std::isnan(table.column("runout_m")[2]));
    QCOMPARE(table.column("t_over_tc")[2], 3.0);
}

QTEST_APPLESS_MAIN(CheckpointFileTest)
#include "CheckpointFileTest.moc"
