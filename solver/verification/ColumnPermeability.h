// Permeability of the paper's generated columns: a window of the packing away from the walls,
// grains fixed, pressure-driven flow at the run's fluid settings.
#pragma once

#include "solver/core/Real.h"
#include "solver/coupling/Coupling.h"
#include "solver/dem/Packing.h"
#include "solver/lattice/Collision.h"
#include "solver/scene/CaseSpec.h"
#include "solver/verification/Verification.h"

#include <string>
#include <vector>

namespace lbdem::solver {

/// A fixed disc of a permeability window, lattice units (x from the domain's left edge).
struct WindowDisc {
    Real x = 0, y = 0, r = 0; ///< centre and true radius (the fluid sees hydro_radius_ratio r)
};

/// One pressure-driven flow through fixed discs: pressure (anti-bounce-back) sides left and
/// right, free-slip sides bottom and top (mirror planes: the window continues as its own mirror
/// image, so a cut disc is not a wall the flow rubs along). Lattice units throughout.
struct WindowFlowSetup {
    int nx = 0, ny = 0; ///< domain nodes
    std::vector<WindowDisc> discs;
    lattice::CollisionParams collision;
    coupling::CouplingMethod method = coupling::CouplingMethod::BounceBack;
    Real hydro_radius_ratio = 0.9;
    /// Node columns whose centre lies in [fit_x0, fit_x1] give the flux; the pressure gradient is
    /// the difference of the mean pressures of its end slabs, each `slab` nodes wide, over the
    /// distance of their centres (slabs a whole period wide make a periodic medium exact).
    Real fit_x0 = 0, fit_x1 = 0, slab = 1;
    Real gradient = 1e-8; ///< imposed mean pressure drop per node, (p_in - p_out) / nx
    /// Converged: the change of K still to come, projected from the decay of its last changes,
    /// is below this (relative), at two checks in a row.
    Real tolerance = 1e-3;
    int check_steps = 1000;     ///< fluid steps between two evaluations of K
    long long min_steps = 2000; ///< never stop before this many steps
    long long max_steps = 400000;
};

/// What one window flow gave, lattice units.
struct WindowFlowResult {
    Real k = 0;                ///< permeability K [nodes^2] = nu (rho U) / (-dp/dx)
    Real mass_flux = 0;        ///< superficial mass flux rho U over the fit columns
    Real fitted_gradient = 0;  ///< -dp/dx between the end slabs of the fit part
    Real projected_change = 0; ///< |change of K still to come| at the end (see tolerance)
    Real max_speed = 0;        ///< largest |u| on a fluid node at the end
    Real fluid_fraction = 0;   ///< mean (1 - solid fraction) of the fit columns (lattice porosity)
    long long steps = 0;       ///< fluid steps run
    bool converged = false;    ///< the tolerance was met before max_steps
    bool finite = true;        ///< no NaN seen
};

/// Run the flow of setup to a steady state and measure K by Darcy's law. The pressures are
/// intrinsic averages (fluid nodes only, PSM cells weighted by 1 - s); the mass flux is the mean
/// over the fit columns of sum_j (1 - s) rho u_x / ny. The density starts as the linear
/// profile between the two pressure sides.
WindowFlowResult measureWindowPermeability(const WindowFlowSetup& setup);

/// A rectangular window of a column packing, SI units in the column's frame (floor y = 0, back
/// wall x = 0), with the discs that reach into it.
struct ColumnWindow {
    Real x0 = 0, x1 = 0, y0 = 0, y1 = 0; ///< the window: the fluid sees the discs inside it
    Real fit_x0 = 0, fit_x1 = 0;         ///< the part whose flux and pressure gradient count
    std::vector<Real> x, y, r;           ///< discs whose circle reaches into the window
    Real d_mean = 0, d_max = 0; ///< mean and largest diameter of the discs centred in the fit part
    Real solid_fraction = 0;    ///< true disc area / area, over the fit part
    Real quasi_porosity = 0;    ///< 1 - area of the r_h discs / area, over the fit part
};

/// The window `length` x `height` d_max centred on (L_i / 2, H_i / 2) of a packing; the fit part
/// leaves out `fitMargin` d_max at the inlet and outlet faces. Throws SimulationError when the
/// window comes within 3 d_max of the walls, the floor or H_i.
ColumnWindow columnWindow(const dem::Packing& packing, Real length, Real height, Real fitMargin,
                          Real hydroRatio);

/// Area of the disc (cx, cy, r) inside the rectangle [x0, x1] x [y0, y1] (chord integration).
Real discAreaInRectangle(Real cx, Real cy, Real r, Real x0, Real x1, Real y0, Real y1);

/// One measured point of a column's permeability.
struct ColumnPermeabilityPoint {
    std::string packing;   ///< "dense" or "loose"
    std::string method;    ///< coupling method word
    std::string collision; ///< collision model word
    double s_q = 0;        ///< MRT rate of the energy-flux moments
    double resolution = 0; ///< d_min / h
    int nx = 0, ny = 0;    ///< lattice nodes
    double solid_fraction = 0, quasi_porosity = 0, lattice_porosity = 0;
    double k_over_dmean2 = 0, k_over_dmin2 = 0; ///< K / d_mean^2 and K / d_min^2
    double ck_spheres = 0;                      ///< n^3 / (180 (1 - n)^2) at the quasi-porosity n
    double ck_cylinders = 0;                    ///< n^3 / (80 (1 - n)^2)
    double k_m2 = 0;                            ///< K in m^2
    double reynolds = 0;                        ///< pore Reynolds number (U / n) d_mean / nu
    double max_speed_lattice = 0;
    double projected_change = 0; ///< relative change of K still to come at the end
    long long steps = 0;
    bool converged = false, finite = true;
    double wall_s = 0;
};

/// The window of spec's column (generated by the packing generator, from its cache when present)
/// measured at d_min / h = resolution with spec's tau, collision model and rates, hydrodynamic
/// radius and the given coupling method; `packingName` labels the point.
ColumnPermeabilityPoint columnPermeability(const CaseSpec& spec, const dem::Packing& packing,
                                           const std::string& packingName, double resolution,
                                           coupling::CouplingMethod method,
                                           lattice::CollisionParams collision);

/// Write points as CSV with a header (one row each).
void writeColumnPermeabilityCsv(const std::string& path,
                                const std::vector<ColumnPermeabilityPoint>& points);

} // namespace lbdem::solver
