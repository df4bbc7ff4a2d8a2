// Diagnostics of the granular mass (DESIGN §6): runout, energies, packing, Froude number, outline.
#pragma once

#include "solver/core/Real.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace lbdem::solver {

/// Read-only view of the discs' state, structure of arrays, SI units (x downslope, y normal).
struct GrainArrays {
    std::size_t count = 0;
    const Real* x = nullptr;
    const Real* y = nullptr;
    const Real* radius = nullptr;
    const Real* vx = nullptr;
    const Real* vy = nullptr;
    const Real* omega = nullptr;
    const Real* mass = nullptr;    ///< per unit thickness [kg/m]
    const Real* inertia = nullptr; ///< per unit thickness [kg m]
};

/// Fixed parameters of the diagnostics of one run.
struct MassDiagnosticsParams {
    double contact_gap_m = 0;    ///< two discs belong to one mass when their gap is below this
    double column_width_m = 0;   ///< L_i, for Delta L = (L_f - L_i) / L_i
    double initial_potential_j_m = 0; ///< E_p0, for E_k / E_p0
    double slope_rad = 0;        ///< slope angle theta
    double gravity_m_s2 = 9.81;  ///< |g|
    double grain_density = 2650; ///< rho_s
    double fluid_density = 0;    ///< rho_w; 0 in a dry scene (no Froude number)
    double bin_width_m = 0;      ///< width of the outline columns (about one mean diameter)
    double front_length_m = 0;   ///< length of the front region behind the front
};

/// What the diagnostics report at one instant.
struct MassDiagnostics {
    double front_x_m = 0;          ///< L_f: farthest point of the main mass from the left wall
    double runout_normalised = 0;  ///< (L_f - L_i) / L_i
    double height_m = 0;           ///< highest point of the main mass above the base
    double kinetic_energy_j_m = 0; ///< translation + rotation, all grains [J/m]
    double ke_over_ep0 = 0;        ///< E_k / E_p0
    double packing_fraction = 0;   ///< grain area / area under the outline (main mass)
    double froude_densimetric = 0; ///< U / sqrt((rho_m / rho_w - 1) g H cos theta); 0 when dry
    double front_velocity_m_s = 0; ///< U: mean downslope velocity of the front region
    double front_thickness_m = 0;  ///< H: thickness of the front region
    std::size_t main_mass_grains = 0; ///< size of the largest connected group of discs
    std::vector<std::pair<double, double>> outline; ///< base -> upper surface -> front -> base
};

/// Potential energy sum m g (y cos theta - x sin theta) of all discs, relative to the slope base
/// through the origin [J/m]; evaluated at t = 0 it is E_p0.
double potentialEnergy(const GrainArrays& grains, double gravity, double slopeRad);

/// Labels of the connected groups of discs (gap below contactGap); label of the largest first.
/// Returns, per disc, true when it belongs to the largest group.
std::vector<bool> largestConnectedGroup(const GrainArrays& grains, double contactGap);

/// All diagnostics of DESIGN §6 that depend on the grains alone.
MassDiagnostics computeMassDiagnostics(const GrainArrays& grains, const MassDiagnosticsParams& params);

} // namespace lbdem::solver
