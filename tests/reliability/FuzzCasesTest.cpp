// Fuzz-style robustness: a few hundred malformed or extreme variants of the default case
// (mutated keys, values, types and syntax, random bytes) each make `lbdem info` exit 0 or 2
// within seconds, with one line of message on 2; a few dozen extreme values of run-time keys
// make a short `lbdem run` exit 0, 2 or 3 (a stability guard), never a signal or a hang. Run
// folders given another run's checkpoint make `lbdem resume` exit 2 changing no file, and
// random pairs of writers started together on one folder (run --force, resume) leave one
// running and the other refused with exit 2 naming its pid, and a consistent time series.
// Files that are not regular (a FIFO, devices, a socket, a folder) or too large, given as the
// case or sweep file of every command, are refused at once; SIGTERM or SIGINT at a random moment
// of a run stops it with 143 or 130, and a resume ends with the time series of a run never
// stopped.
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>
#include <vector>

class FuzzCasesTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void infoSurvivesMutants();
    void runSurvivesExtremeValues();
    void foreignCheckpointsRefused();
    void concurrentWritersRefused();
    void nonRegularFilesRefused();
    void signalsAtRandomMoments();

private:
    std::vector<std::string> m_lines;
    QTemporaryDir m_dir;
};

namespace {

constexpr int kInfoMutants = 300;
constexpr int kRunMutants = 10;
constexpr std::uint32_t kSeed = 16;

const std::vector<std::string> kExtremes{"0",
                                         "-1",
                                         "1e308",
                                         "-1e308",
                                         "nan",
                                         "inf",
                                         "-inf",
                                         "1e-308",
                                         "9223372036854775807",
                                         "-9223372036854775808",
                                         "\"\"",
                                         "\"x\"",
                                         "true",
                                         "[]",
                                         "{}",
                                         "[1, \"a\"]",
                                         "0x10",
                                         "1_000",
                                         "\"../../x\"",
                                         "2026-12-01",
                                         "\"\\u0000\"",
                                         "0.5",
                                         "1e9",
                                         "-0.0",
                                         "\"" + std::string(5000, 'a') + "\"",
                                         "=",
                                         "\"unterminated",
                                         "1.",
                                         ".5",
                                         "+inf"};

/// Run-time keys whose extreme values must not crash or hang a short run (none of them scales
/// the lattice or the number of grains).
const std::vector<std::string> kRunKeys{"domain.slope_deg",
                                        "domain.top",
                                        "domain.right",
                                        "fluid.tau",
                                        "fluid.collision",
                                        "fluid.smagorinsky",
                                        "fluid.s_e",
                                        "fluid.target_mach",
                                        "grains.restitution",
                                        "grains.friction_deg",
                                        "grains.normal_stiffness_n_m",
                                        "grains.tangential_stiffness_n_m",
                                        "grains.rolling_resistance",
                                        "grains.dt_safety",
                                        "coupling.substeps",
                                        "coupling.hydro_radius_ratio",
                                        "coupling.method",
                                        "fluid.density_kg_m3",
                                        "fluid.viscosity_m2_s"};

struct Outcome {
    int code = -1;   ///< exit code; -1 after a signal or a hang
    QString message; ///< stderr
};

Outcome runLbdem(const QStringList& arguments, int timeoutMs) {
    QProcess process;
    process.start(LBDEM_EXECUTABLE, arguments);
    Outcome outcome;
    if (!process.waitForFinished(timeoutMs)) {
        process.kill();
        process.waitForFinished();
        outcome.message = QString("no answer within %1 s").arg(timeoutMs / 1000);
        return outcome;
    }
    outcome.message = QString::fromLocal8Bit(process.readAllStandardError());
    if (process.exitStatus() == QProcess::NormalExit) outcome.code = process.exitCode();
    return outcome;
}

std::size_t pick(std::mt19937& random, std::size_t count) {
    return count > 0 ? random() % count : 0;
}

/// One random mutation of a case file's lines (or of its bytes).
std::string mutate(std::vector<std::string> lines, std::mt19937& random) {
    const std::size_t line = pick(random, lines.size());
    std::string& text = lines[line];
    const auto equals = text.find('=');
    switch (pick(random, 9)) {
    case 0:
        lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(line));
        break;
    case 1:
        lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(line), text);
        break;
    case 2:
        if (equals != std::string::npos)
            text = text.substr(0, equals + 1) + " " + kExtremes[pick(random, kExtremes.size())];
        break;
    case 3:
        if (!text.empty())
            text[pick(random, text.size())] = static_cast<char>('a' + pick(random, 26));
        break;
    case 4:
        for (int k = 0; k < 8 && !text.empty(); ++k)
            text.insert(pick(random, text.size()), 1, static_cast<char>(random() & 0xff));
        break;
    case 5:
        for (char& c : text)
            if (c == '=' || c == '"' || c == '[' || c == ']') {
                c = ' ';
                break;
            }
        break;
    case 6:
        text = "[" + text;
        break;
    case 7:
        lines.push_back(pick(random, 2) ? "[nowhere]\nkey = 1" : "grains.count = 150");
        break;
    default:
        lines.push_back(text);
        break; // a key repeated at the end (maybe in another section)
    }
    std::ostringstream out;
    for (const auto& l : lines)
        out << l << "\n";
    std::string file = out.str();
    if (pick(random, 10) == 0) file.resize(pick(random, file.size())); // truncated
    return file;
}

