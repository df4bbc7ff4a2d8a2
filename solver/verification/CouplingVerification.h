// Verification of the fluid-grain coupling: settling disc, Gebart array, disc in shear,
// permeability.
#pragma once

#include "solver/core/Real.h"
#include "solver/coupling/Coupling.h"
#include "solver/verification/Verification.h"

#include <string>
#include <vector>

namespace lbdem::solver {

/// Result of one coupled scene run.
struct CouplingRun {
    double value = 0;    ///< the measured quantity (see each scene)
    double wall_s = 0;   ///< wall time of the run
    long long steps = 0; ///< fluid steps run
    bool finite = true;  ///< no NaN seen
};

/// Wachs (2009) disc settling in a closed channel of width 4 d (d = 1 m, rho_s/rho_f = 1.5,
/// g = 10 m/s^2, nu = 0.008088 m^2/s); value = terminal Reynolds number |v| d / nu, the mean
/// over the last third of the fall. `nodes` lattice nodes per diameter.
CouplingRun settlingDisc(coupling::CouplingMethod method, int nodes);

/// Square periodic array of fixed cylinders at solid fraction `fraction`, unit cell `cell`
/// nodes, body-force driven Stokes flow; value = K / R^2 from Darcy's law (K = nu U / g).
CouplingRun gebartSquare(coupling::CouplingMethod method, int cell, double fraction = 0.5);

/// A free disc of `nodes` nodes per diameter in plane Couette flow between walls `channel` d
/// apart (periodic, as long), Re_p = gamma R^2 / nu = 0.1; value = omega / (-gamma / 2).
CouplingRun discShear(coupling::CouplingMethod method, int nodes, int channel = 16);

/// One permeability point of a fixed random disc packing.
struct PermeabilityPoint {
    double ratio = 0;        ///< r_h / R
    double porosity = 0;     ///< quasi-porosity 1 - (area of hydrodynamic discs) / (box area)
    double k_over_d2 = 0;    ///< K / d_mean^2
    double ck_spheres = 0;   ///< Carman-Kozeny for spheres, n^3 / (180 (1 - n)^2)
    double ck_cylinders = 0; ///< Carman-Kozeny for cylinders, n^3 / (80 (1 - n)^2)
    double wall_s = 0;
};

/// Seeded random non-overlapping polydisperse packing (d in [d_min, 1.8 d_min], d_min = `nodes`
/// lattice nodes) in a periodic square box of `box` d_min; body-force-driven flow for each ratio.
std::vector<PermeabilityPoint> permeabilitySweep(coupling::CouplingMethod method, int nodes,
                                                 int box, const std::vector<double>& ratios);

/// Write a sweep as CSV: method, ratio, porosity, k_over_d2, ck_spheres, ck_cylinders, wall_s.
void writePermeabilityCsv(const std::string& path, const std::vector<std::string>& methods,
                          const std::vector<std::vector<PermeabilityPoint>>& sweeps);

} // namespace lbdem::solver
