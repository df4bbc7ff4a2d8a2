// `lbdem info`: the plan of a case, or the complete documented default case.
#include "app/cli/CaseOptions.h"
#include "app/cli/Cli.h"
#include "app/cli/Commands.h"
#include "campaign/RunFolder.h"
#include "solver/io/CaseWriter.h"
#include "solver/io/PlanJson.h"
#include "solver/scene/Plan.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace lbdem::cli {

namespace {

struct InfoOptions {
    CaseOptions caseOptions;
    bool json = false;
    bool defaults = false;
};

void runInfo(const InfoOptions& options) {
    if (options.defaults) {
        std::cout << io::formatCase(options.caseOptions.load());
        return;
    }
    const solver::CaseSpec spec = options.caseOptions.load();
    const solver::Plan plan = solver::makePlan(spec);
    if (options.json) {
        std::cout << io::planToJson(plan).dump(2) << "\n";
        return;
    }
    std::cout << "Case '" << spec.name << "' (scene " << solver::enumWord(spec.scene) << ")\n"
              << io::formatPlan(plan);
    // Would it fit here? (lbdem run refuses what does not, unless --force.)
    for (const auto& problem : campaign::resourceProblems(plan, "results/" + spec.name))
        std::cout << "warning: " << problem << "\n";
}

} // namespace

void addInfoCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<InfoOptions>();
    auto* command = app.add_subcommand("info", "Print the plan of a case (lattice, time steps, "
                                               "stability numbers, cost) or the default case");
    options->caseOptions.addTo(*command, false);
    command->add_flag("--json", options->json, "Print the plan as JSON");
    command->add_flag("--defaults", options->defaults,
                      "Print the complete documented default case (with --set applied)");
    command->callback([options, &exitCode] {
        if (!options->defaults && options->caseOptions.path.empty())
            throw CLI::RequiredError("info needs a CASE file (or --defaults)");
        runInfo(*options);
        exitCode = kExitOk;
    });
}

} // namespace lbdem::cli