std::string write(const QTemporaryDir& dir, int index, const std::string& text) {
    const std::string path =
        dir.filePath(QString("mutant_%1.toml").arg(index, 3, 10, QChar('0'))).toStdString();
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

} // namespace

void FuzzCasesTest::initTestCase() {
    std::ifstream in(LBDEM_SOURCE_DIR "/sample_cases/default.toml");
    for (std::string line; std::getline(in, line);)
        m_lines.push_back(line);
    QVERIFY(m_lines.size() > 10);
}

void FuzzCasesTest::infoSurvivesMutants() {
    std::mt19937 random(kSeed);
    QStringList failures;
    int refused = 0;
    for (int k = 0; k < kInfoMutants; ++k) {
        std::string text = mutate(m_lines, random);
        if (pick(random, 3) == 0)
            text = mutate(std::vector<std::string>{text}, random); // a second mutation
        const std::string path = write(m_dir, k, text);
        const Outcome outcome = runLbdem({"info", QString::fromStdString(path)}, 20000);
        refused += outcome.code == 2;
        const bool oneLine = outcome.code != 2 ||
                             (outcome.message.count('\n') == 1 && outcome.message.endsWith('\n'));
        if ((outcome.code != 0 && outcome.code != 2) || !oneLine)
            failures << QString("%1: exit %2: %3")
                            .arg(QString::fromStdString(path))
                            .arg(outcome.code)
                            .arg(outcome.message.left(300));
    }
    qInfo("%d of %d mutants refused with exit 2, the rest accepted", refused, kInfoMutants);
    QVERIFY2(failures.isEmpty(), qPrintable(failures.join("\n")));
    QVERIFY(refused > kInfoMutants / 4); // the mutations do break most files
}

void FuzzCasesTest::runSurvivesExtremeValues() {
    std::mt19937 random(kSeed + 1);
    const QString base = LBDEM_SOURCE_DIR "/sample_cases/default.toml";
    QStringList failures;
    for (int k = 0; k < kRunMutants; ++k) {
        const std::string key = kRunKeys[pick(random, kRunKeys.size())];
        const std::string value =
            kExtremes[pick(random, kExtremes.size() - 6)]; // not the syntax breakers
        const QString out = m_dir.filePath(QString("run_%1").arg(k));
        const Outcome outcome = runLbdem(
            {"run", base, "--out", out, "--quiet", "--until-tc", "0.02", "--set",
             "grains.count=150", "--set", "grains.packing=0.79", "--set", "fluid.resolution=4",
             "--set", "output.vtk=false", "--set", QString::fromStdString(key + "=" + value)},
            180000);
        if (outcome.code != 0 && outcome.code != 2 && outcome.code != 3)
            failures << QString("%1=%2: exit %3: %4")
                            .arg(QString::fromStdString(key),
                                 QString::fromStdString(value).left(40))
                            .arg(outcome.code)
                            .arg(outcome.message.left(300));
    }
    QVERIFY2(failures.isEmpty(), qPrintable(failures.join("\n")));
}

namespace {

constexpr int kFolders = 3;

/// A dry run of the default case's 150-grain column into dir, without VTK output; the callers add
/// its end, output interval and any other key.
QStringList smallDryRun(const QString& dir) {
    return {"run",
            LBDEM_SOURCE_DIR "/sample_cases/default.toml",
            "--out",
            dir,
            "--quiet",
            "--set",
            "grains.count=150",
            "--set",
            "grains.packing=0.79",
            "--set",
            "fluid.enabled=false",
            "--set",
            "output.vtk=false"};
}

/// A short dry run of the default case with grains.seed = seed, into dir.
QStringList shortRun(const QString& dir, int seed, const QString& untilTc) {
    return smallDryRun(dir) << "--until-tc" << untilTc << "--set"
                            << "run.end_tc=0.5"
                            << "--set"
                            << "run.output_interval_tc=0.05"
                            << "--set" << QString("grains.seed=%1").arg(seed);
}

/// Every file under dir with its bytes.
std::map<std::string, std::string> contents(const std::string& dir) {
    std::map<std::string, std::string> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir))
        if (entry.is_regular_file()) {
            std::ifstream in(entry.path(), std::ios::binary);
            files[entry.path().string()] = {std::istreambuf_iterator<char>(in),
                                            std::istreambuf_iterator<char>()};
        }
    return files;
}

