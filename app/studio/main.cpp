// lbdem-studio: the desktop application; a thin main over lbdem::studio (docs/style.md, Style §1).
#include "solver/io/CaseLoader.h"
#include "ui/studio/LiveView.h"
#include "ui/studio/MainWindow.h"
#include "ui/studio/ScriptedRun.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>

#include <iostream>

int main(int argc, char** argv) {
    using namespace lbdem::studio;
    QCommandLineParser parser;
    parser.setApplicationDescription("Set up, run and watch lbdem cases.");
    const QCommandLineOption help = parser.addHelpOption();
    const QCommandLineOption version = parser.addVersionOption();
    parser.addPositionalArgument("case", "TOML case file to open.", "[CASE]");
    const QCommandLineOption set("set", "Override a case key, e.g. fluid.tau=0.51.",
                                 "section.key=value");
    const QCommandLineOption steps("run-steps", "Run this many steps at start.", "N");
    const QCommandLineOption shot("screenshot", "Save the window as PNG once the run is shown.",
                                  "FILE");
    const QCommandLineOption quit("quit", "Quit after the screenshot.");
    const QCommandLineOption ensemble(
        "ensemble",
        "Shade behind the live curves the band of the case's finished runs in a sweep "
        "folder (lbdem sweep --seeds).",
        "DIR");
    parser.addOptions({set, steps, shot, quit, ensemble});

    // Bad input is reported before any window or display is touched: one sentence, exit 2.
    QStringList arguments;
    for (int k = 0; k < argc; ++k)
        arguments << QString::fromLocal8Bit(argv[k]);
    if (!parser.parse(arguments)) {
        std::cerr << "lbdem-studio: " << parser.errorText().toStdString() << "\n";
        return 2;
    }
    if (parser.isSet(help) || parser.isSet(version)) {
        // Answered without a display: a core application is enough to print and exit.
        QCoreApplication core(argc, argv);
        QCoreApplication::setApplicationName("lbdem-studio");
        QCoreApplication::setApplicationVersion(LBDEM_VERSION);
        parser.process(core);
        return 0;
    }
    ScriptOptions script;
    bool stepsOk = true;
    if (parser.isSet(steps)) script.steps = parser.value(steps).toLongLong(&stepsOk);
    if (!stepsOk || script.steps < 0) {
        std::cerr << "lbdem-studio: --run-steps expects a whole number of steps, got '"
                  << parser.value(steps).toStdString() << "'.\n";
        return 2;
    }
    if (parser.isSet(ensemble) && !QFileInfo(parser.value(ensemble)).isDir()) {
        std::cerr << "lbdem-studio: --ensemble expects a sweep folder, and '"
                  << parser.value(ensemble).toStdString() << "' is not a folder.\n";
        return 2;
    }
    script.screenshot = parser.value(shot);
    script.quit = parser.isSet(quit);
    const bool scripted = parser.isSet(steps) || parser.isSet(shot) || script.quit;
    std::vector<std::string> overrides;
    for (const QString& assignment : parser.values(set))
        overrides.push_back(assignment.toStdString());
    const QString path = parser.positionalArguments().value(0);
    lbdem::solver::CaseSpec spec = lbdem::solver::defaultCase();
    try {
        if (!path.isEmpty()) spec = lbdem::io::loadCase(path.toStdString(), overrides);
    } catch (const std::exception& error) {
        std::cerr << error.what() << "\n";
        return 2;
    }

    configureOpenGlFormat();
    QApplication app(argc, argv);
    QApplication::setOrganizationName("lbdem");
    QApplication::setApplicationName("lbdem-studio");
    QApplication::setApplicationVersion(LBDEM_VERSION);
    parser.process(app); // --help and --version print and exit here

    MainWindow window;
    if (parser.isSet(ensemble)) window.setEnsembleFolder(parser.value(ensemble));
    if (!path.isEmpty() || scripted) window.setCase(spec, path.isEmpty() ? "defaults" : path);
    if (scripted) window.resize(1400, 900); // a fixed size keeps documentation images alike
    window.show();
    if (!scripted) return app.exec();

    auto* run = new ScriptedRun(window, script);
    QObject::connect(run, &ScriptedRun::finished, &app, [&app, &script](int code) {
        if (script.quit || code != 0) app.exit(code);
    });
    run->start();
    return app.exec();
}
