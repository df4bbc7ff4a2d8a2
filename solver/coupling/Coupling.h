// Resolved fluid-grain coupling: the interface both methods (moving bounce-back, partially
// saturated cells) implement, the geometry and load hand-over they share, and unit conversion.
#pragma once

#include "solver/core/Real.h"
#include "solver/coupling/CouplingMethod.h"
#include "solver/dem/DemSystem.h"
#include "solver/lattice/Lattice.h"

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace lbdem::solver::coupling {

/// Parameters of the coupling. The lattice works in lattice units (h = dt = rho_f = 1); the DEM
/// in SI per unit thickness. Lattice position x_lat = (x - origin_x) / h, i.e. the lattice's
/// domain edge (nodeX = 0) sits at origin_x [m].
struct CouplingParams {
    CouplingMethod method = CouplingMethod::BounceBack;
    Real hydro_radius_ratio = 0.9; ///< r_h / R seen by the fluid (contacts keep R)
    PsmWeight psm_weight = PsmWeight::Nt;
    RefillRule refill = RefillRule::SurfaceEquilibrium; ///< bounce-back: uncovered nodes
    bool link_mass_correction = true; ///< bounce-back: links return their mass excess (see links)
    Real h = 1;                       ///< lattice spacing [m]
    Real dt = 1;                      ///< fluid time step [s]
    Real rho_f = 1;                   ///< fluid density [kg/m^3]
    Real origin_x = 0, origin_y = 0;  ///< SI position of the lattice's domain corner [m]
};

/// Hydrodynamic force and torque on one grain.
struct GrainLoad {
    Real fx = 0, fy = 0, torque = 0;
};

/// Restart state: the nodes covered at the last mapGrains, in order, with their grains, whether
/// covering momentum is being tracked yet, and the raw loads of the last step (fx, fy, torque per
/// grain, lattice units; empty before the first) that the next step averages with (bounce-back;
/// PSM keeps no state and writes an empty one).
struct CouplingState {
    std::vector<long long> cells;
    std::vector<std::int32_t> grains;
    bool initialised = false;
    std::vector<Real> previous_loads;
};

/// Couples a Lattice and a DemSystem; makeCoupling builds the method's implementation. Per fluid
/// step, in this order:
///   coupling.mapGrains();      // grain positions at t -> solid nodes / links or solid fractions
///   lattice.step();
///   coupling.collectForces();  // PSM collision of covered cells; ext loads into the DEM
///   dem.advance(dt, n_s);      // loads held fixed over the n_s sub-steps
/// Hydrodynamic loads: F [N/m] = F_lat rho_f h^3 / dt^2 (a node is a prism of area h^2 and unit
/// thickness, holding rho_f h^2 kg per metre), torque [N m / m] = T_lat rho_f h^4 / dt^2.
/// Gravity acts on the grains only (set the buoyancy-reduced value on the DemSystem), so the
/// lattice pressure is the excess pore pressure. Both objects must outlive the coupling.
class Coupling {
public:
    virtual ~Coupling() = default;
    Coupling(const Coupling&) = delete;
    Coupling& operator=(const Coupling&) = delete;

    /// Map the grains (current DEM positions) onto the lattice: this step's loads start from
    /// zero, the method places the grains (placeGrains) and the bulk kernel is told which row to
    /// sweep last.
    void mapGrains();
    /// Finish the fluid step: the method's own last work and its loads, written into the
    /// particles' ext_fx, ext_fy, ext_torque (handOverLoads).
    virtual void collectForces() = 0;

    /// Hydrodynamic load on grain i of the last step [N/m, N m/m] (raw, before any two-step mean).
    GrainLoad load(std::size_t i) const;
    /// Hydrodynamic load on grain i of the last step, lattice units.
    GrainLoad latticeLoad(std::size_t i) const;
    /// Solid fraction per lattice cell (index lattice.index(i, j)): 0/1 for bounce-back, eps for
    /// PSM.
    const std::vector<Real>& solidFraction() const { return m_solid; }
    /// Append the fluid nodes that the links of the last mapGrains write into (bounce-back; none
    /// under PSM); a node may appear more than once.
    virtual void linkedFluidCells(std::vector<long long>& out) const { (void)out; }
    /// Number of bounce-back links or PSM cell entries of the last mapGrains.
    virtual std::size_t boundaryCount() const = 0;
    /// The parameters the coupling was built with.
    const CouplingParams& params() const { return m_params; }
    /// Lattice force unit rho_f h^3 / dt^2 [N/m per lattice unit].
    Real forceUnit() const {
        return m_params.rho_f * m_params.h * m_params.h * m_params.h / (m_params.dt * m_params.dt);
    }
    /// Lattice torque unit rho_f h^4 / dt^2 [N per lattice unit].
    Real torqueUnit() const { return forceUnit() * m_params.h; }

    /// Restart state (plain data for the checkpoint writer).
    virtual CouplingState state() const = 0;
    /// Restore the state written by state() (same lattice and grain count).
    virtual void restore(const CouplingState& state) = 0;
    /// Follow dem.sortSpatially(): newToOld[k] is the old index of the grain now at k.
    virtual void renumberGrains(const std::vector<std::int32_t>& newToOld) = 0;

protected:
    /// Check the parameters, read the lattice's sides and origin, allocate the per-cell arrays.
    Coupling(lattice::Lattice& lattice, dem::DemSystem& dem, const CouplingParams& params);

    /// Loops over fewer items than this run on one thread: a parallel region costs more than
    /// a few thousand nodes of work (and much more when cores are oversubscribed).
    static constexpr long long kParallelMin = 4096;

    /// Nodes a grain's scan visits, in unwrapped lattice indices (inclusive).
    struct Box {
        int i0 = 0, i1 = -1, j0 = 0, j1 = -1;
    };

    /// The method's part of mapGrains: solid nodes and links, or solid fractions; adds to the
    /// loads (zeroed before).
    virtual void placeGrains() = 0;
    /// Write the SI loads into the particles' ext_fx, ext_fy, ext_torque (and shift fx, fy,
    /// torque by the change so the next DEM step starts from consistent totals). With `previous`
    /// (fx, fy, torque per grain of the step before) the mean of both steps is handed over.
    void handOverLoads(const std::vector<Real>* previous);
    /// Add per-entry loads (fx, fy, torque at 3k, 3k + 1, 3k + 2) to the grains grainOf(k), in
    /// entry order: a sum independent of the thread count that filled them.
    template <class GrainOf>
    void addEntryLoads(const std::vector<Real>& entryLoads, std::size_t entries,
                       const GrainOf& grainOf) {
        for (std::size_t k = 0; k < entries; ++k)
            addLoad(grainOf(k), entryLoads[3 * k], entryLoads[3 * k + 1], entryLoads[3 * k + 2]);
    }
    /// Add one contribution (lattice units) to the loads of grain g.
    void addLoad(std::int32_t g, Real fx, Real fy, Real torque) {
        m_loadX[g] += fx;
        m_loadY[g] += fy;
        m_loadT[g] += torque;
    }
    /// Size the per-grain loads for the current grain count; true when it changed.
    bool resizeGrains();

    long long wrapCell(int iu, int ju) const;
    /// Wrap (i, j) into the lattice across periodic sides; false when it lies outside.
    bool wrapNode(int& i, int& j) const;
    /// Centre and hydrodynamic radius of grain p in lattice units; across a periodic side the
    /// centre is brought within one period of the lattice (a no-op for grains inside it).
    void grainGeometry(std::size_t p, Real& cx, Real& cy, Real& r) const;
    void surfaceVelocity(std::size_t p, Real rx, Real ry, Real& ux, Real& uy) const;
    /// Nodes within r + margin of the centre (cx, cy) along each axis, clipped to the lattice (to
    /// one period along periodic sides): no loop over a box depends on an unclipped grain position.
    Box clippedBox(Real cx, Real cy, Real r, Real margin) const;

    lattice::Lattice& m_lattice;
    dem::DemSystem& m_dem;
    CouplingParams m_params;
    bool m_periodicX = false, m_periodicY = false;
    Real m_originX = 0, m_originY = 0;           // lattice coordinate of node (0, 0)
    std::vector<Real> m_solid;                   // per cell: solid fraction (snapshot)
    std::vector<Real> m_loadX, m_loadY, m_loadT; // lattice units, per grain

private:
    /// The row the bulk kernel should sweep last: just above the highest grain (cache reuse).
    int topGrainRow() const;
};

/// The coupling of params.method on the lattice and the grains (both must outlive it).
std::unique_ptr<Coupling> makeCoupling(lattice::Lattice& lattice, dem::DemSystem& dem,
                                       const CouplingParams& params);

// Inline helpers of the per-node loops (they run once per covered node or link).

inline long long Coupling::wrapCell(int iu, int ju) const {
    return wrapNode(iu, ju) ? m_lattice.index(iu, ju) : -1;
}

inline bool Coupling::wrapNode(int& i, int& j) const {
    const int nx = m_lattice.nx(), ny = m_lattice.ny();
    if (i < 0 || i >= nx) {
        if (!m_periodicX) return false;
        i = ((i % nx) + nx) % nx;
    }
    if (j < 0 || j >= ny) {
        if (!m_periodicY) return false;
        j = ((j % ny) + ny) % ny;
    }
    return true;
}

inline void Coupling::grainGeometry(std::size_t p, Real& cx, Real& cy, Real& r) const {
    const auto& g = m_dem.particles();
    cx = (g.x[p] - m_params.origin_x) / m_params.h;
    cy = (g.y[p] - m_params.origin_y) / m_params.h;
    r = m_params.hydro_radius_ratio * g.radius[p] / m_params.h;
    // A centre more than a period outside (a hostile checkpoint) moves by whole periods.
    const Real nx = m_lattice.nx(), ny = m_lattice.ny();
    if (m_periodicX && !(cx >= -nx && cx <= 2 * nx)) cx -= nx * std::floor(cx / nx);
    if (m_periodicY && !(cy >= -ny && cy <= 2 * ny)) cy -= ny * std::floor(cy / ny);
}

inline void Coupling::surfaceVelocity(std::size_t p, Real rx, Real ry, Real& ux, Real& uy) const {
    // u_p + omega x r in lattice units (u dt / h, omega dt); (rx, ry) from the centre, lattice
    // units.
    const auto& g = m_dem.particles();
    const Real scale = m_params.dt / m_params.h, w = g.omega[p] * m_params.dt;
    ux = g.vx[p] * scale - w * ry;
    uy = g.vy[p] * scale + w * rx;
}

} // namespace lbdem::solver::coupling
