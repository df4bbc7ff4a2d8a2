// The validated description of one case, in SI units, typed.
//
// Each field is one case key. The schema (solver/scene/CaseKeys.cpp) is the one place where a
// key's default, unit, allowed range and meaning live; the fields here are value-initialised
// only, so a default case comes from defaultCase(), which applies the schema's defaults.
#pragma once

#include "solver/coupling/CouplingMethod.h"
#include "solver/lattice/Collision.h"
#include "solver/lattice/PopulationStorage.h"
#include "solver/lattice/SideType.h"
#include "solver/scene/SceneKind.h"

#include <string>

namespace lbdem::solver {

/// Geometry, body force and open sides of the computational domain ([domain]).
struct DomainSpec {
    double width_m{};
    double height_m{};
    double slope_deg{};
    double gravity_m_s2{};
    lattice::SideType top{};
    lattice::SideType right{};
    int absorbing_layer_nodes{};
    double absorbing_layer_strength{};
};

/// The ambient fluid and its lattice-Boltzmann discretisation ([fluid]).
struct FluidSpec {
    bool enabled{};
    double density_kg_m3{};
    double viscosity_m2_s{};
    double resolution{};
    double tau{};
    double target_mach{};
    lattice::CollisionModel collision{};
    double smagorinsky{};
    double s_e{};
    double s_eps{};
    double s_q{};
    double magic_lambda{};
    bool magic_lambda_links_only{};
    lattice::PopulationStorage storage{};
};

/// The granular column and the contact law of its discs ([grains]).
struct GrainSpec {
    int count{};
    double d_min_m{};
    double size_ratio{};
    double density_kg_m3{};
    double packing{};
    double aspect_ratio{};
    double friction_deg{};
    double wall_friction{};
    double rolling_resistance{};
    double wall_rolling_resistance{};
    bool buoyancy{};
    bool contact_torque{};
    double normal_stiffness_n_m{};
    double tangential_stiffness_n_m{};
    double restitution{};
    double dt_safety{};
    int seed{};
};

/// Fluid-grain coupling ([coupling]).
struct CouplingSpec {
    coupling::CouplingMethod method{};
    double hydro_radius_ratio{};
    coupling::PsmWeight psm_weight{};
    int substeps{};
    coupling::RefillRule refill{};
    bool link_mass_correction{};
};

/// How long to run and how often to report ([run]).
struct RunSpec {
    double end_tc{};
    double output_interval_tc{};
    int threads{};
    double gate_release_tc{};
};

/// What each output writes ([output]).
struct OutputSpec {
    bool vtk{};
    int vtk_every{};
    int fluid_downsample{};
    double checkpoint_interval_tc{};
};

/// Verification flows (poiseuille, taylor_green, cavity, cylinder), in lattice terms ([flow]).
struct FlowSpec {
    int nodes{};
    double reynolds{};
    double lattice_velocity{};
    double tau{};
    int steps{};
};

/// A whole case: the top-level keys (schema, name, scene) and its sections.
struct CaseSpec {
    int schema{};
    std::string name;
    SceneKind scene{};
    DomainSpec domain;
    FluidSpec fluid;
    FlowSpec flow;
    GrainSpec grains;
    CouplingSpec coupling;
    RunSpec run;
    OutputSpec output;
};

/// The case with every key at the schema's default (the one way to get a default case).
CaseSpec defaultCase();

} // namespace lbdem::solver
