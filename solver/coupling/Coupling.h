// Resolved fluid-grain coupling: moving bounce-back or partially saturated cells, with unit
// conversion.
#pragma once

#include "solver/core/HugePageAllocator.h"
#include "solver/core/Real.h"
#include "solver/coupling/CouplingMethod.h"
#include "solver/dem/DemSystem.h"
#include "solver/lattice/Lattice.h"

#include <cmath>
#include <cstdint>
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
    Real h = 1;                      ///< lattice spacing [m]
    Real dt = 1;                     ///< fluid time step [s]
    Real rho_f = 1;                  ///< fluid density [kg/m^3]
    Real origin_x = 0, origin_y = 0; ///< SI position of the lattice's domain corner [m]
};

/// Hydrodynamic force and torque on one grain.
struct GrainLoad {
    Real fx = 0, fy = 0, torque = 0;
};

/// Restart state: the nodes covered at the last mapGrains, in order, with their grains, whether
/// covering momentum is being tracked yet, and the raw loads of the last step (fx, fy, torque per
/// grain, lattice units; empty before the first) that the next step averages with (bounce-back;
/// PSM keeps no state).
struct CouplingState {
    std::vector<long long> cells;
    std::vector<std::int32_t> grains;
    bool initialised = false;
    std::vector<Real> previous_loads;
};

/// Couples a Lattice and a DemSystem. Per fluid step, in this order:
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
    /// Couple the lattice and the grains; allocates the per-cell arrays once.
    Coupling(lattice::Lattice& lattice, dem::DemSystem& dem, const CouplingParams& params);

    /// Map the grains (current DEM positions) onto the lattice. Bounce-back: refill uncovered
    /// nodes, make covered nodes solid, write the moving-wall links and sum the exchanged
    /// momentum. PSM: solid fraction and weight of every cell a grain overlaps.
    void mapGrains();
    /// Finish the fluid step: PSM collision of the partly solid cells and their loads; then write
    /// the SI loads into the particles' ext_fx, ext_fy, ext_torque (and shift fx, fy, torque by
    /// the change so the next DEM step starts from consistent totals). Bounce-back hands the DEM
    /// the mean of this step's and the last step's load (see collectForces for why).
    void collectForces();

    /// Hydrodynamic load on grain i of the last step [N/m, N m/m] (raw, before the two-step mean).
    GrainLoad load(std::size_t i) const;
    /// Hydrodynamic load on grain i of the last step, lattice units.
    GrainLoad latticeLoad(std::size_t i) const;
    /// Solid fraction per lattice cell (index lattice.index(i, j)): 0/1 for bounce-back, eps for
    /// PSM.
    const std::vector<Real>& solidFraction() const { return m_solid; }
    /// Grain covering each cell at the last mapGrains (-1: none); bounce-back only.
    const HugeVector<std::int32_t>& owners() const { return m_owner; }
    /// Number of bounce-back links or PSM cell entries of the last mapGrains.
    std::size_t boundaryCount() const;
    /// The parameters the coupling was built with.
    const CouplingParams& params() const { return m_params; }
    /// Lattice force unit rho_f h^3 / dt^2 [N/m per lattice unit].
    Real forceUnit() const {
        return m_params.rho_f * m_params.h * m_params.h * m_params.h / (m_params.dt * m_params.dt);
    }
    /// Lattice torque unit rho_f h^4 / dt^2 [N per lattice unit].
    Real torqueUnit() const { return forceUnit() * m_params.h; }

    /// Restart state (plain data for the checkpoint writer).
    CouplingState state() const;
    /// Restore the state written by state() (same lattice and grain count).
    void restore(const CouplingState& state);
    /// Follow dem.sortSpatially(): newToOld[k] is the old index of the grain now at k.
    void renumberGrains(const std::vector<std::int32_t>& newToOld);

