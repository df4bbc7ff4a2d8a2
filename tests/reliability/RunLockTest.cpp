// One writer per run folder: two `lbdem resume` of one folder started together leave one exiting
// 2 with a sentence naming the other's pid, and the folder ends as an uninterrupted run's; a run
// with --force into a folder being written is refused the same way and removes nothing; a
// second sweep into a sweep's folder is refused; a sweep killed with SIGKILL leaves none of its
// runs going (so that a restarted sweep cannot race them).
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <map>
#include <sys/types.h>

namespace fs = std::filesystem;

namespace {

/// Dry and small, to 2 tau_c with a checkpoint every 0.5: a resume from 1 tau_c lasts seconds.
const QStringList kSmall{"--set", "grains.count=150",
                         "--set", "grains.packing=0.79",
                         "--set", "fluid.enabled=false",
                         "--set", "domain.slope_deg=0",
                         "--set", "run.end_tc=2",
                         "--set", "run.output_interval_tc=0.25",
                         "--set", "output.checkpoint_interval_tc=0.5",
                         "--set", "output.vtk=false"};
const QString kCase = LBDEM_SOURCE_DIR "/sample_cases/default.toml";

struct Outcome {
    int code = -1;   ///< exit code; -1 after a signal or a hang
    QString message; ///< stderr
};

Outcome finish(QProcess& process, int timeoutMs = 300000) {
    Outcome outcome;
    if (!process.waitForFinished(timeoutMs)) {
        process.kill();
        process.waitForFinished();
        outcome.message = "no answer in time";
        return outcome;
    }
    outcome.message = QString::fromLocal8Bit(process.readAllStandardError());
    if (process.exitStatus() == QProcess::NormalExit) outcome.code = process.exitCode();
    return outcome;
}

Outcome lbdem(const QStringList& arguments, int timeoutMs = 300000) {
    QProcess process;
    process.start(LBDEM_EXECUTABLE, arguments);
    return finish(process, timeoutMs);
}

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// summary.json without its wall-time fields, which differ from process to process.
QJsonObject summaryWithoutWallTime(const fs::path& dir) {
    QJsonObject summary =
        QJsonDocument::fromJson(QByteArray::fromStdString(readFile(dir / "summary.json"))).object();
    for (const char* field : {"wall_s", "mlups", "stage_seconds"})
        summary.remove(field);
    return summary;
}

/// Every file under dir but those that name the run or hold its wall time, with its bytes.
std::map<std::string, std::string> outputs(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
        const std::string name = fs::relative(entry.path(), dir).string();
        if (entry.is_regular_file() && name != "summary.json" && name != "run.json" &&
            name != "checkpoint.h5")
            files[name] = readFile(entry.path());
    }
    return files;
}

/// The pids of the processes whose parent is pid (from /proc).
QList<qint64> childrenOf(qint64 pid) {
    QList<qint64> children;
    for (const QString& entry : QDir("/proc").entryList(QDir::Dirs)) {
        bool number = false;
        const qint64 child = entry.toLongLong(&number);
        if (!number) continue;
        QFile stat("/proc/" + entry + "/stat");
        if (!stat.open(QIODevice::ReadOnly)) continue;
        // pid (comm) state ppid ...: comm may hold spaces, so read after the last ')'.
        const QString text = QString::fromLocal8Bit(stat.readAll());
        const QStringList fields = text.mid(text.lastIndexOf(')') + 2).split(' ');
        if (fields.size() > 1 && fields[1].toLongLong() == pid) children << child;
    }
    return children;
}

/// True while pid is a process that has not ended (a zombie has ended).
bool alive(qint64 pid) {
    QFile stat(QString("/proc/%1/stat").arg(pid));
    if (!stat.open(QIODevice::ReadOnly)) return false;
    const QString text = QString::fromLocal8Bit(stat.readAll());
    const QString state = text.mid(text.lastIndexOf(')') + 2, 1);
    return state != "Z" && state != "X";
}

} // namespace

class RunLockTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void concurrentResumes();
    void forcedRunIntoBusyFolder();
    void killedSweepLeavesNoRun();

private:
    /// A copy of the run stopped at 1 tau_c.
    fs::path copyStopped(const std::string& name);

    QTemporaryDir m_dir;
    fs::path m_stopped, m_whole;
};

void RunLockTest::initTestCase() {
    const fs::path root = m_dir.path().toStdString();
    m_stopped = root / "stopped";
    m_whole = root / "whole";
    Outcome outcome = lbdem(QStringList{"run", kCase, "--out", QString::fromStdString(m_stopped),
                                        "--quiet", "--until-tc", "1"} +
                            kSmall);
    QVERIFY2(outcome.code == 0, qPrintable(outcome.message));
    outcome = lbdem(QStringList{"run", kCase, "--out", QString::fromStdString(m_whole), "--quiet"} +
                    kSmall);
    QVERIFY2(outcome.code == 0, qPrintable(outcome.message));
}

fs::path RunLockTest::copyStopped(const std::string& name) {
    const fs::path copy = fs::path(m_dir.path().toStdString()) / name;
    fs::copy(m_stopped, copy, fs::copy_options::recursive);
    return copy;
}

