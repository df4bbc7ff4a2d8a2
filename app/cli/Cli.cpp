// The lbdem command line: builds the CLI11 application and maps failures to exit codes.
#include "app/cli/Cli.h"

#include "app/cli/Commands.h"
#include "app/cli/StopSignals.h"
#include "campaign/JobRunner.h"
#include "solver/core/InputError.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <new>

namespace lbdem::cli {

int runCli(int argc, char** argv) {
    campaign::endWithParent(); // a sweep's or study's run ends with its sweep or study
    CLI::App app{"lbdem — 2D lattice-Boltzmann / discrete-element simulator of submerged "
                 "granular flows"};
    app.footer("Exit codes: 0 success; 1 failure (a file that cannot be written, memory exhausted, "
               "failed runs "
               "in a sweep or study); 2 bad input (case, options, output folder, checkpoint); 3 a "
               "run stopped by "
               "a stability guard (lattice or DEM; summary.json gives the diagnosis); 130 or 143 "
               "a run stopped by SIGINT or SIGTERM after writing its checkpoint (lbdem resume "
               "continues it).");
    app.require_subcommand(1);
    app.set_version_flag("--version", "lbdem 0.1.0");
    int exitCode = kExitOk;
    addInfoCommand(app, exitCode);
    addRunCommand(app, exitCode);
    addVerifyCommand(app, exitCode);
    addBenchCommand(app, exitCode);
    addSweepCommand(app, exitCode);
    addStudyCommand(app, exitCode);
#ifdef LBDEM_HAS_VIS
    addRenderCommand(app, exitCode);
#endif
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& help) {
        return app.exit(help);
    } catch (const CLI::CallForAllHelp& help) {
        return app.exit(help);
    } catch (const CLI::CallForVersion& version) {
        return app.exit(version);
    } catch (const CLI::ParseError& error) {
        std::cerr << "lbdem: " << error.what() << " (see lbdem --help)\n";
        return kExitBadInput;
    } catch (const solver::InputError& error) {
        std::cerr << "lbdem: " << error.what() << "\n";
        return kExitBadInput;
    } catch (const solver::SimulationError& error) {
        std::cerr << "lbdem: the simulation stopped: " << error.what() << "\n";
        return kExitUnstable;
    } catch (const StoppedBySignal& stopped) {
        std::cerr << "lbdem: " << stopped.what() << "\n";
        return stopped.exitCode();
    } catch (const std::bad_alloc&) {
        std::cerr << "lbdem: out of memory (lbdem info CASE estimates what a case needs)\n";
        return kExitFailure;
    } catch (const std::exception& error) {
        std::cerr << "lbdem: " << error.what() << "\n";
        return kExitFailure;
    }
    return exitCode;
}

} // namespace lbdem::cli
