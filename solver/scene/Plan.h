// The plan of a case: lattice and DEM discretisation, stability numbers and cost estimate.
#pragma once

#include "solver/scene/CaseSpec.h"

#include <cstddef>
#include <string>
#include <vector>

namespace lbdem::solver {

/// Dimensions of the initial granular column, derived from the grain specification.
struct ColumnGeometry {
    double width_m = 0;           ///< L_i
    double height_m = 0;          ///< H_i = a L_i
    double mean_disc_area_m2 = 0; ///< expected area of one disc
    double grain_area_m2 = 0;     ///< total disc area
};

/// Column size that holds count discs at the target packing and aspect ratio.
ColumnGeometry columnGeometry(const GrainSpec& grains);

/// Lattice units and numbers that follow from a CaseSpec (docs/design.md §4).
struct Plan {
    bool has_fluid = false;     ///< false for dry scenes: no lattice is allocated
    bool has_grains = false;    ///< false for pure fluid scenes
    int nx = 0, ny = 0;         ///< lattice nodes
    double h_m = 0;             ///< lattice spacing
    double dt_s = 0;            ///< fluid time step (or DEM step for dry scenes)
    double tau = 0;             ///< BGK relaxation time
    double nu_lattice = 0;      ///< lattice viscosity (tau - 1/2) / 3
    double u_expected_m_s = 0;  ///< the velocity scale the Mach number refers to
    double mach = 0;            ///< u_expected dt / h / c_s
    double sound_speed_m_s = 0; ///< the lattice's sound speed c_s h / dt = h / (sqrt(3) dt)
    double bulk_modulus_pa = 0; ///< the lattice fluid's bulk modulus rho_f c_s^2 (water: 2.2 GPa)
    double dem_dt_s = 0;        ///< DEM time step the run uses (dt_s / substeps when coupled)
    double dem_dt_safe_s = 0;   ///< grains.dt_safety times the shortest contact duration
    double dem_dt_stable_s = 0; ///< stability limit of the explicit DEM integrator (packed grains)
    int substeps = 1;           ///< DEM sub-steps per fluid step
    long long grains = 0;       ///< number of discs
    double tc_s = 0;            ///< tau_c = sqrt(H_i / g); the time unit of the run
    double end_time_s = 0;      ///< physical end time
    long long steps = 0;        ///< fluid (or DEM) steps to the end time
    std::size_t memory_bytes = 0;  ///< estimated solver memory
    std::size_t output_bytes = 0;  ///< peak disk use of the outputs (two checkpoints; upper bound)
    double estimated_run_s = 0;    ///< rough wall time on this class of machine
    ColumnGeometry column;         ///< the initial column (zero when there are no grains)
    int absorbing_layer_nodes = 0; ///< sponge thickness inside the pressure sides (0: none)
    /// Normalised runout Delta L = (L_f - L_i) / L_i at which a front meets the end of the domain
    /// or its absorbing layer (column scenes; 0 otherwise).
    double runout_room = 0;
    std::vector<std::string> notes;    ///< sentences on choices the plan made, and why
    std::vector<std::string> warnings; ///< sentences about stability or accuracy risks
};

/// Set plan's sound speed, bulk modulus and expected Mach number from its h, dt and expected
/// speed and the fluid's density.
void planAcoustics(double fluidDensity, Plan& plan);

/// Compute the plan of a validated case. Throws InputError naming coupling.substeps when the
/// DEM step it gives is beyond the stability limit of the integrator.
Plan makePlan(const CaseSpec& spec);

/// Critical step of the explicit (velocity-Verlet) integrator for a linear spring-dashpot
/// contact: (2 / omega) (sqrt(1 + zeta^2) - zeta), omega = sqrt(k / m_eff), zeta the damping
/// ratio of the restitution (the central-difference bound with viscous damping, Belytschko,
/// Liu & Moran, Nonlinear Finite Elements, 2000, section 6.3).
double stableDemStep(double stiffness, double effectiveMass, double restitution);

/// Duration of a binary linear spring-dashpot contact between discs of effective mass m_eff.
double contactDuration(double stiffness, double effectiveMass, double restitution);

} // namespace lbdem::solver