void RunLockTest::concurrentResumes() {
    const fs::path dir = copyStopped("together");
    const QStringList arguments{"resume", QString::fromStdString(dir), "--quiet"};
    QProcess first, second;
    first.start(LBDEM_EXECUTABLE, arguments);
    second.start(LBDEM_EXECUTABLE, arguments);
    QVERIFY(first.waitForStarted() && second.waitForStarted());
    const qint64 pids[] = {first.processId(), second.processId()};
    const Outcome outcomes[] = {finish(first), finish(second)};
    // Exactly one of them ran; the other was refused, naming the one that ran.
    const int refused = outcomes[0].code == 2 ? 0 : 1;
    const int ran = 1 - refused;
    QVERIFY2(outcomes[ran].code == 0 && outcomes[refused].code == 2,
             qPrintable(QString("exits %1 and %2: %3 %4")
                            .arg(outcomes[0].code)
                            .arg(outcomes[1].code)
                            .arg(outcomes[0].message, outcomes[1].message)));
    const QString& message = outcomes[refused].message;
    QCOMPARE(message.count('\n'), 1);
    QVERIFY2(message.contains(QString("pid %1").arg(pids[ran])), qPrintable(message));
    QVERIFY2(message.contains("in use by another lbdem process"), qPrintable(message));
    // The folder ends as the uninterrupted run's.
    QVERIFY(outputs(dir) == outputs(m_whole));
    QCOMPARE(summaryWithoutWallTime(dir), summaryWithoutWallTime(m_whole));
}

void RunLockTest::forcedRunIntoBusyFolder() {
    const fs::path dir = copyStopped("busy");
    QProcess resume;
    resume.start(LBDEM_EXECUTABLE, {"resume", QString::fromStdString(dir), "--quiet"});
    QVERIFY(resume.waitForStarted());
    // Wait until the resume holds the folder (its pid in the lock file) and writes into it.
    QElapsedTimer clock;
    clock.start();
    const std::string pid = std::to_string(resume.processId()) + "\n";
    while (readFile(dir / "lbdem.lock") != pid && clock.elapsed() < 60000 &&
           resume.state() == QProcess::Running)
        QTest::qWait(20);
    QVERIFY2(resume.state() == QProcess::Running, "the resume ended before it could be raced");
    const Outcome forced = lbdem(
        QStringList{"run", kCase, "--out", QString::fromStdString(dir), "--force", "--quiet"} +
        kSmall);
    QVERIFY2(forced.code == 2,
             qPrintable(QString("exit %1: %2").arg(forced.code).arg(forced.message)));
    QVERIFY2(forced.message.contains(QString("pid %1").arg(resume.processId())),
             qPrintable(forced.message));
    const Outcome resumed = finish(resume);
    QVERIFY2(resumed.code == 0, qPrintable(resumed.message));
    QVERIFY(outputs(dir) == outputs(m_whole));
    QVERIFY(readFile(dir / "lbdem.lock").empty()); // a clean release empties the lock file
}

void RunLockTest::killedSweepLeavesNoRun() {
    const fs::path root = fs::path(m_dir.path().toStdString()) / "sweep";
    fs::create_directories(root);
    // A case long enough to be still going when the sweep is killed.
    std::ofstream(root / "long.toml")
        << "schema = 1\nname = \"long\"\n[fluid]\nenabled = false\n[grains]\ncount = 150\n"
           "packing = 0.79\n[run]\nend_tc = 100\n[output]\nvtk = false\n";
    std::ofstream(root / "sweep.toml") << "sweep = 1\ncases = [\"long.toml\"]\n";
    const QString out = QString::fromStdString((root / "out").string());
    const QStringList arguments{"sweep",
                                QString::fromStdString((root / "sweep.toml").string()),
                                "--out",
                                out,
                                "--progress-every",
                                "0",
                                "--quiet"};
    QProcess sweep;
    sweep.start(LBDEM_EXECUTABLE, arguments);
    QVERIFY(sweep.waitForStarted());
    QElapsedTimer clock;
    clock.start();
    while (!fs::exists(root / "out" / "long" / "timeseries.csv") && clock.elapsed() < 120000 &&
           sweep.state() == QProcess::Running)
        QTest::qWait(50);
    const QList<qint64> runs = childrenOf(sweep.processId());
    QVERIFY2(!runs.isEmpty(), "the sweep started no run");
    // A second sweep into the same folder is refused while the first goes on.
    const Outcome second = lbdem(arguments, 30000);
    QVERIFY2(second.code == 2 && second.message.contains(QString("pid %1").arg(sweep.processId())),
             qPrintable(QString("exit %1: %2").arg(second.code).arg(second.message)));
    ::kill(static_cast<pid_t>(sweep.processId()), SIGKILL);
    sweep.waitForFinished();
    clock.restart();
    QList<qint64> going = runs;
    while (!going.isEmpty() && clock.elapsed() < 20000) {
        QTest::qWait(50);
        for (int k = going.size() - 1; k >= 0; --k)
            if (!alive(going[k])) going.removeAt(k);
    }
    for (const qint64 run : going) // left going: stop it, the test has failed anyway
        ::kill(static_cast<pid_t>(run), SIGKILL);
    QVERIFY2(going.isEmpty(), "a run of the killed sweep is still going");
}

QTEST_GUILESS_MAIN(RunLockTest)
#include "RunLockTest.moc"
