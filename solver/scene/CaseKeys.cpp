// Every case key, declared once: its field, default, unit, range and meaning. Each declaration
// reads "key, field, default, unit, min, max, doc".
#include "solver/scene/CaseKeys.h"

#include "solver/lattice/AbsorbingLayer.h"
#include "solver/scene/CaseSchema.h"

namespace lbdem::solver {

namespace {

using lattice::SideType;

// One key a line, as a table: the lines are long where the meaning takes a long sentence.
// clang-format off

void declareTopLevel(SectionKeys<CaseSpec> s) {
    s.integer("schema", &CaseSpec::schema, 1, "-", 1, 1, "Case-file schema version; this build reads 1.");
    s.text("name", &CaseSpec::name, "default", "Case name; results go to a folder of this name.");
    s.choice("scene", &CaseSpec::scene, SceneKind::ColumnCollapse, "Scene builder: the paper's collapse or a verification flow.");
}

void declareDomain(SectionKeys<DomainSpec> s) {
    // The sides a case may choose; Zou-He sides belong to the verification flows.
    const std::vector<SideType> sides{SideType::Wall, SideType::FreeSlip, SideType::Pressure, SideType::Periodic};
    s.real("width_m", &DomainSpec::width_m, 0.2, "m", 1e-4, 100, "Domain extent along the slope (x).");
    s.real("height_m", &DomainSpec::height_m, 0.1, "m", 1e-4, 100, "Domain extent normal to the slope (y).");
    s.real("slope_deg", &DomainSpec::slope_deg, 5.0, "deg", -45, 45, "Slope angle: gravity is tilted to (g sin theta, -g cos theta), +x downslope.");
    s.real("gravity_m_s2", &DomainSpec::gravity_m_s2, 9.81, "m/s^2", 0, 100, "Magnitude of gravity.");
    s.choice("top", &DomainSpec::top, SideType::Pressure, "Top boundary of the fluid.", sides);
    s.choice("right", &DomainSpec::right, SideType::Pressure, "Right boundary of the fluid.", sides);
    s.integer("absorbing_layer_nodes", &DomainSpec::absorbing_layer_nodes, lattice::AbsorbingLayerSetup{}.nodes, "-", 0, 100000, "Thickness in lattice nodes of the sponge layer inside each pressure side, which absorbs sound instead of reflecting it (column scenes; 0: none).");
    s.real("absorbing_layer_strength", &DomainSpec::absorbing_layer_strength, lattice::AbsorbingLayerSetup{}.strength, "-", 0, 1, "Relaxation per fluid step toward rest at the sponge layer's outer edge; it rises from 0 at the inner edge as the square of the depth.");
}

void declareFluid(SectionKeys<FluidSpec> s) {
    s.flag("enabled", &FluidSpec::enabled, true, "Submerged (true) or dry (false: no lattice is allocated).");
    s.real("density_kg_m3", &FluidSpec::density_kg_m3, 1000.0, "kg/m^3", 1, 1e5, "Fluid density.");
    s.real("viscosity_m2_s", &FluidSpec::viscosity_m2_s, 1e-6, "m^2/s", 1e-9, 10, "Kinematic viscosity (water: 1e-6).");
    s.real("resolution", &FluidSpec::resolution, 10.0, "-", 1, 100, "Lattice nodes across the smallest grain, d_min / h (the paper: 10).");
    s.real("tau", &FluidSpec::tau, 0.506, "-", 0, 5, "Relaxation time; 0 derives it from target_mach (the paper: 0.506).");
    s.real("target_mach", &FluidSpec::target_mach, 0.1, "-", 0.001, 0.5, "Lattice Mach number of the expected peak velocity, used when tau = 0.");
    s.choice("collision", &FluidSpec::collision, lattice::CollisionModel::MrtLes, "Collision model: BGK, MRT (Lallemand-Luo) or MRT with Smagorinsky LES.");
    s.real("smagorinsky", &FluidSpec::smagorinsky, 0.17, "-", 0, 1, "Smagorinsky constant C in tau* = (tau + sqrt(tau^2 + 18 C^2 sqrt(2Q)/rho))/2.");
    s.real("s_e", &FluidSpec::s_e, 1.64, "-", 0, 2, "MRT relaxation rate of the energy moment e.");
    s.real("s_eps", &FluidSpec::s_eps, 1.54, "-", 0, 2, "MRT relaxation rate of the energy-squared moment.");
    s.real("s_q", &FluidSpec::s_q, 1.9, "-", 0, 2, "MRT relaxation rate of the energy-flux moments q.");
    s.real("magic_lambda", &FluidSpec::magic_lambda, 0.0, "-", 0, 10, "When above 0, sets s_q so that (tau - 1/2)(1/s_q - 1/2) equals it, whatever tau: 0.1875 (3/16) puts bounce-back walls half-way between nodes, which makes a packing's permeability nearly independent of the resolution (docs/paper.md); 0: s_q as given.");
    s.flag("magic_lambda_links_only", &FluidSpec::magic_lambda_links_only, false, "Column scenes with bounce-back grains: magic_lambda's s_q only at the fluid nodes next to a wall or grain (their energy flux re-relaxed after the bulk collision), s_q elsewhere; false: magic_lambda's s_q everywhere. Near tau = 1/2 that s_q is small and leaves grid-scale noise in the open fluid (docs/studies.md, \"Grid-scale noise\").");
    s.choice("storage", &FluidSpec::storage, lattice::PopulationStorage::Double, "Number format of the stored distributions and of the bulk collision. double: 8 B per value, collided in double. float: 4 B, holding f_i - w_i (DDF shifting, Lehmann et al. 2022), collided in float on those deviations (boundary, obstacle and grain passes stay in double): half the memory and memory traffic, faster where the kernel is memory-bound, for a velocity ~1e-7 (relative) off double's.");
}

void declareFlow(SectionKeys<FlowSpec> s) {
    s.integer("nodes", &FlowSpec::nodes, 32, "-", 4, 100000, "Lattice nodes across the characteristic length (channel width, vortex wavelength, cavity side, cylinder diameter).");
    s.real("reynolds", &FlowSpec::reynolds, 100.0, "-", 0, 1e7, "Reynolds number U L / nu of a verification flow (cylinder: U = mean inflow); 0 with flow.tau above 0.5 imposes tau and lattice_velocity (both stability numbers) and lets Re follow.");
    s.real("lattice_velocity", &FlowSpec::lattice_velocity, 0.05, "-", 1e-5, 0.3, "Peak velocity in lattice units (lid, centreline, amplitude, peak inflow); used when flow.tau = 0 or flow.reynolds = 0.");
    s.real("tau", &FlowSpec::tau, 0.0, "-", 0, 5, "Relaxation time of a verification flow; 0 derives it from lattice_velocity and reynolds, above 0.5 it is imposed and the velocity follows from reynolds (from lattice_velocity when reynolds = 0).");
    s.integer("steps", &FlowSpec::steps, 0, "-", 0, 2000000000, "Lattice steps to run; 0 uses the scene's default (steady state or decay time).");
}

void declareGrains(SectionKeys<GrainSpec> s) {
    s.integer("count", &GrainSpec::count, 1000, "-", 0, 1e7, "Number of discs in the column.");
    s.real("d_min_m", &GrainSpec::d_min_m, 1.2e-3, "m", 1e-6, 1, "Smallest disc diameter.");
    s.real("size_ratio", &GrainSpec::size_ratio, 1.8, "-", 1, 10, "d_max / d_min; diameters uniform in between.");
    s.real("density_kg_m3", &GrainSpec::density_kg_m3, 2650.0, "kg/m^3", 1, 1e5, "Grain density.");
    s.real("packing", &GrainSpec::packing, 0.83, "-", 0.5, 0.9, "Target packing fraction of the column (dense 0.83, loose 0.79).");
    s.real("aspect_ratio", &GrainSpec::aspect_ratio, 0.8, "-", 0.1, 10, "Column aspect ratio a = H_i / L_i.");
    s.real("friction_deg", &GrainSpec::friction_deg, 26.0, "deg", 0, 89, "Grain-grain friction angle.");
    s.real("wall_friction", &GrainSpec::wall_friction, 0.466, "-", 0, 10, "Grain-wall friction coefficient.");
    s.real("rolling_resistance", &GrainSpec::rolling_resistance, 0.01, "-", 0, 1, "Rolling resistance coefficient.");
    s.real("wall_rolling_resistance", &GrainSpec::wall_rolling_resistance, 0.2, "-", 0, 1, "Rolling resistance of disc-wall contacts, the paper's frictional floor: rolling torque limited to mu_r R F_n. A disc alone on a slope theta comes to rest when it exceeds tan(theta); 0.2 is above tan(7.5 deg) = 0.13.");
    s.flag("buoyancy", &GrainSpec::buoyancy, true, "Submerged grains feel the buoyancy-reduced gravity (1 - rho_f / rho_s) g, the paper's model (the fluid carries no body force, so its pressure is the excess pore pressure); false: the full g, as the reference's published code does.");
    s.flag("contact_torque", &GrainSpec::contact_torque, true, "Contacts turn the discs (tangential force times radius, rolling resistance); false: they push the centres only, as in the reference's published code.");
    s.real("normal_stiffness_n_m", &GrainSpec::normal_stiffness_n_m, 1.6e6, "N/m", 1, 1e12, "Normal contact stiffness k_n per unit thickness.");
    s.real("tangential_stiffness_n_m", &GrainSpec::tangential_stiffness_n_m, 1.0e6, "N/m", 0, 1e12, "Tangential contact stiffness k_t per unit thickness.");
    s.real("restitution", &GrainSpec::restitution, 0.5, "-", 0.01, 1, "Normal coefficient of restitution; sets the contact damping.");
    s.real("dt_safety", &GrainSpec::dt_safety, 0.02, "-", 1e-3, 0.3, "DEM time step as a fraction of the binary contact duration of the lightest pair.");
    s.integer("seed", &GrainSpec::seed, 1, "-", 0, 2147483647, "Seed of the packing generator.");
}

void declareCoupling(SectionKeys<CouplingSpec> s) {
    s.choice("method", &CouplingSpec::method, coupling::CouplingMethod::BounceBack, "Fluid-grain coupling: interpolated moving-wall bounce-back or partially saturated cells (Noble-Torczynski).");
    s.real("hydro_radius_ratio", &CouplingSpec::hydro_radius_ratio, 0.9, "-", 0.5, 1, "Hydrodynamic radius r_h / R seen by the fluid only (the paper: 0.9).");
    s.choice("psm_weight", &CouplingSpec::psm_weight, coupling::PsmWeight::Nt, "Partially-saturated weighting: B = eps, or the Noble-Torczynski weight.");
    s.choice("refill", &CouplingSpec::refill, coupling::RefillRule::SurfaceEquilibrium, "Bounce-back: what a node a grain uncovers starts from: the equilibrium at its fluid neighbours' mean density and the grain surface's velocity, or the mean of its fluid neighbours' populations.");
    s.flag("link_mass_correction", &CouplingSpec::link_mass_correction, true, "Bounce-back: each interpolated link's mass beyond halfway bounce-back is taken back from its fluid node's rest population, so that pores sealed by grains keep their mass (docs/coupling-methods.md); false leaves it.");
    s.integer("substeps", &CouplingSpec::substeps, 0, "-", 0, 10000, "DEM steps per fluid step; 0 = floor(dt / dt_DEM) + 1.");
}

void declareRun(SectionKeys<RunSpec> s) {
    s.real("end_tc", &RunSpec::end_tc, 16.0, "tau_c", 0, 1e4, "End time in units of tau_c = sqrt(H_i / g) (the paper: about 16).");
    s.real("output_interval_tc", &RunSpec::output_interval_tc, 0.25, "tau_c", 1e-4, 1e4, "Time between outputs.");
    s.integer("threads", &RunSpec::threads, 0, "-", 0, 1024, "OpenMP threads; 0 uses every core.");
    s.real("gate_release_tc", &RunSpec::gate_release_tc, 0.0, "tau_c", 0, 1e4, "Column collapse: the gate holds the column until this time (0: it opens at the start).");
}

void declareOutput(SectionKeys<OutputSpec> s) {
    s.flag("vtk", &OutputSpec::vtk, true, "Write VTU/VTI/PVD series for ParaView.");
    s.integer("vtk_every", &OutputSpec::vtk_every, 1, "-", 1, 1e6, "Write VTK files every this many outputs.");
    s.integer("fluid_downsample", &OutputSpec::fluid_downsample, 1, "-", 1, 64, "Keep every n-th fluid node in snapshots and VTI files.");
    s.real("checkpoint_interval_tc", &OutputSpec::checkpoint_interval_tc, 1.0, "tau_c", 0, 1e4, "Time between checkpoints; 0 writes one at the end only.");
}

// clang-format on

} // namespace

void declareCaseKeys(CaseSchema& schema) {
    declareTopLevel(SectionKeys<CaseSpec>(schema));
    declareDomain({schema, "domain", &CaseSpec::domain});
    declareFluid({schema, "fluid", &CaseSpec::fluid});
    declareFlow({schema, "flow", &CaseSpec::flow});
    declareGrains({schema, "grains", &CaseSpec::grains});
    declareCoupling({schema, "coupling", &CaseSpec::coupling});
    declareRun({schema, "run", &CaseSpec::run});
    declareOutput({schema, "output", &CaseSpec::output});
}

} // namespace lbdem::solver