private:
    /// Loops over fewer items than this run on one thread: a parallel region costs more than
    /// a few thousand nodes of work (and much more when cores are oversubscribed).
    static constexpr long long kParallelMin = 4096;

    /// A node whose owner changes this step: a grain covers it, or its grain leaves it.
    struct Change {
        long long cell;
        std::int32_t grain;
        int iu, ju;
        bool cover;
    };
    /// Nodes a grain's scan visits, in unwrapped lattice indices (inclusive).
    struct Box {
        int i0 = 0, i1 = -1, j0 = 0, j1 = -1;
    };
    struct PsmEntry {
        long long cell;
        std::int32_t grain;
        Real eps, rx, ry;
    };
    /// A covered node within 1.5 of its grain's surface: reset to the surface motion, source of
    /// the moving-wall links. (i, j) wrapped into the lattice, (sx, sy) from the grain's centre.
    struct SurfaceNode {
        long long cell;
        int i, j;
        std::int32_t grain;
        Real sx, sy;
    };
    /// What the links of one grain need: radius and surface motion, lattice units.
    struct GrainMotion {
        Real r, vx, vy, w;
    };

    long long wrapCell(int iu, int ju) const;
    /// Wrap (i, j) into the lattice across periodic sides; false when it lies outside.
    bool wrapNode(int& i, int& j) const;
    /// Node access of the links of surface nodes near the lattice's edges (wrapping, flags and
    /// owners through the lattice and this coupling); defined with the links.
    struct EdgeAccess;
    /// Centre and hydrodynamic radius of grain p in lattice units; across a periodic side the
    /// centre is brought within one period of the lattice (a no-op for grains inside it).
    void grainGeometry(std::size_t p, Real& cx, Real& cy, Real& r) const;
    void surfaceVelocity(std::size_t p, Real rx, Real ry, Real& ux, Real& uy) const;
    /// Nodes within r + margin of the centre (cx, cy) along each axis, clipped to the lattice (to
    /// one period along periodic sides): no loop over a box depends on an unclipped grain position.
    Box clippedBox(Real cx, Real cy, Real r, Real margin) const;
    Box grainBox(std::size_t p) const;
    /// The row the bulk kernel should sweep last: just above the highest grain (cache reuse).
    int topGrainRow() const;
    void resizeGrains();
    void mapBounceBack();
    void findChanges();
    void findGrainChanges(std::size_t p, std::vector<Change>& out) const;
    /// Owner changes of the nodes iu in [i0, i1] of row (ju, wrapped row j) for grain p.
    void scanRow(std::int32_t p, int ju, int j, Real dy, int i0, int i1, Real cx, Real r,
                 std::vector<Change>& out) const;
    void applyChanges();
    void refillUncovered();
    /// The surface nodes of every grain, sorted row by row.
    void findSurfaceNodes();
    void findGrainSurface(std::size_t p, std::vector<SurfaceNode>& out) const;
    /// Reset every surface node and apply its links, visiting the nodes row by row (memory
    /// order); loads are summed per grain afterwards in grain order. Returns the link count.
    std::size_t linkSurfaceNodes();
    template <class S> std::size_t linkSurfaceNodesStored(S* stored);
    void mapPsm();
    void collidePsm();

    lattice::Lattice& m_lattice;
    dem::DemSystem& m_dem;
    CouplingParams m_params;
    bool m_periodicX = false, m_periodicY = false;
    Real m_originX = 0, m_originY = 0; // lattice coordinate of node (0, 0)
    bool m_initialised = false;

    HugeVector<std::int32_t> m_owner; // per cell: grain covering it, -1 none, -2 just uncovered
    std::vector<Real> m_solid;        // per cell: solid fraction (snapshot)
    std::vector<Box> m_box;           // bounce-back, per grain: the box its nodes lie in
    std::vector<std::vector<Change>> m_threadChanges;      // per thread, grains in order
    std::vector<Change> m_uncovered;                       // nodes left by their grain this step
    std::vector<std::vector<SurfaceNode>> m_threadSurface; // per thread, grains in order
    std::vector<SurfaceNode>
        m_surface; // surface nodes of all grains, row by row (grain order within)
    std::vector<std::int32_t> m_rowStart; // counting sort of m_surface by row
    std::vector<int> m_prefetchSpan;    // per row: first and last column its links' rows may touch
    std::vector<Real> m_surfaceLoad;    // per surface node: (fx, fy, torque) of its links
    std::vector<GrainMotion> m_motion;  // per grain, this step
    std::size_t m_linkCount = 0;        // bounce-back links of the last mapGrains
    std::vector<long long> m_linkStart; // PSM: first entry of each touched cell (prefix sums)
    std::vector<Real> m_linkLoad;       // per PSM entry: momentum and torque exchanged
    std::vector<PsmEntry> m_psm;
    std::vector<long long> m_psmCells;           // cells touched by the last PSM mapping
    std::vector<Real> m_loadX, m_loadY, m_loadT; // lattice units, per grain
    std::vector<Real> m_previousLoad; // bounce-back: (fx, fy, torque) per grain of the step before
};

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
