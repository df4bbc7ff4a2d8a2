// A damaged or edited checkpoint is refused by `lbdem resume` with one sentence and exit 2,
// within seconds: random bytes in the lattice data, a case that disagrees with the arrays, a
// grain far outside the domain, a value that is not finite, an edit of the stored case text.
// (Before the checksum, random bytes and a far grain made resume loop forever in the coupling.)
#include "solver/io/Checkpoint.h"

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

using namespace lbdem;
namespace fs = std::filesystem;

class CheckpointDamageTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void randomBytesInLatticeData();
    void editedCaseText();
    void caseDisagreesWithArrays();
    void grainFarOutside();
    void nonFiniteValue();
    void intactCheckpointResumes();

private:
    /// A copy of the run folder, to damage.
    std::string copyRun(const QString& name);
    /// `lbdem resume DIR --quiet [extra]`: exit code (-1 on a hang or a signal), stderr in message.
    int resume(const std::string& dir, QString& message, const QStringList& extra = {});
    /// Resume must exit 2 with one line that names the checkpoint and matches pattern.
    void expectRefused(const std::string& dir, const char* pattern);

    QTemporaryDir m_dir;
    std::string m_run;
};

void CheckpointDamageTest::initTestCase() {
    // Submerged and coarse, stopped at 0.1 tau_c: a checkpoint with lattice, coupling and grains.
    m_run = (fs::path(m_dir.path().toStdString()) / "run").string();
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(LBDEM_EXECUTABLE,
                  {"run", LBDEM_SOURCE_DIR "/sample_cases/default.toml", "--out",
                   QString::fromStdString(m_run), "--quiet", "--until-tc", "0.1", "--set",
                   "grains.count=150", "--set", "grains.packing=0.79", "--set",
                   "fluid.resolution=4", "--set", "run.end_tc=0.2", "--set",
                   "run.output_interval_tc=0.05", "--set", "output.vtk=false"});
    QVERIFY(process.waitForFinished(300000));
    QVERIFY2(process.exitCode() == 0, process.readAll().constData());
    QVERIFY(fs::exists(m_run + "/checkpoint.h5"));
}

std::string CheckpointDamageTest::copyRun(const QString& name) {
    const std::string copy = (fs::path(m_dir.path().toStdString()) / name.toStdString()).string();
    fs::remove_all(copy);
    fs::copy(m_run, copy, fs::copy_options::recursive);
    return copy;
}

int CheckpointDamageTest::resume(const std::string& dir, QString& message,
                                 const QStringList& extra) {
    QProcess process;
    process.start(LBDEM_EXECUTABLE,
                  QStringList{"resume", QString::fromStdString(dir), "--quiet"} + extra);
    if (!process.waitForFinished(180000)) {
        process.kill();
        process.waitForFinished();
        message = "no answer within 180 s";
        return -1;
    }
    message = QString::fromLocal8Bit(process.readAllStandardError());
    return process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
}

void CheckpointDamageTest::expectRefused(const std::string& dir, const char* pattern) {
    QString message;
    const int code = resume(dir, message);
    QVERIFY2(code == 2, qPrintable(QString("exit %1: %2").arg(code).arg(message)));
    QCOMPARE(message.count('\n'), 1);
    QVERIFY2(message.contains("checkpoint.h5"), qPrintable(message));
    QVERIFY2(message.contains(QRegularExpression(pattern)), qPrintable(message));
}

void CheckpointDamageTest::randomBytesInLatticeData() {
    const std::string dir = copyRun("random_bytes");
    const std::string path = dir + "/checkpoint.h5";
    const auto size = fs::file_size(path);
    // The populations are most of the file: its middle lies in them.
    std::mt19937 random(16);
    std::string bytes(4096, '\0');
    for (char& byte : bytes)
        byte = static_cast<char>(random() & 0xff);
    std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(static_cast<std::streamoff>(size / 2));
    file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    file.close();
    expectRefused(dir, "damaged|not a readable");
}

void CheckpointDamageTest::editedCaseText() {
    const std::string dir = copyRun("edited_text");
    const std::string path = dir + "/checkpoint.h5";
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    in.close();
    const auto at = bytes.find("count = 150");
    QVERIFY(at != std::string::npos);
    bytes[at + 10] = '1'; // 150 -> 151, in place
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    expectRefused(dir, "damaged");
}

void CheckpointDamageTest::caseDisagreesWithArrays() {
    const std::string dir = copyRun("other_case");
    auto data = io::readCheckpoint(dir + "/checkpoint.h5");
    const auto at = data.case_toml.find("count = 150");
    QVERIFY(at != std::string::npos);
    data.case_toml.replace(at, 11, "count = 140");
    io::writeCheckpoint(dir + "/checkpoint.h5", data); // a valid checksum over the edited case
    expectRefused(dir, "does not match");
}

void CheckpointDamageTest::grainFarOutside() {
    const std::string dir = copyRun("far_grain");
    auto data = io::readCheckpoint(dir + "/checkpoint.h5");
    data.state.reals.at("dem/x").at(3) = 1e300;
    io::writeCheckpoint(dir + "/checkpoint.h5", data);
    expectRefused(dir, "outside");
}

void CheckpointDamageTest::nonFiniteValue() {
    const std::string dir = copyRun("nan");
    auto data = io::readCheckpoint(dir + "/checkpoint.h5");
    data.state.reals.at("lattice/f").at(1000) = std::numeric_limits<double>::quiet_NaN();
    io::writeCheckpoint(dir + "/checkpoint.h5", data);
    expectRefused(dir, "not finite");
}

void CheckpointDamageTest::intactCheckpointResumes() {
    const std::string dir = copyRun("intact");
    QString message;
    QCOMPARE(resume(dir, message, {"--until-tc", "0.11"}),
             0); // a few steps: the checkpoint is sound
}

QTEST_GUILESS_MAIN(CheckpointDamageTest)
#include "CheckpointDamageTest.moc"