/// The step column of dir/timeseries.csv (the third).
std::vector<long long> steps(const std::string& dir) {
    std::ifstream in(dir + "/timeseries.csv");
    std::vector<long long> column;
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
        std::istringstream row(line);
        std::string cell;
        for (int k = 0; k < 3 && std::getline(row, cell, ','); ++k) {
        }
        column.push_back(std::stoll(cell));
    }
    return column;
}

/// A UNIX socket file at path (what a case path must never be), or false.
bool makeSocket(const std::string& path) {
    const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    if (fd < 0 || path.size() >= sizeof address.sun_path) return false;
    std::strcpy(address.sun_path, path.c_str());
    const bool bound = ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0;
    ::close(fd); // the file stays
    return bound;
}

QByteArray fileBytes(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

} // namespace

void FuzzCasesTest::foreignCheckpointsRefused() {
    std::mt19937 random(kSeed + 2);
    QStringList folders;
    for (int k = 0; k < kFolders; ++k) {
        folders << m_dir.filePath(QString("foreign_%1").arg(k));
        const int seed = 1 + static_cast<int>(pick(random, 1000)); // a case of its own
        // Every folder a run of its own: the same seed twice still makes two runs.
        const Outcome made = runLbdem(shortRun(folders.back(), seed, "0.1"), 180000);
        QVERIFY2(made.code == 0, qPrintable(made.message));
    }
    QStringList failures;
    for (int k = 0; k < kFolders; ++k) {
        const std::string dir = folders[k].toStdString();
        const std::string other =
            folders[(k + 1 + static_cast<int>(pick(random, kFolders - 1))) % kFolders]
                .toStdString();
        std::filesystem::copy_file(dir + "/checkpoint.h5", dir + "/own.h5");
        std::filesystem::copy_file(other + "/checkpoint.h5", dir + "/checkpoint.h5",
                                   std::filesystem::copy_options::overwrite_existing);
        const auto before = contents(dir);
        const Outcome outcome = runLbdem({"resume", folders[k], "--quiet"}, 60000);
        if (outcome.code != 2 || outcome.message.count('\n') != 1 || contents(dir) != before)
            failures << QString("%1 with the checkpoint of %2: exit %3: %4")
                            .arg(folders[k], QString::fromStdString(other))
                            .arg(outcome.code)
                            .arg(outcome.message.left(300));
        std::filesystem::rename(dir + "/own.h5", dir + "/checkpoint.h5");
    }
    QVERIFY2(failures.isEmpty(), qPrintable(failures.join("\n")));
}

void FuzzCasesTest::concurrentWritersRefused() {
    std::mt19937 random(kSeed + 3);
    QStringList failures;
    for (int k = 0; k < kFolders; ++k) {
        const QString dir = m_dir.filePath(QString("writers_%1").arg(k));
        const int seed = 1 + static_cast<int>(pick(random, 1000));
        const Outcome made = runLbdem(shortRun(dir, seed, "0.1"), 180000);
        QVERIFY2(made.code == 0, qPrintable(made.message));
        // Two writers at once, each a resume or a forced fresh start of the same case.
        QStringList commands[2];
        for (auto& command : commands)
            command = pick(random, 2) ? QStringList{"resume", dir, "--quiet"}
                                      : shortRun(dir, seed, "0.3") << "--force";
        QProcess writers[2];
        qint64 pids[2];
        for (int w = 0; w < 2; ++w)
            writers[w].start(LBDEM_EXECUTABLE, commands[w]);
        for (int w = 0; w < 2; ++w)
            pids[w] = writers[w].waitForStarted() ? writers[w].processId() : -1;
        int codes[2];
        QString messages[2];
        for (int w = 0; w < 2; ++w) {
            codes[w] = writers[w].waitForFinished(180000) &&
                               writers[w].exitStatus() == QProcess::NormalExit
                           ? writers[w].exitCode()
                           : -1;
            messages[w] = QString::fromLocal8Bit(writers[w].readAllStandardError());
        }
        const auto series = steps(dir.toStdString());
        const bool increasing = std::is_sorted(series.begin(), series.end()) &&
                                std::adjacent_find(series.begin(), series.end()) == series.end();
        // Started together, one holds the folder to its end and the other is refused at once.
        for (int w = 0; w < 2; ++w) {
            const bool refusedNamingOther =
                codes[w] == 2 && messages[w].contains(QString("pid %1").arg(pids[1 - w]));
            if (!(codes[w] == 0 && codes[1 - w] == 2) && !(refusedNamingOther && codes[1 - w] == 0))
                failures << QString("%1: %2: exit %3: %4")
                                .arg(dir, commands[w].join(' ').left(80))
                                .arg(codes[w])
                                .arg(messages[w].left(300));
        }
        if (!increasing)
            failures << dir + ": timeseries.csv does not hold each step once, in order";
    }
    QVERIFY2(failures.isEmpty(), qPrintable(failures.join("\n")));
}

