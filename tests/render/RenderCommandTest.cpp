// `lbdem render` end to end on a synthetic run folder, with no DISPLAY (a private Xvfb is started).
#include "tests/render/ImageBaseline.h"
#include "tests/support/SyntheticSnapshot.h"
#include "ui/vis/HeadlessDisplay.h"

#include <vtkImageData.h>

#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include <cstdlib>
#include <filesystem>

using namespace lbdem;

class RenderCommandTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void lastFrameWithoutDisplay();
    void allFramesIntoFolder();
    void timePicksNearestFrame();
    void fixedRangesChangeTheImage();
    void badInputExitsTwo_data();
    void badInputExitsTwo();
    void staleDisplayFallsBackToXvfb();
    void privateXvfbStopsWithItsOwner();

private:
    int lbdem(const QStringList& arguments, QString* output = nullptr, const QString& display = {});
    QTemporaryDir m_dir;
    QString m_run;
};

void RenderCommandTest::initTestCase() {
    ::unsetenv("DISPLAY"); // the acceptance case: no X server given
    QVERIFY(m_dir.isValid());
    m_run = m_dir.filePath("run");
    support::writeSyntheticRun(m_run.toStdString(), 4);
}

int RenderCommandTest::lbdem(const QStringList& arguments, QString* output,
                             const QString& display) {
    QProcess process;
    QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
    environment.remove("DISPLAY");
    if (!display.isEmpty()) environment.insert("DISPLAY", display);
    process.setProcessEnvironment(environment);
    process.setProcessChannelMode(QProcess::MergedChannels);
    process.start(LBDEM_EXECUTABLE, arguments);
    if (!process.waitForFinished(120000)) return -1;
    if (output) *output = QString::fromUtf8(process.readAll());
    return process.exitCode();
}

void RenderCommandTest::lastFrameWithoutDisplay() {
    const QString png = m_dir.filePath("last.png");
    QString output;
    QCOMPARE(
        lbdem({"render", m_run, "--frame", "last", "--png", png, "--size", "400x300"}, &output), 0);
    QVERIFY2(output.contains("frame 3"), qPrintable(output));
    const auto image = support::readPng(png.toStdString());
    QVERIFY(image);
    int dims[3];
    image->GetDimensions(dims);
    QCOMPARE(dims[0], 400);
    QCOMPARE(dims[1], 300);
    // Fluid colours, grains, chains and outline together give far more than a few colours.
    QVERIFY(support::distinctColours(image) > 200);
    int orange = 0, blue = 0, white = 0;
    for (int y = 0; y < dims[1]; ++y)
        for (int x = 0; x < dims[0]; ++x) {
            const auto* p = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
            orange += p[0] > 220 && p[1] > 100 && p[1] < 200 && p[2] < 80; // grain colour map
            blue += p[2] > 150 && p[0] < 80 && p[1] < 120;                 // force-chain colour map
            white += p[0] > 250 && p[1] > 250 && p[2] > 250;               // outline and margins
        }
    QVERIFY2(orange > 50 && blue > 20 && white > 100,
             qPrintable(QString("orange %1 blue %2 white %3").arg(orange).arg(blue).arg(white)));
}

void RenderCommandTest::allFramesIntoFolder() {
    const QString folder = m_dir.filePath("frames");
    QCOMPARE(lbdem({"render", m_run, "--all", "--png", folder, "--size", "200x150", "--quiet"}), 0);
    for (int k = 0; k < 4; ++k)
        QVERIFY(std::filesystem::exists(folder.toStdString() + "/frame_00000" + std::to_string(k) +
                                        ".png"));
}

void RenderCommandTest::timePicksNearestFrame() {
    QString output;
    const QString png = m_dir.filePath("t.png");
    QCOMPARE(lbdem({"render", m_run, "--time", "0.049", "--png", png, "--size", "200x150",
                    "--layers", "grains,chains,streamlines", "--field", "vorticity"},
                   &output),
             0);
    QVERIFY2(output.contains("frame 2"), qPrintable(output));
}

