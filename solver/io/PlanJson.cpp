// Plan serialisation.
#include "solver/io/PlanJson.h"

#include <cstdio>

namespace lbdem::io {

nlohmann::json planToJson(const solver::Plan& plan) {
    return nlohmann::json{
        {"has_fluid", plan.has_fluid},
        {"has_grains", plan.has_grains},
        {"nx", plan.nx},
        {"ny", plan.ny},
        {"h_m", plan.h_m},
        {"dt_s", plan.dt_s},
        {"tau", plan.tau},
        {"nu_lattice", plan.nu_lattice},
        {"u_expected_m_s", plan.u_expected_m_s},
        {"mach", plan.mach},
        {"sound_speed_m_s", plan.sound_speed_m_s},
        {"bulk_modulus_pa", plan.bulk_modulus_pa},
        {"dem_dt_s", plan.dem_dt_s},
        {"dem_dt_safe_s", plan.dem_dt_safe_s},
        {"dem_dt_stable_s", plan.dem_dt_stable_s},
        {"substeps", plan.substeps},
        {"grains", plan.grains},
        {"tc_s", plan.tc_s},
        {"end_time_s", plan.end_time_s},
        {"steps", plan.steps},
        {"memory_bytes", plan.memory_bytes},
        {"output_bytes", plan.output_bytes},
        {"estimated_run_s", plan.estimated_run_s},
        {"column_width_m", plan.column.width_m},
        {"column_height_m", plan.column.height_m},
        {"absorbing_layer_nodes", plan.absorbing_layer_nodes},
        {"runout_room", plan.runout_room},
        {"notes", plan.notes},
        {"warnings", plan.warnings},
    };
}

std::string formatPlan(const solver::Plan& plan) {
    std::string text;
    auto line = [&text](const char* name, const char* pattern, double value, const char* unit) {
        char buffer[160];
        char number[64];
        std::snprintf(number, sizeof number, pattern, value);
        std::snprintf(buffer, sizeof buffer, "  %-22s %14s  %s\n", name, number, unit);
        text += buffer;
    };
    text += plan.has_fluid ? "Fluid lattice\n" : "Fluid lattice: none (dry scene)\n";
    if (plan.has_fluid) {
        line("nodes nx", "%.0f", plan.nx, "");
        line("nodes ny", "%.0f", plan.ny, "");
        line("spacing h", "%.4g", plan.h_m, "m");
        line("time step dt", "%.4g", plan.dt_s, "s");
        line("relaxation time tau", "%.6g", plan.tau, "");
        line("lattice viscosity", "%.4g", plan.nu_lattice, "lattice units");
        line("expected velocity", "%.4g", plan.u_expected_m_s, "m/s");
        line("expected Mach", "%.4g", plan.mach, "");
        line("sound speed", "%.4g", plan.sound_speed_m_s, "m/s (lattice; water 1480)");
        line("bulk modulus", "%.4g", plan.bulk_modulus_pa, "Pa (rho_f c_s^2; water 2.2e9)");
        line("DEM sub-steps", "%.0f", plan.substeps, "per fluid step");
        line("absorbing layer", "%.0f", plan.absorbing_layer_nodes, "nodes");
    }
    text += "Grains\n";
    line("grains", "%.0f", static_cast<double>(plan.grains), "discs");
    line("column width L_i", "%.4g", plan.column.width_m, "m");
    line("column height H_i", "%.4g", plan.column.height_m, "m");
    line("DEM time step", "%.4g", plan.dem_dt_s, "s (used)");
    line("DEM stable step", "%.4g", plan.dem_dt_stable_s, "s (stability limit)");
    text += "Run\n";
    line("tau_c", "%.4g", plan.tc_s, "s");
    line("end time", "%.4g", plan.end_time_s, "s");
    line("steps", "%.0f", static_cast<double>(plan.steps), "");
    line("memory", "%.1f", plan.memory_bytes / 1048576.0, "MiB (estimate)");
    line("outputs", "%.1f", plan.output_bytes / 1048576.0,
         "MiB (upper bound, all files of the run)");
    line("estimated run time", "%.0f", plan.estimated_run_s,
         "s (rough, from assumed throughputs; lbdem bench --case measures)");
    for (const auto& note : plan.notes)
        text += "note: " + note + "\n";
    for (const auto& warning : plan.warnings)
        text += "warning: " + warning + "\n";
    return text;
}

} // namespace lbdem::io
