// The validated description of one case, in SI units, with every default explicit.
#pragma once

#include "solver/core/Real.h"
#include "solver/lattice/AbsorbingLayer.h"

#include <string>

namespace lbdem::solver {

/// Geometry and body forces of the computational domain.
struct DomainSpec {
    double width_m = 0.2;           ///< extent in x (downslope), the paper's 0.2 m
    double height_m = 0.1;          ///< extent in y (normal to the slope), the paper's 0.1 m
    double slope_deg = 5.0;         ///< slope angle theta: gravity tilted to (g sin, -g cos)
    double gravity_m_s2 = 9.81;     ///< magnitude of gravity
    std::string top = "pressure";   ///< top boundary: wall, free_slip, pressure, periodic
    std::string right = "pressure"; ///< right boundary: wall, free_slip, pressure, periodic
    /// Thickness in lattice nodes of the absorbing layer inside every pressure side (0: none).
    int absorbing_layer_nodes = lattice::AbsorbingLayerSetup{}.nodes;
    /// Relaxation per step toward rest at the layer's outer edge, sigma_max in (0, 1].
    double absorbing_layer_strength = lattice::AbsorbingLayerSetup{}.strength;
};

/// The ambient fluid and its lattice-Boltzmann discretisation.
struct FluidSpec {
    bool enabled = true;           ///< submerged (true) or dry (false: no lattice is allocated)
    double density_kg_m3 = 1000.0; ///< water
    double viscosity_m2_s = 1e-6;  ///< kinematic viscosity of water
    double resolution = 10.0;      ///< lattice nodes across the smallest grain, d_min / h
    double tau = 0.506;            ///< BGK relaxation time; 0 derives it from target_mach
    double target_mach = 0.1;      ///< Mach number of the expected peak velocity, used when tau = 0
    std::string collision = "mrt_les"; ///< bgk, mrt or mrt_les
    double smagorinsky = 0.17;         ///< Smagorinsky constant C (the paper's S_c ~ 0.03 ~ C^2)
    double s_e = 1.64;                 ///< MRT rate of the energy moment
    double s_eps = 1.54;               ///< MRT rate of the energy-squared moment
    double s_q = 1.9;                  ///< MRT rate of the energy-flux moments
    std::string storage = "double"; ///< number format of the stored distributions: double or float
};

/// The granular column and the contact law of its discs.
struct GrainSpec {
    int count = 1000;                     ///< number of discs in the column
    double d_min_m = 1.2e-3;              ///< smallest diameter
    double size_ratio = 1.8;              ///< d_max / d_min, diameters uniform in between
    double density_kg_m3 = 2650.0;        ///< grain density
    double packing = 0.83;                ///< target packing fraction (dense 0.83, loose 0.79)
    double aspect_ratio = 0.8;            ///< column height / width, H_i / L_i
    double friction_deg = 26.0;           ///< grain-grain friction angle
    double wall_friction = 0.466;         ///< grain-wall friction coefficient
    double rolling_resistance = 0.01;     ///< rolling resistance coefficient
    double wall_rolling_resistance = 0.2; ///< rolling resistance of disc-wall contacts (the floor)
    bool buoyancy = true;       ///< submerged grains feel (1 - rho_f / rho_s) g; false: full g
    bool contact_torque = true; ///< contacts turn the discs; false: they push centres only
    double normal_stiffness_n_m = 1.6e6;     ///< k_n, per unit thickness
    double tangential_stiffness_n_m = 1.0e6; ///< k_t, per unit thickness
    double restitution = 0.5;                ///< normal coefficient of restitution
    double dt_safety = 0.02; ///< DEM time step as a fraction of the binary contact time
    int seed = 1;            ///< seed of the packing generator
};

/// Fluid-grain coupling.
struct CouplingSpec {
    std::string method =
        "bounce_back"; ///< bounce_back (Bouzidi moving wall) or psm (Noble–Torczynski)
    double hydro_radius_ratio = 0.9; ///< r_h / R seen by the fluid only
    std::string psm_weight = "nt";   ///< psm weighting: eps or nt
    int substeps = 0;                ///< DEM steps per fluid step; 0 = floor(dt/dt_D) + 1
};

/// How long to run and how often to report.
struct RunSpec {
    double end_tc = 16.0;             ///< end time in units of tau_c = sqrt(H_i / g)
    double output_interval_tc = 0.25; ///< time between outputs, in tau_c
    int threads = 0;                  ///< OpenMP threads; 0 = all cores
    double gate_release_tc = 0.0; ///< the column's gate opens at this time, in tau_c (0: at once)
};

/// What each output writes.
struct OutputSpec {
    bool vtk = true;                     ///< write VTU/VTI/PVD series
    int vtk_every = 1;                   ///< write VTK every this many outputs
    int fluid_downsample = 1;            ///< keep every n-th fluid node in snapshots and VTI files
    double checkpoint_interval_tc = 1.0; ///< time between checkpoints, in tau_c
};

/// Verification flows (poiseuille, taylor_green, cavity, cylinder), in lattice terms.
/// The characteristic length L is domain.height_m (channel width, vortex wavelength, cavity
/// side) or, for the cylinder, its diameter domain.height_m / 4.1 (Schäfer & Turek 1996).
struct FlowSpec {
    int nodes = 32;                 ///< lattice nodes across L
    double reynolds = 100.0;        ///< Re = U L / nu (cylinder: U = mean inflow = 2/3 peak)
    double lattice_velocity = 0.05; ///< peak lattice velocity (lid, centreline, amplitude, inflow)
    double tau = 0.0;               ///< > 0.5 imposes tau; the velocity then follows from Re
    int steps = 0;                  ///< lattice steps to run; 0 uses the scene's default
};

/// A whole case: the scene kind plus its sections.
struct CaseSpec {
    int schema = 1;                        ///< case-file schema version
    std::string name = "default";          ///< case name (output folder name)
    std::string scene = "column_collapse"; ///< scene builder to use
    DomainSpec domain;
    FluidSpec fluid;
    FlowSpec flow;
    GrainSpec grains;
    CouplingSpec coupling;
    RunSpec run;
    OutputSpec output;
};

} // namespace lbdem::solver