void RenderCommandTest::fixedRangesChangeTheImage() {
    // The same frame with automatic and with fixed colour ranges: a far wider fixed range maps
    // every speed to the low end of the colour maps, so most coloured pixels must differ.
    const QString automatic = m_dir.filePath("auto.png"), fixed = m_dir.filePath("fixed.png");
    QCOMPARE(lbdem({"render", m_run, "--png", automatic, "--size", "900x600", "--quiet"}), 0);
    QCOMPARE(lbdem({"render", m_run, "--png", fixed, "--size", "900x600", "--quiet",
                    "--fluid-range", "0,1000", "--grain-range", "0,1000"}),
             0);
    const auto a = support::readPng(automatic.toStdString()),
               b = support::readPng(fixed.toStdString());
    QVERIFY(a && b);
    int dims[3];
    a->GetDimensions(dims);
    int differing = 0;
    for (int y = 0; y < dims[1]; ++y)
        for (int x = 0; x < dims[0]; ++x) {
            const auto* p = static_cast<unsigned char*>(a->GetScalarPointer(x, y, 0));
            const auto* q = static_cast<unsigned char*>(b->GetScalarPointer(x, y, 0));
            differing += p[0] != q[0] || p[1] != q[1] || p[2] != q[2];
        }
    QVERIFY2(differing > dims[0] * dims[1] / 10,
             qPrintable(QString("%1 pixels differ").arg(differing)));
}

void RenderCommandTest::badInputExitsTwo_data() {
    QTest::addColumn<QStringList>("arguments");
    QTest::newRow("missing frame") << QStringList{"--frame", "9"};
    QTest::newRow("bad layer") << QStringList{"--layers", "fluid,grain"};
    QTest::newRow("bad size") << QStringList{"--size", "300"};
    QTest::newRow("frame and all") << QStringList{"--frame", "1", "--all"};
    QTest::newRow("inverted fluid range") << QStringList{"--fluid-range", "0.1,0.02"};
    QTest::newRow("one-number grain range") << QStringList{"--grain-range", "0.5"};
}

void RenderCommandTest::badInputExitsTwo() {
    QFETCH(QStringList, arguments);
    QString output;
    QCOMPARE(lbdem(QStringList{"render", m_run, "--png", m_dir.filePath("bad.png")} + arguments,
                   &output),
             2);
    QVERIFY(!output.contains("terminate"));
    QCOMPARE(lbdem({"render", m_dir.filePath("nowhere"), "--png", m_dir.filePath("bad.png")}), 2);
}

void RenderCommandTest::staleDisplayFallsBackToXvfb() {
    // A DISPLAY left over from a closed session: VTK would abort; lbdem starts its own Xvfb.
    int unused = 900;
    while (std::filesystem::exists("/tmp/.X11-unix/X" + std::to_string(unused)))
        ++unused;
    const QString png = m_dir.filePath("stale.png");
    QCOMPARE(lbdem({"render", m_run, "--png", png, "--size", "200x150", "--quiet"}, nullptr,
                   QString(":%1").arg(unused)),
             0);
    QVERIFY(std::filesystem::exists(png.toStdString()));
}

void RenderCommandTest::privateXvfbStopsWithItsOwner() {
    int display = -1;
    {
        vis::HeadlessDisplay headless;
        QVERIFY(headless.startedXvfb());
        display = headless.displayNumber();
        QCOMPARE(QString(std::getenv("DISPLAY")), QString(":%1").arg(display));
        QVERIFY(std::filesystem::exists("/tmp/.X11-unix/X" + std::to_string(display)));
    }
    QVERIFY(std::getenv("DISPLAY") == nullptr);
    QVERIFY(!std::filesystem::exists("/tmp/.X" + std::to_string(display) + "-lock"));
}

QTEST_GUILESS_MAIN(RenderCommandTest)
#include "RenderCommandTest.moc"