void FuzzCasesTest::nonRegularFilesRefused() {
    const std::string fifo = m_dir.filePath("case.fifo").toStdString();
    const std::string socket = m_dir.filePath("case.sock").toStdString();
    const std::string huge = m_dir.filePath("huge.toml").toStdString();
    QCOMPARE(::mkfifo(fifo.c_str(), 0600), 0);
    QVERIFY(makeSocket(socket));
    std::ofstream(huge) << "schema = 1\n" << std::string(3 << 20, '#') << "\n";
    const QStringList files{QString::fromStdString(fifo),
                            QString::fromStdString(socket),
                            "/dev/zero",
                            "/dev/null",
                            "/dev/urandom",
                            m_dir.path(),
                            QString::fromStdString(huge)};
    QStringList failures;
    for (const QString& file : files) {
        const QString out = m_dir.filePath("non_regular_out");
        const QList<QStringList> commands{
            {"info", file},
            {"run", file, "--out", out, "--quiet"},
            {"study", file, "--vary", "fluid.resolution=4,5", "--out", out, "--quiet"},
            {"sweep", file, "--out", out, "--quiet"},
            {"bench", "--case", file}};
        for (const QStringList& command : commands) {
            QElapsedTimer clock;
            clock.start();
            const Outcome outcome = runLbdem(command, 10000);
            const bool oneLine = outcome.message.count('\n') == 1 && outcome.message.endsWith('\n');
            if (outcome.code != 2 || !oneLine || clock.elapsed() > 5000 || QFile::exists(out))
                failures << QString("%1: exit %2 after %3 ms: %4")
                                .arg(command.join(' '))
                                .arg(outcome.code)
                                .arg(clock.elapsed())
                                .arg(outcome.message.left(300));
        }
    }
    QVERIFY2(failures.isEmpty(), qPrintable(failures.join("\n")));
}

void FuzzCasesTest::signalsAtRandomMoments() {
    std::mt19937 random(kSeed + 4);
    const auto runArguments = [](const QString& out) {
        return smallDryRun(out) << "--set"
                                << "run.end_tc=0.3"
                                << "--set"
                                << "run.output_interval_tc=0.02";
    };
    const QString reference = m_dir.filePath("signal_reference");
    QCOMPARE(runLbdem(runArguments(reference), 300000).code, 0);
    const QByteArray expected = fileBytes(reference + "/timeseries.csv");
    QStringList failures;
    for (int k = 0; k < 3; ++k) {
        const QString out = m_dir.filePath(QString("signal_%1").arg(k));
        const int signal = pick(random, 2) ? SIGTERM : SIGINT;
        const int rows = 1 + static_cast<int>(pick(random, 10)); // rows written before the signal
        QProcess process;
        process.start(LBDEM_EXECUTABLE, runArguments(out));
        while (fileBytes(out + "/timeseries.csv").count('\n') < rows + 1 &&
               !process.waitForFinished(5))
            ;
        QTest::qWait(static_cast<int>(pick(random, 30))); // anywhere within a step or a write
        ::kill(static_cast<pid_t>(process.processId()), signal);
        process.waitForFinished(120000);
        const int code = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
        const QString message = QString::fromUtf8(process.readAllStandardError());
        if (code != 0 && (code != 128 + signal || !message.contains("stopped at t/")))
            failures << QString("signal %1 after %2 rows: exit %3: %4")
                            .arg(signal)
                            .arg(rows)
                            .arg(code)
                            .arg(message.left(300));
        const Outcome resumed = runLbdem({"resume", out, "--quiet"}, 300000);
        if (resumed.code != 0 || fileBytes(out + "/timeseries.csv") != expected)
            failures << QString("signal %1 after %2 rows: resume exit %3, time series %4: %5")
                            .arg(signal)
                            .arg(rows)
                            .arg(resumed.code)
                            .arg(fileBytes(out + "/timeseries.csv") == expected ? "identical"
                                                                                : "differs")
                            .arg(resumed.message.left(300));
    }
    QVERIFY2(failures.isEmpty(), qPrintable(failures.join("\n")));
}

QTEST_GUILESS_MAIN(FuzzCasesTest)
#include "FuzzCasesTest.moc"
