// `lbdem run` and `lbdem resume`: resolve and plan a case, then drive the Simulation.
#include "app/cli/CaseOptions.h"
#include "app/cli/Cli.h"
#include "app/cli/Commands.h"
#include "app/cli/ProfileSink.h"
#include "app/cli/RunDriver.h"
#include "app/cli/RunSinks.h"
#include "campaign/RunFolder.h"
#include "solver/core/InputError.h"
#include "solver/core/OpenMp.h"
#include "solver/io/CaseLoader.h"
#include "solver/io/CaseWriter.h"
#include "solver/io/Checkpoint.h"
#include "solver/io/PlanJson.h"
#include "solver/io/RunIdentity.h"
#include "solver/io/RunLock.h"
#include "solver/io/SafeFile.h"
#include "solver/scene/Plan.h"
#include "solver/scene/Simulation.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

namespace lbdem::cli {

namespace fs = std::filesystem;

namespace {

struct RunOptions {
    CaseOptions caseOptions;
    std::string out;
    std::string resumeDir;
    double renderEveryTc = 0;
    std::optional<double> untilTc; ///< checked against the case by checkUntilTc
    bool quiet = false;
    bool force = false;
};

void applyThreads(const solver::CaseSpec& spec) {
    solver::ompSetThreads(spec.run.threads);
}

void drive(solver::Simulation& simulation, const fs::path& dir, const RunOptions& options,
           bool resumed, const io::RunIdentity& identity) {
    const auto& spec = simulation.spec();
    if (spec.output.vtk && !sinksAvailable() && !options.quiet)
        std::cerr
            << "warning: this build has no VTK (LBDEM_GUI=OFF): no VTU/VTI files are written\n";
    RunDriverOptions driverOptions{dir, options.quiet, options.untilTc.value_or(-1), resumed,
                                   identity};
    RunDriver driver(simulation, driverOptions);
    SinkOptions sinkOptions{spec.output.vtk, spec.output.vtk_every, options.renderEveryTc,
                            spec.run.output_interval_tc, resumed};
    // A resumed run writes again the frames after its checkpoint: the series keeps those before.
    if (resumed) sinkOptions.keep_until_s = simulation.time() + 0.5 * simulation.plan().dt_s;
    for (auto& sink : makeRunSinks(dir.string(), sinkOptions))
        driver.addSink(std::move(sink));
    driver.addSink(makeProfileSink(dir.string()));
    driver.run();
    if (!options.quiet) std::cout << "outputs in " << dir.string() << "/\n";
}

/// Build the Simulation of a case; a case that cannot be built (a packing that cannot reach its
/// target, a column that does not fit) is bad input, named after where the case came from.
std::unique_ptr<solver::Simulation>
buildSimulation(const solver::CaseSpec& spec, const solver::Plan& plan, const std::string& source) {
    try {
        return std::make_unique<solver::Simulation>(spec, plan);
    } catch (const solver::SimulationError& error) {
        throw solver::InputError(source + ": the case cannot be built: " + error.what());
    }
}

void runCase(const RunOptions& options) {
    // Everything is checked before anything is written: the case, its plan, the folder, the
    // machine's memory and disk, and the scene itself.
    const solver::CaseSpec spec = options.caseOptions.load();
    const solver::Plan plan = solver::makePlan(spec);
    checkUntilTc(options.untilTc, plan);
    const fs::path dir = options.out.empty() ? "results/" + spec.name : options.out;
    io::requireWritableFolder(dir.string()); // before the lock file is opened or made
    // One writer at a time: a folder that another process is writing is refused first, naming
    // it; a folder without a lock file gets one only once every check has passed.
    std::optional<io::RunLock> lock;
    if (fs::exists(dir / io::RunLock::kFileName)) lock.emplace(dir);
    campaign::refuseExistingRun(dir, options.force);
    campaign::checkResources(plan, dir, options.force, options.quiet);
    applyThreads(spec);
    const auto simulation = buildSimulation(
        spec, plan, options.caseOptions.path.empty() ? "the case" : options.caseOptions.path);
    if (!lock) lock.emplace(dir); // before anything in the folder is removed or written
    campaign::prepareRunFolder(dir, options.force);
    const io::RunIdentity identity = io::newRunIdentity(io::formatCase(spec));
    io::writeRunIdentity(dir, identity);
    io::writeCase(spec, (dir / "case.toml").string());
    io::writeFileAtomically((dir / "plan.json").string(), io::planToJson(plan).dump(2) + "\n");
    if (!options.quiet)
        for (const auto& warning : plan.warnings)
            std::cerr << "warning: " << warning << "\n";
    drive(*simulation, dir, options, false, identity);
}

void resumeCase(const RunOptions& options) {
    const fs::path dir = options.resumeDir;
    const fs::path checkpoint = dir / "checkpoint.h5";
    if (!fs::is_directory(dir))
        throw solver::InputError(dir.string() +
                                 " is not a folder: lbdem resume takes the output folder of a run");
    if (!fs::exists(checkpoint))
        throw solver::InputError(
            checkpoint.string() + ": no checkpoint to resume from; " +
            (campaign::holdsRun(dir)
                 ? "the run was stopped before it wrote one (at t = 0); start it again with "
                   "lbdem run CASE --out " +
                       dir.string() + " --force"
                 : "was the run started with lbdem run --out " + dir.string() + "?"));
    io::requireWritableFolder(dir.string()); // before the lock file is made
    const io::RunLock lock(dir);
    const io::CheckpointData data = io::readCheckpoint(checkpoint.string(), options.force);
    if (!data.verified && !options.quiet)
        std::cerr << "warning: " << checkpoint.string()
                  << " carries no checksum: resuming it unverified (--force)\n";
    // A checkpoint that another run wrote is refused before anything is changed.
    const auto folderIdentity = io::readRunIdentity(dir);
    io::checkCheckpointBelongs(checkpoint.string(), data, folderIdentity);
    const solver::CaseSpec spec =
        io::parseCase(data.case_toml, checkpoint.string() + " (case_toml)");
    const solver::Plan plan = solver::makePlan(spec);
    checkUntilTc(options.untilTc, plan);
    applyThreads(spec);
    const auto simulation = buildSimulation(spec, plan, checkpoint.string());
    try {
        simulation->restoreState(data.state);
    } catch (const std::exception& error) {
        throw solver::InputError(checkpoint.string() +
                                 " does not match the case it holds: " + error.what());
    }
    // A folder of an older lbdem (no run.json, a checkpoint without run id) gets an identity now.
    const io::RunIdentity identity =
        folderIdentity ? *folderIdentity : io::newRunIdentity(data.case_toml);
    if (!folderIdentity) io::writeRunIdentity(dir, identity);
    if (!options.quiet)
        std::cout << "resuming " << spec.name << " at t/tc = " << simulation->timeOverTc()
                  << " (step " << simulation->stepIndex() << ")\n";
    drive(*simulation, dir, options, true, identity);
}

} // namespace

void addRunCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<RunOptions>();
    auto* command =
        app.add_subcommand("run", "Run a case; writes the resolved case, the plan, "
                                  "timeseries.csv, summary.json, VTK series and a checkpoint");
    options->caseOptions.addTo(*command);
    command->add_option("--out", options->out, "Output folder (default results/<case name>)");
    command
        ->add_option("--render-every", options->renderEveryTc,
                     "Also render a PNG frame every X tau_c into OUT/frames/")
        ->check(CLI::NonNegativeNumber);
    command->add_option("--until-tc", options->untilTc, "Stop at this t / tau_c (resume later)");
    command->add_flag("--quiet", options->quiet, "Print nothing but errors");
    command->add_flag(
        "--force", options->force,
        "Replace a run already in the output folder (its outputs, and nothing else, are removed "
        "first; a folder that holds files but no run is refused), and run even when the plan's "
        "memory or outputs exceed this machine's memory or free disk");
    command->callback([options, &exitCode] {
        runCase(*options);
        exitCode = kExitOk;
    });

    auto resumeOptions = std::make_shared<RunOptions>();
    auto* resume =
        app.add_subcommand("resume", "Continue a run from DIR/checkpoint.h5, bit for bit");
    resume->add_option("dir", resumeOptions->resumeDir, "Output folder of the run")->required();
    resume->add_option("--until-tc", resumeOptions->untilTc,
                       "Stop at this t / tau_c instead of the case's end");
    resume->add_option("--render-every", resumeOptions->renderEveryTc, "PNG frame every X tau_c")
        ->check(CLI::NonNegativeNumber);
    resume->add_flag("--quiet", resumeOptions->quiet, "Print nothing but errors");
    resume->add_flag("--force", resumeOptions->force,
                     "Resume a checkpoint that carries no checksum (written before checksums, or "
                     "with its checksum attribute damaged), unverified");
    resume->callback([resumeOptions, &exitCode] {
        resumeCase(*resumeOptions);
        exitCode = kExitOk;
    });
}

} // namespace lbdem::cli
