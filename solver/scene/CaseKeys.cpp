// Every case key, declared once with its unit, range and documentation (docs/design.md, Style §5).
#include "solver/scene/CaseKeys.h"

#include "solver/scene/CaseSchema.h"
#include "solver/scene/SceneKind.h"

namespace lbdem::solver {

namespace {

void declareTopLevel(CaseSchema& s) {
    s.addInteger("", "schema", "-", 1, 1, "Case-file schema version; this build reads 1.",
                 [](CaseSpec& c) -> int& { return c.schema; });
    s.addText("", "name", "Case name; results go to a folder of this name.",
              [](CaseSpec& c) -> std::string& { return c.name; });
    s.addChoice("", "scene", sceneNames(),
                "Scene builder: the paper's collapse or a verification flow.",
                [](CaseSpec& c) -> std::string& { return c.scene; });
}

void declareDomain(CaseSchema& s) {
    s.addReal("domain", "width_m", "m", 1e-4, 100, "Domain extent along the slope (x).",
              [](CaseSpec& c) -> double& { return c.domain.width_m; });
    s.addReal("domain", "height_m", "m", 1e-4, 100, "Domain extent normal to the slope (y).",
              [](CaseSpec& c) -> double& { return c.domain.height_m; });
    s.addReal("domain", "slope_deg", "deg", -45, 45,
              "Slope angle: gravity is tilted to (g sin theta, -g cos theta), +x downslope.",
              [](CaseSpec& c) -> double& { return c.domain.slope_deg; });
    s.addReal("domain", "gravity_m_s2", "m/s^2", 0, 100, "Magnitude of gravity.",
              [](CaseSpec& c) -> double& { return c.domain.gravity_m_s2; });
    s.addChoice("domain", "top", {"wall", "free_slip", "pressure", "periodic"},
                "Top boundary of the fluid.",
                [](CaseSpec& c) -> std::string& { return c.domain.top; });
    s.addChoice("domain", "right", {"wall", "free_slip", "pressure", "periodic"},
                "Right boundary of the fluid.",
                [](CaseSpec& c) -> std::string& { return c.domain.right; });
    s.addInteger("domain", "absorbing_layer_nodes", "-", 0, 100000,
                 "Thickness in lattice nodes of the sponge layer inside each pressure side, which "
                 "absorbs sound instead of reflecting it (column scenes; 0: none).",
                 [](CaseSpec& c) -> int& { return c.domain.absorbing_layer_nodes; });
    s.addReal("domain", "absorbing_layer_strength", "-", 0, 1,
              "Relaxation per fluid step toward rest at the sponge layer's outer edge; it rises "
              "from 0 at the inner edge as the square of the depth.",
              [](CaseSpec& c) -> double& { return c.domain.absorbing_layer_strength; });
}

void declareFluid(CaseSchema& s) {
    s.addBool("fluid", "enabled", "Submerged (true) or dry (false: no lattice is allocated).",
              [](CaseSpec& c) -> bool& { return c.fluid.enabled; });
    s.addReal("fluid", "density_kg_m3", "kg/m^3", 1, 1e5, "Fluid density.",
              [](CaseSpec& c) -> double& { return c.fluid.density_kg_m3; });
    s.addReal("fluid", "viscosity_m2_s", "m^2/s", 1e-9, 10, "Kinematic viscosity (water: 1e-6).",
              [](CaseSpec& c) -> double& { return c.fluid.viscosity_m2_s; });
    s.addReal("fluid", "resolution", "-", 1, 100,
              "Lattice nodes across the smallest grain, d_min / h (the paper: 10).",
              [](CaseSpec& c) -> double& { return c.fluid.resolution; });
    s.addReal("fluid", "tau", "-", 0, 5,
              "Relaxation time; 0 derives it from target_mach (the paper: 0.506).",
              [](CaseSpec& c) -> double& { return c.fluid.tau; });
    s.addReal("fluid", "target_mach", "-", 0.001, 0.5,
              "Lattice Mach number of the expected peak velocity, used when tau = 0.",
              [](CaseSpec& c) -> double& { return c.fluid.target_mach; });
    s.addChoice("fluid", "collision", {"bgk", "mrt", "mrt_les"},
                "Collision model: BGK, MRT (Lallemand-Luo) or MRT with Smagorinsky LES.",
                [](CaseSpec& c) -> std::string& { return c.fluid.collision; });
    s.addReal("fluid", "smagorinsky", "-", 0, 1,
              "Smagorinsky constant C in tau* = (tau + sqrt(tau^2 + 18 C^2 sqrt(2Q)/rho))/2.",
              [](CaseSpec& c) -> double& { return c.fluid.smagorinsky; });
    s.addReal("fluid", "s_e", "-", 0, 2, "MRT relaxation rate of the energy moment e.",
              [](CaseSpec& c) -> double& { return c.fluid.s_e; });
    s.addReal("fluid", "s_eps", "-", 0, 2, "MRT relaxation rate of the energy-squared moment.",
              [](CaseSpec& c) -> double& { return c.fluid.s_eps; });
    s.addReal("fluid", "s_q", "-", 0, 2, "MRT relaxation rate of the energy-flux moments q.",
              [](CaseSpec& c) -> double& { return c.fluid.s_q; });
    s.addChoice("fluid", "storage", {"double", "float"},
                "Number format of the stored distributions; arithmetic is double either way. "
                "double: 8 B per value. float: 4 B, holding f_i - w_i (DDF shifting, Lehmann et "
                "al. 2022): half the memory and memory traffic (faster where the kernel is "
                "memory-bound), for a velocity ~1e-7 (relative) off double's.",
                [](CaseSpec& c) -> std::string& { return c.fluid.storage; });
}

void declareFlow(CaseSchema& s) {
    s.addInteger("flow", "nodes", "-", 4, 100000,
                 "Lattice nodes across the characteristic length (channel width, vortex "
                 "wavelength, cavity side, cylinder diameter).",
                 [](CaseSpec& c) -> int& { return c.flow.nodes; });
    s.addReal("flow", "reynolds", "-", 0, 1e7,
              "Reynolds number U L / nu of a verification flow (cylinder: U = mean inflow); 0 "
              "with flow.tau above 0.5 imposes tau and lattice_velocity (both stability "
              "numbers) and lets Re follow.",
              [](CaseSpec& c) -> double& { return c.flow.reynolds; });
    s.addReal("flow", "lattice_velocity", "-", 1e-5, 0.3,
              "Peak velocity in lattice units (lid, centreline, amplitude, peak inflow); used "
              "when flow.tau = 0 or flow.reynolds = 0.",
              [](CaseSpec& c) -> double& { return c.flow.lattice_velocity; });
    s.addReal("flow", "tau", "-", 0, 5,
              "Relaxation time of a verification flow; 0 derives it from lattice_velocity and "
              "reynolds, above 0.5 it is imposed and the velocity follows from reynolds (from "
              "lattice_velocity when reynolds = 0).",
              [](CaseSpec& c) -> double& { return c.flow.tau; });
    s.addInteger("flow", "steps", "-", 0, 2000000000,
                 "Lattice steps to run; 0 uses the scene's default (steady state or decay time).",
                 [](CaseSpec& c) -> int& { return c.flow.steps; });
}

void declareGrains(CaseSchema& s) {
    s.addInteger("grains", "count", "-", 0, 1e7, "Number of discs in the column.",
                 [](CaseSpec& c) -> int& { return c.grains.count; });
    s.addReal("grains", "d_min_m", "m", 1e-6, 1, "Smallest disc diameter.",
              [](CaseSpec& c) -> double& { return c.grains.d_min_m; });
    s.addReal("grains", "size_ratio", "-", 1, 10, "d_max / d_min; diameters uniform in between.",
              [](CaseSpec& c) -> double& { return c.grains.size_ratio; });
    s.addReal("grains", "density_kg_m3", "kg/m^3", 1, 1e5, "Grain density.",
              [](CaseSpec& c) -> double& { return c.grains.density_kg_m3; });
    s.addReal("grains", "packing", "-", 0.5, 0.9,
              "Target packing fraction of the column (dense 0.83, loose 0.79).",
              [](CaseSpec& c) -> double& { return c.grains.packing; });
    s.addReal("grains", "aspect_ratio", "-", 0.1, 10, "Column aspect ratio a = H_i / L_i.",
              [](CaseSpec& c) -> double& { return c.grains.aspect_ratio; });
    s.addReal("grains", "friction_deg", "deg", 0, 89, "Grain-grain friction angle.",
              [](CaseSpec& c) -> double& { return c.grains.friction_deg; });
    s.addReal("grains", "wall_friction", "-", 0, 10, "Grain-wall friction coefficient.",
              [](CaseSpec& c) -> double& { return c.grains.wall_friction; });
    s.addReal("grains", "rolling_resistance", "-", 0, 1, "Rolling resistance coefficient.",
              [](CaseSpec& c) -> double& { return c.grains.rolling_resistance; });
    s.addReal("grains", "wall_rolling_resistance", "-", 0, 1,
              "Rolling resistance of disc-wall contacts, the paper's frictional floor: rolling "
              "torque limited to mu_r R F_n. A disc alone on a slope theta comes to rest when it "
              "exceeds tan(theta); 0.2 is above tan(7.5 deg) = 0.13.",
              [](CaseSpec& c) -> double& { return c.grains.wall_rolling_resistance; });
    s.addBool("grains", "buoyancy",
              "Submerged grains feel the buoyancy-reduced gravity (1 - rho_f / rho_s) g, the "
              "paper's model (the fluid carries no body force, so its pressure is the excess "
              "pore pressure); false: the full g, as the reference's published code does.",
              [](CaseSpec& c) -> bool& { return c.grains.buoyancy; });
    s.addBool("grains", "contact_torque",
              "Contacts turn the discs (tangential force times radius, rolling resistance); "
              "false: they push the centres only, as in the reference's published code.",
              [](CaseSpec& c) -> bool& { return c.grains.contact_torque; });
    s.addReal("grains", "normal_stiffness_n_m", "N/m", 1, 1e12,
              "Normal contact stiffness k_n per unit thickness.",
              [](CaseSpec& c) -> double& { return c.grains.normal_stiffness_n_m; });
    s.addReal("grains", "tangential_stiffness_n_m", "N/m", 0, 1e12,
              "Tangential contact stiffness k_t per unit thickness.",
              [](CaseSpec& c) -> double& { return c.grains.tangential_stiffness_n_m; });
    s.addReal("grains", "restitution", "-", 0.01, 1,
              "Normal coefficient of restitution; sets the contact damping.",
              [](CaseSpec& c) -> double& { return c.grains.restitution; });
    s.addReal("grains", "dt_safety", "-", 1e-3, 0.3,
              "DEM time step as a fraction of the binary contact duration of the lightest pair.",
              [](CaseSpec& c) -> double& { return c.grains.dt_safety; });
    s.addInteger("grains", "seed", "-", 0, 2147483647, "Seed of the packing generator.",
                 [](CaseSpec& c) -> int& { return c.grains.seed; });
}

void declareCoupling(CaseSchema& s) {
    s.addChoice("coupling", "method", {"bounce_back", "psm"},
                "Fluid-grain coupling: interpolated moving-wall bounce-back or partially "
                "saturated cells (Noble-Torczynski).",
                [](CaseSpec& c) -> std::string& { return c.coupling.method; });
    s.addReal("coupling", "hydro_radius_ratio", "-", 0.5, 1,
              "Hydrodynamic radius r_h / R seen by the fluid only (the paper: 0.9).",
              [](CaseSpec& c) -> double& { return c.coupling.hydro_radius_ratio; });
    s.addChoice("coupling", "psm_weight", {"eps", "nt"},
                "Partially-saturated weighting: B = eps, or the Noble-Torczynski weight.",
                [](CaseSpec& c) -> std::string& { return c.coupling.psm_weight; });
    s.addInteger("coupling", "substeps", "-", 0, 10000,
                 "DEM steps per fluid step; 0 = floor(dt / dt_DEM) + 1.",
                 [](CaseSpec& c) -> int& { return c.coupling.substeps; });
}

void declareRun(CaseSchema& s) {
    s.addReal("run", "end_tc", "tau_c", 0, 1e4,
              "End time in units of tau_c = sqrt(H_i / g) (the paper: about 16).",
              [](CaseSpec& c) -> double& { return c.run.end_tc; });
    s.addReal("run", "output_interval_tc", "tau_c", 1e-4, 1e4, "Time between outputs.",
              [](CaseSpec& c) -> double& { return c.run.output_interval_tc; });
    s.addInteger("run", "threads", "-", 0, 1024, "OpenMP threads; 0 uses every core.",
                 [](CaseSpec& c) -> int& { return c.run.threads; });
    s.addReal(
        "run", "gate_release_tc", "tau_c", 0, 1e4,
        "Column collapse: the gate holds the column until this time (0: it opens at the start).",
        [](CaseSpec& c) -> double& { return c.run.gate_release_tc; });
}

void declareOutput(CaseSchema& s) {
    s.addBool("output", "vtk", "Write VTU/VTI/PVD series for ParaView.",
              [](CaseSpec& c) -> bool& { return c.output.vtk; });
    s.addInteger("output", "vtk_every", "-", 1, 1e6, "Write VTK files every this many outputs.",
                 [](CaseSpec& c) -> int& { return c.output.vtk_every; });
    s.addInteger("output", "fluid_downsample", "-", 1, 64,
                 "Keep every n-th fluid node in snapshots and VTI files.",
                 [](CaseSpec& c) -> int& { return c.output.fluid_downsample; });
    s.addReal("output", "checkpoint_interval_tc", "tau_c", 0, 1e4,
              "Time between checkpoints; 0 writes one at the end only.",
              [](CaseSpec& c) -> double& { return c.output.checkpoint_interval_tc; });
}

} // namespace

void declareCaseKeys(CaseSchema& schema) {
    declareTopLevel(schema);
    declareDomain(schema);
    declareFluid(schema);
    declareFlow(schema);
    declareGrains(schema);
    declareCoupling(schema);
    declareRun(schema);
    declareOutput(schema);
}

} // namespace lbdem::solver
