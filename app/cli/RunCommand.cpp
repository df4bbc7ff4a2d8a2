// `lbdem run`: resolve and plan a case, write the resolved case and plan, then run it.
#include "app/cli/CaseOptions.h"
#include "app/cli/Cli.h"
#include "app/cli/Commands.h"
#include "solver/io/CaseWriter.h"
#include "solver/io/PlanJson.h"
#include "solver/scene/Plan.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <memory>

namespace lbdem::cli {

namespace {

struct RunOptions {
    CaseOptions caseOptions;
    std::string out;
    bool quiet = false;
};

void runCase(const RunOptions& options) {
    const solver::CaseSpec spec = options.caseOptions.load();
    const solver::Plan plan = solver::makePlan(spec);
    const std::filesystem::path dir = options.out.empty() ? "results/" + spec.name : options.out;
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error)
        throw std::runtime_error("cannot create the output folder " + dir.string() + ": " +
                                 error.message());
    io::writeCase(spec, (dir / "case.toml").string());
    io::writeFileAtomically((dir / "plan.json").string(), io::planToJson(plan).dump(2) + "\n");
    if (!options.quiet) {
        for (const auto& warning : plan.warnings) std::cerr << "warning: " << warning << "\n";
        std::cout << "wrote " << (dir / "case.toml").string() << " and "
                  << (dir / "plan.json").string() << "\n";
    }
}

} // namespace

void addRunCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<RunOptions>();
    auto* command = app.add_subcommand("run", "Run a case; writes the resolved case, the plan "
                                              "and the results into an output folder");
    options->caseOptions.addTo(*command);
    command->add_option("--out", options->out, "Output folder (default results/<case name>)");
    command->add_flag("--quiet", options->quiet, "Print nothing but errors");
    command->callback([options, &exitCode] {
        runCase(*options);
        exitCode = kExitOk;
    });
}

} // namespace lbdem::cli
