// SIGTERM and SIGINT stop a running `lbdem run` at the end of a step: it writes a checkpoint,
// says "stopped at t/τc = …; lbdem resume DIR continues" and exits 143 or 130, and
// `lbdem resume DIR` then ends with the timeseries.csv and summary.json of a run never stopped.
// A second signal while the first is being honoured ends the process at once.
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <sys/types.h>

class StopSignalsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void stopsAndResumes_data();
    void stopsAndResumes();
    void secondSignalStopsAtOnce();

private:
    QTemporaryDir m_dir;
    QString m_reference;
};

namespace {

const QString kCase = LBDEM_SOURCE_DIR "/sample_cases/default.toml";

/// A small dry column, long enough (a few seconds) to be stopped in the middle.
QStringList smallRun(const QString& out) {
    QStringList arguments{"run", kCase, "--out", out, "--quiet"};
    for (const char* setting :
         {"grains.count=150", "grains.packing=0.79", "fluid.enabled=false", "run.end_tc=0.6",
          "run.output_interval_tc=0.02", "output.checkpoint_interval_tc=0.2", "output.vtk=false"})
        arguments << "--set" << setting;
    return arguments;
}

QByteArray readAll(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

/// Lines in a file (0 when it does not exist yet).
int lineCount(const QString& path) {
    return static_cast<int>(readAll(path).count('\n'));
}

/// summary.json without the timings of the process that wrote it.
QJsonObject comparableSummary(const QString& dir) {
    QJsonObject summary = QJsonDocument::fromJson(readAll(dir + "/summary.json")).object();
    for (const char* key : {"wall_s", "mlups", "stage_seconds"})
        summary.remove(key);
    return summary;
}

/// Wait until the run's time series has `rows` data rows (the run loop is going); false when
/// the process ended first or nothing came within a minute.
bool waitForRows(QProcess& process, const QString& dir, int rows) {
    for (int k = 0; k < 6000; ++k) {
        if (lineCount(dir + "/timeseries.csv") >= rows + 1) return true;
        if (process.waitForFinished(10)) return false;
    }
    return false;
}

} // namespace

void StopSignalsTest::initTestCase() {
    m_reference = m_dir.filePath("reference");
    QProcess process;
    process.start(LBDEM_EXECUTABLE, smallRun(m_reference));
    QVERIFY(process.waitForFinished(300000));
    QVERIFY2(process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0,
             process.readAllStandardError().constData());
}

void StopSignalsTest::stopsAndResumes_data() {
    QTest::addColumn<int>("signal");
    QTest::addColumn<int>("exitCode");
    QTest::newRow("SIGTERM") << int(SIGTERM) << 143;
    QTest::newRow("SIGINT") << int(SIGINT) << 130;
}

void StopSignalsTest::stopsAndResumes() {
    QFETCH(int, signal);
    QFETCH(int, exitCode);
    const QString dir = m_dir.filePath(QString("stopped_%1").arg(signal));
    QProcess process;
    process.start(LBDEM_EXECUTABLE, smallRun(dir));
    QVERIFY2(waitForRows(process, dir, 3), "the run ended before it could be stopped");
    QCOMPARE(::kill(static_cast<pid_t>(process.processId()), signal), 0);
    QVERIFY(process.waitForFinished(120000));
    const QString message = QString::fromUtf8(process.readAllStandardError());
    QVERIFY2(process.exitStatus() == QProcess::NormalExit, "the signal ended the process");
    QCOMPARE(process.exitCode(), exitCode);
    const QRegularExpression expected(QString("^lbdem: stopped at t/τc = [0-9.e+-]+; lbdem resume "
                                              "%1 continues\n$")
                                          .arg(QRegularExpression::escape(dir)));
    QVERIFY2(expected.match(message).hasMatch(), qPrintable(message));
    QVERIFY(QFile::exists(dir + "/checkpoint.h5"));
    QVERIFY(!comparableSummary(dir).value("finished").toBool());
    QVERIFY2(lineCount(dir + "/timeseries.csv") < lineCount(m_reference + "/timeseries.csv"),
             "the run finished before the signal");

    QProcess resume;
    resume.start(LBDEM_EXECUTABLE, {"resume", dir, "--quiet"});
    QVERIFY(resume.waitForFinished(300000));
    QVERIFY2(resume.exitStatus() == QProcess::NormalExit && resume.exitCode() == 0,
             resume.readAllStandardError().constData());
    QVERIFY2(readAll(dir + "/timeseries.csv") == readAll(m_reference + "/timeseries.csv"),
             "the resumed timeseries.csv differs from the uninterrupted run's");
    QCOMPARE(comparableSummary(dir), comparableSummary(m_reference));
}

void StopSignalsTest::secondSignalStopsAtOnce() {
    // A lattice of about a million nodes: a step, and the checkpoint that ends a stop, take far
    // longer than it takes to send two signals. SIGINT then SIGTERM: two different signals are
    // never merged into one by the kernel, whatever the load of the machine, so the second
    // always comes while the first is being honoured.
    const QString dir = m_dir.filePath("interrupted_twice");
    QProcess process;
    process.start(LBDEM_EXECUTABLE,
                  {"run", kCase, "--out", dir, "--quiet", "--set", "grains.count=150", "--set",
                   "grains.packing=0.79", "--set", "fluid.resolution=10", "--set",
                   "output.vtk=false", "--set", "run.threads=1"});
    QVERIFY2(waitForRows(process, dir, 1), "the run did not start its loop");
    const auto pid = static_cast<pid_t>(process.processId());
    QElapsedTimer clock;
    clock.start();
    QCOMPARE(::kill(pid, SIGINT), 0);
    QCOMPARE(::kill(pid, SIGTERM), 0);
    QVERIFY(process.waitForFinished(60000));
    qInfo("ended %lld ms after the first signal", static_cast<long long>(clock.elapsed()));
    QCOMPARE(process.exitStatus(), QProcess::CrashExit); // ended by the second signal itself
    QVERIFY(!QString::fromUtf8(process.readAllStandardError()).contains("stopped at"));
}

QTEST_GUILESS_MAIN(StopSignalsTest)
#include "StopSignalsTest.moc"
