// A damaged or edited checkpoint is refused by `lbdem resume` with one sentence and exit 2,
// within seconds: random bytes in the lattice data, a case that disagrees with the arrays, a
// grain far outside the domain, a value that is not finite, an edit of the stored case text, a
// checksum attribute renamed by one byte (resumed only with --force), a checkpoint copied in
// from another run's folder (of another case, or of the same case) with no file changed.
// (Before the checksum, random bytes and a far grain made resume loop forever in the coupling.)
#include "solver/core/Checksum.h"
#include "solver/io/Checkpoint.h"
#include "solver/io/RunIdentity.h"

#include <QCryptographicHash>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
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
    void renamedChecksumAttribute();
    void copiedFromAnotherCase();
    void copiedFromAnotherRunOfTheCase();
    void intactCheckpointResumes();

private:
    /// Run the test's case (with extra overrides) into dir, stopped at 0.1 tau_c.
    void runInto(const std::string& dir, const QStringList& extra = {});
    /// Copy other's checkpoint into a copy of the run: resume must exit 2 changing no file.
    void expectForeignRefused(const QString& name, const std::string& other);
    /// A copy of the run folder, to damage.
    std::string copyRun(const QString& name);
    /// `lbdem resume DIR --quiet [extra]`: exit code (-1 on a hang or a signal), stderr in message.
    int resume(const std::string& dir, QString& message, const QStringList& extra = {});
    /// Resume must exit 2 with one line that names the checkpoint and matches pattern.
    void expectRefused(const std::string& dir, const char* pattern);

    QTemporaryDir m_dir;
    std::string m_run;
};

void CheckpointDamageTest::runInto(const std::string& dir, const QStringList& extra) {
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(LBDEM_EXECUTABLE,
                  QStringList{"run", LBDEM_SOURCE_DIR "/sample_cases/default.toml", "--out",
                              QString::fromStdString(dir), "--quiet", "--until-tc", "0.1", "--set",
                              "grains.count=150", "--set", "grains.packing=0.79", "--set",
                              "fluid.resolution=4", "--set", "run.end_tc=0.2", "--set",
                              "run.output_interval_tc=0.05", "--set", "output.vtk=false"} +
                      extra);
    QVERIFY(process.waitForFinished(300000));
    QVERIFY2(process.exitCode() == 0, process.readAll().constData());
    QVERIFY(fs::exists(dir + "/checkpoint.h5"));
}

void CheckpointDamageTest::initTestCase() {
    // Submerged and coarse, stopped at 0.1 tau_c: a checkpoint with lattice, coupling and grains.
    m_run = (fs::path(m_dir.path().toStdString()) / "run").string();
    runInto(m_run);
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
    // A valid checksum over the edited case, and the folder's run.json made to name it, so that
    // only the arrays disagree with the case.
    data.case_hash = solver::checksumOf(data.case_toml);
    io::writeCheckpoint(dir + "/checkpoint.h5", data);
    io::writeRunIdentity(dir, {data.run_id, data.case_hash});
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

void CheckpointDamageTest::renamedChecksumAttribute() {
    const std::string dir = copyRun("renamed_checksum");
    const std::string path = dir + "/checkpoint.h5";
    std::ifstream in(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    in.close();
    const auto at = bytes.find("checksum");
    QVERIFY(at != std::string::npos);
    QVERIFY(bytes.find("checksum", at + 1) == std::string::npos); // only the attribute's name
    bytes[at + 7] = 'n'; // "checksun": the file is valid HDF5 without its checksum
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
    expectRefused(dir, "no checksum.*--force");
    QString message;
    QCOMPARE(resume(dir, message, {"--until-tc", "0.11", "--force"}), 0);
}

/// The name and SHA-256 of every file under dir.
static std::map<std::string, QByteArray> fingerprint(const std::string& dir) {
    std::map<std::string, QByteArray> sums;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
        if (!entry.is_regular_file()) continue;
        QFile file(QString::fromStdString(entry.path().string()));
        QCryptographicHash hash(QCryptographicHash::Sha256);
        if (file.open(QIODevice::ReadOnly)) hash.addData(&file);
        sums[fs::relative(entry.path(), dir).string()] = hash.result();
    }
    return sums;
}

void CheckpointDamageTest::expectForeignRefused(const QString& name, const std::string& other) {
    const std::string dir = copyRun(name);
    fs::copy_file(other + "/checkpoint.h5", dir + "/checkpoint.h5",
                  fs::copy_options::overwrite_existing);
    const auto before = fingerprint(dir);
    expectRefused(dir, "belongs to run|holds another case");
    QVERIFY(fingerprint(dir) == before);
}

void CheckpointDamageTest::copiedFromAnotherCase() {
    const std::string other = (fs::path(m_dir.path().toStdString()) / "other_seed").string();
    runInto(other, {"--set", "grains.seed=2"});
    expectForeignRefused("copied_other_case", other);
}

void CheckpointDamageTest::copiedFromAnotherRunOfTheCase() {
    const std::string twin = (fs::path(m_dir.path().toStdString()) / "twin").string();
    runInto(twin);
    expectForeignRefused("copied_twin", twin);
}

void CheckpointDamageTest::intactCheckpointResumes() {
    const std::string dir = copyRun("intact");
    QString message;
    QCOMPARE(resume(dir, message, {"--until-tc", "0.11"}),
             0); // a few steps: the checkpoint is sound
}

QTEST_GUILESS_MAIN(CheckpointDamageTest)
#include "CheckpointDamageTest.moc"
