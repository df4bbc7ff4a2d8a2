// `lbdem verify`: run named verification cases and report error against tolerance.
#include "app/cli/Cli.h"
#include "app/cli/Commands.h"
#include "app/cli/PermeabilityPlot.h"
#include "solver/core/InputError.h"
#include "solver/core/TextDistance.h"
#include "solver/verification/Verification.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

namespace lbdem::cli {

namespace {

constexpr const char* kPermeabilityTable = "coupling-permeability.csv";
constexpr const char* kPermeabilityPlot = "coupling-permeability.png";

struct VerifyOptions {
    std::vector<std::string> names;
    bool list = false;
    bool json = false;
    bool longRun = false;
    int threads = 0;
};

std::vector<const solver::VerificationCase*> selectCases(const std::vector<std::string>& names) {
    const auto& cases = solver::verificationCases();
    std::vector<const solver::VerificationCase*> selected;
    if (names.empty()) {
        for (const auto& c : cases)
            selected.push_back(&c);
        return selected;
    }
    std::vector<std::string> known;
    for (const auto& c : cases)
        known.push_back(c.name);
    for (const auto& name : names) {
        const solver::VerificationCase* found = nullptr;
        for (const auto& c : cases)
            if (c.name == name) found = &c;
        if (!found) {
            const std::string nearest = solver::nearestWord(name, known);
            throw solver::InputError("unknown verification case '" + name + "'" +
                                     (nearest.empty() ? "" : "; did you mean '" + nearest + "'?") +
                                     " (lbdem verify --list shows them all)");
        }
        selected.push_back(found);
    }
    return selected;
}

nlohmann::json toJson(const solver::VerificationResult& r) {
    return {{"name", r.name},           {"quantity", r.quantity}, {"value", r.value},
            {"reference", r.reference}, {"error", r.error},       {"tolerance", r.tolerance},
            {"passed", r.passed},       {"wall_s", r.wall_s},     {"method", r.method},
            {"source", r.source}};
}

void printRow(const solver::VerificationResult& r) {
    std::printf("%-4s %-22s %-14s %-44s value %-12.6g ref %-12.6g err %-10.3g tol %-8.3g %6.2f s\n",
                r.passed ? "ok" : "FAIL", r.name.c_str(), r.method.c_str(), r.quantity.c_str(),
                r.value, r.reference, r.error, r.tolerance, r.wall_s);
    std::fflush(stdout);
}

int runVerify(const VerifyOptions& options) {
    const auto cases = selectCases(options.names);
    if (options.list) {
        for (const auto* c : cases)
            std::printf("%-22s %s\n", c->name.c_str(), c->description.c_str());
        return kExitOk;
    }
    solver::VerificationOptions runOptions;
    runOptions.long_run = options.longRun;
    runOptions.threads = options.threads;
    nlohmann::json records = nlohmann::json::array();
    bool allPassed = true;
    for (const auto* c : cases) {
        for (const auto& result : c->run(runOptions)) {
            allPassed = allPassed && result.passed;
            if (options.json)
                records.push_back(toJson(result));
            else
                printRow(result);
        }
    }
    if (options.json) std::cout << records.dump(2) << "\n";
    for (const auto* c : cases) {
        // The permeability case writes its table; draw it as the paper's Figure 3 beside it.
        if (c->name == "permeability" && std::filesystem::exists(kPermeabilityTable) &&
            writePermeabilityPlot(kPermeabilityTable, kPermeabilityPlot))
            std::cerr << "wrote " << kPermeabilityTable << " and " << kPermeabilityPlot << "\n";
    }
    return allPassed ? kExitOk : kExitFailure;
}

} // namespace

void addVerifyCommand(CLI::App& app, int& exitCode) {
    auto options = std::make_shared<VerifyOptions>();
    auto* command = app.add_subcommand("verify", "Compare the solver with analytic and "
                                                 "published solutions");
    command->add_option("names", options->names, "Verification cases to run (default: all)");
    command->add_flag("--list", options->list, "List the cases and what each checks");
    command->add_flag("--json", options->json,
                      "Print an array of {name, quantity, value, reference, error, tolerance, "
                      "passed, wall_s}");
    command->add_flag("--long", options->longRun, "Run the finer, slower variants");
    command->add_option("--threads", options->threads, "OpenMP threads (0 = all cores)")
        ->check(CLI::Range(0, 1024));
    command->callback([options, &exitCode] { exitCode = runVerify(*options); });
}

} // namespace lbdem::cli
