// Diagnostics of the granular mass (the paper's definitions): runout, energies, packing, Froude
// number (the drawn outline is MassOutline.h).
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
    double contact_gap_m = 0;  ///< two discs touch when their gap is below this
    double bridge_gap_m = 0;   ///< discs closer than this link one mass (at least contact_gap_m)
    double column_width_m = 0; ///< L_i, for Delta L = (L_f - L_i) / L_i
    double initial_potential_j_m = 0; ///< E_p0, for E_k / E_p0
    double slope_rad = 0;             ///< slope angle theta
    double gravity_m_s2 = 9.81;       ///< |g|
    double grain_density = 2650;      ///< rho_s
    double fluid_density = 0;         ///< rho_w; 0 in a dry scene (no Froude number)
    double bin_width_m = 0;           ///< width of the outline columns (about one mean diameter)
    double front_length_m = 0;        ///< length of the front window behind the front
    double flowing_fraction =
        0.1; ///< flowing: downslope speed >= this fraction of the window's fastest
};

/// What the diagnostics report at one instant.
struct MassDiagnostics {
    double front_x_m = 0;          ///< L_f: farthest point of the main mass from the left wall
    double runout_normalised = 0;  ///< (L_f - L_i) / L_i
    double height_m = 0;           ///< highest point of the main mass above the base
    double kinetic_energy_j_m = 0; ///< translation + rotation, all grains [J/m]
    double ke_over_ep0 = 0;        ///< E_k / E_p0
    double packing_fraction = 0;   ///< grain area / area under the column-wise top (main mass)
    double froude_densimetric = 0; ///< U / sqrt((rho_m / rho_w - 1) g H cos theta); 0 when dry
    double front_velocity_m_s = 0; ///< U: mean downslope velocity of the flowing front layer
    double front_thickness_m = 0;  ///< H: mean thickness of the flowing front layer
    double front_packing_fraction =
        0; ///< grain area fraction of the flowing front layer (sets rho_m)
    std::size_t main_mass_grains = 0; ///< discs of the main mass
};

/// Potential energy sum m g h of all discs, h the height of the centre normal to the slope base
/// and g the full gravity, dry and submerged alike (no along-slope term; Kumar's thesis) [J/m].
/// Evaluated at t = 0 it is E_p0.
double potentialEnergy(const GrainArrays& grains, double gravity);

/// The main mass, per disc. Discs closer than bridgeGap link into groups; the main mass is the
/// discs of the largest group that touch (gap below contactGap) another disc of it. A gap of one
/// disc diameter as bridgeGap means a lone disc that leaves (or enters) a chain opens (or fills)
/// a hole no wider than itself and cuts (or joins) nothing else: only that disc enters or leaves
/// the mass, so the front moves by at most about its own diameter.
std::vector<bool> mainMass(const GrainArrays& grains, double contactGap, double bridgeGap);

/// All diagnostics of the paper that depend on the grains alone.
MassDiagnostics computeMassDiagnostics(const GrainArrays& grains,
                                       const MassDiagnosticsParams& params);

} // namespace lbdem::solver
