// summary.json from the Simulation and its running diagnostics.
#include "solver/io/RunSummary.h"

#include "solver/io/CaseWriter.h"
#include "solver/scene/SceneKind.h"

namespace lbdem::io {

nlohmann::json runSummary(const solver::Simulation& simulation, bool finished,
                          const std::string& stopReason) {
    const auto& plan = simulation.plan();
    const auto& diagnostics = simulation.runDiagnostics();
    const double wallSeconds = diagnostics.wallSeconds();
    const double steps = static_cast<double>(diagnostics.stepsTimed());
    const double nodes = static_cast<double>(plan.nx) * plan.ny;
    const auto& last = diagnostics.lastMetrics();
    nlohmann::json summary{
        {"case", simulation.spec().name},
        {"finished", finished},
        {"scene", solver::enumWord(simulation.spec().scene)},
        {"plan",
         {{"h", plan.h_m},
          {"dt", plan.dt_s},
          {"tau", plan.tau},
          {"mach", plan.mach},
          {"nx", plan.nx},
          {"ny", plan.ny},
          {"substeps", plan.substeps}}},
        {"steps", simulation.stepIndex()},
        {"t_over_tc", simulation.timeOverTc()},
        {"wall_s", wallSeconds},
        {"mlups", wallSeconds > 0 ? nodes * steps / wallSeconds / 1e6 : 0.0},
        {"final", last},
    };
    auto final = [&](const char* metric) {
        const auto found = last.find(metric);
        return found == last.end() ? nlohmann::json(nullptr) : nlohmann::json(found->second);
    };
    summary["runout_final"] = final("runout_normalised");
    summary["packing_final"] = final("packing_fraction");
    summary["ke_peak"] = diagnostics.kePeak();
    summary["t_ke_peak_over_tc"] = diagnostics.tKePeakOverTc();
    // Where the time went, per stage of the step, over every process of the run (outputs are
    // not counted). wall_s, mlups and stage_seconds are the only figures that depend on the
    // machine.
    nlohmann::json stages = nlohmann::json::object();
    const auto stageSeconds = diagnostics.stageSeconds();
    for (std::size_t k = 0; k < static_cast<std::size_t>(solver::Stage::Count); ++k)
        stages[std::string(solver::stageName(static_cast<solver::Stage>(k)))] =
            k < stageSeconds.size() ? stageSeconds[k] : 0.0;
    summary["stage_seconds"] = stages;
    if (!stopReason.empty()) summary["stop_reason"] = stopReason;
    return summary;
}

void writeRunSummary(const std::filesystem::path& dir, const solver::Simulation& simulation,
                     bool finished, const std::string& stopReason) {
    // Durable: a sweep or study that reads it after a crash of the machine finds the last state.
    writeFileAtomically((dir / "summary.json").string(),
                        runSummary(simulation, finished, stopReason).dump(2) + "\n", true);
}

std::vector<std::string> runSummaryNumbers(const solver::CaseSpec& spec) {
    std::vector<std::string> names{"steps", "t_over_tc", "wall_s", "mlups", "t_s", "step"};
    if (spec.scene == solver::SceneKind::ColumnCollapse)
        names.insert(names.end(),
                     {"runout_final", "packing_final", "ke_peak", "t_ke_peak_over_tc"});
    return names;
}

} // namespace lbdem::io
