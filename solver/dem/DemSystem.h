// A system of discs and wall segments advanced by velocity Verlet with a spring-dashpot contact
// law.
#pragma once

#include "solver/core/Real.h"
#include "solver/core/Vec2.h"
#include "solver/dem/ContactLaw.h"
#include "solver/dem/NeighbourGrid.h"
#include "solver/dem/Particles.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lbdem::solver::dem {

/// A straight wall segment from a to b; discs touch it on either side (and at its ends).
struct Wall {
    Vec2 a = Vec2::Zero(), b = Vec2::Zero();
    bool active = true; ///< inactive walls (an opened gate) exert nothing
};

/// A candidate pair (i, j > i) with its contact history; fn, ft are zero when not touching.
struct PairSlot {
    std::int32_t j = 0;
    Real ut = 0;   ///< tangential spring elongation [m]
    Real ur = 0;   ///< rolling spring rotation [rad]
    Real gn = 0;   ///< normal dashpot coefficient of this pair [kg/s per m]
    Real gt = 0;   ///< tangential dashpot coefficient [kg/s per m]
    Real reff = 0; ///< R_i R_j / (R_i + R_j) [m]
    Real fn = 0;   ///< normal force of the last evaluation, repulsive positive [N/m]
    Real ft = 0;   ///< tangential force on j along t = (-n_y, n_x) [N/m]
};

/// What one pair's contact of the last evaluation does to its two discs (zero when not touching).
struct PairLoad {
    Real fx = 0, fy = 0; ///< force on j; i feels the opposite [N/m]
    Real ti = 0, tj = 0; ///< torques on i and on j [N]
};

/// A candidate disc-wall contact with its history and last contact point.
struct WallSlot {
    std::int32_t i = 0, wall = 0;
    Real ut = 0, ur = 0, gn = 0, gt = 0;
    Real fn = 0, ft = 0;
    Real fx = 0, fy = 0, torque = 0; ///< force and torque on the disc of the last evaluation
    Real px = 0, py = 0;             ///< closest point on the wall [m]
};

/// One touching contact for reports and snapshots (j = -1: a wall, point in px, py).
struct ContactForce {
    std::int32_t i = 0, j = 0;
    Real fn = 0, ft = 0;
    Real px = 0, py = 0;
};

/// Contact history of one touching pair, enough to resume a run bit for bit.
/// For wall contacts j is the wall index and is_wall is true.
struct ContactHistory {
    std::int32_t i = 0, j = 0;
    bool is_wall = false;
    Real ut = 0, ur = 0;
};

/// Discs, walls and contacts. Contact law (per unit thickness, overlap delta = R_i + R_j - d):
/// F_n = k_n delta - gamma_n v_n, gamma_n from the restitution coefficient; the contact ends when
/// the overlap returns to zero (F_n is not clipped, so it may be briefly tensile at separation).
/// Tangential: spring k_t on the accumulated slip plus dashpot, capped at mu max(F_n, 0).
/// Rolling: spring k_r = k_t R_eff^2 on the relative rotation, torque capped at mu_r R_eff F_n.
/// Each contact's force is evaluated once into its own slot (in parallel); each disc then sums
/// its slots in a fixed order, so a run gives the same bits on any number of threads.
class DemSystem {
public:
    /// An empty system with the given contact law; skin is the neighbour-list margin [m].
    explicit DemSystem(const Material& material = {}, Real skin = 0);

    /// Append a disc (before or between steps); its mass follows from the material density.
    std::size_t addDisc(Real x, Real y, Real radius);
    /// Append a wall segment and return its index.
    std::size_t addWall(const Vec2& a, const Vec2& b);
    /// Switch a wall on or off (the gate of a column is switched off at t = 0).
    void setWallActive(std::size_t wall, bool active);
    /// Reserve room for n discs so that no step allocates.
    void reserve(std::size_t n);

    /// Body acceleration applied to every disc (tilted and buoyancy-reduced gravity) [m/s^2].
    void setGravity(const Vec2& g) { m_gravity = g; }
    const Vec2& gravity() const { return m_gravity; }
    /// Replace the contact law (dashpots are re-derived at the next neighbour rebuild).
    void setMaterial(const Material& material);
    const Material& material() const { return m_material; }
    /// OpenMP threads for the kernels (0 = the OpenMP default).
    /// Results do not depend on it: every force sum is taken in a fixed order.
    void setThreads(int threads) { m_threads = threads; }

    /// Advance one velocity-Verlet step of length dt; forces on entry must be those of the
    /// current state (they are after any step; call computeForces() after editing the state).
    void step(Real dt);
    /// Advance substeps steps of dt / substeps with the external loads held fixed (coupling).
    void advance(Real dt, int substeps);
    /// Evaluate contact, body and external forces for the current state (used after edits).
    void computeForces();

    /// The discs; after editing positions call invalidateNeighbours() and computeForces().
    Particles& particles() { return m_p; }
    const Particles& particles() const { return m_p; }
    const std::vector<Wall>& walls() const { return m_walls; }
    /// Force a neighbour-list rebuild before the next force evaluation.
    void invalidateNeighbours() { m_rebuild = true; }

    Real time() const { return m_time; }
    long long stepCount() const { return m_steps; }
    /// Set the clock (checkpoint restore).
    void setClock(Real time, long long steps) {
        m_time = time;
        m_steps = steps;
    }

    /// Touching contacts with force magnitudes (allocates: call between steps).
    std::vector<ContactForce> contacts() const;
    /// History of every touching contact (checkpoint).
    std::vector<ContactHistory> contactHistory() const;
    /// Restore contact history (checkpoint); it is merged into the neighbour list on rebuild.
    void restoreContactHistory(const std::vector<ContactHistory>& history);

    /// Translational plus rotational kinetic energy [J/m].
    Real kineticEnergy() const;
    /// Largest disc speed [m/s].
    Real maxSpeed() const;
    /// Neighbour-list rebuilds so far (diagnostics, benchmarks).
    long long rebuilds() const { return m_rebuildCount; }

    /// Reorder discs cell by cell for memory locality; returns old index of each new slot.
    /// Contact history follows the discs. Indices held by callers become invalid.
    std::vector<std::int32_t> sortSpatially();

private:
    void rebuildNeighbours();
    void mergeHistory();
    void buildWallSlots();
    void contactKernel(Real dt, int threads);
    void buildIncoming();
    void finishForces(Real halfDt, bool kick);
    int threadCount() const;
    void resizePredicted();

    Material m_material;
    Real m_skin = 0;
    Real m_kt = 0; ///< k_t as used by the slots of the current neighbour list
    Particles m_p;
    std::vector<Wall> m_walls;
    Vec2 m_gravity = Vec2::Zero();

    NeighbourGrid m_grid;
    PairRows m_rows;                       ///< current candidate pairs
    std::vector<PairSlot> m_slots;         ///< one per candidate pair, parallel to m_rows.cols
    std::vector<PairLoad> m_loads;         ///< parallel to m_slots, compact for the gather
    std::vector<std::uint32_t> m_oldStart; ///< previous rows, for carrying history over
    std::vector<PairSlot> m_oldSlots;
    std::vector<WallSlot> m_wallSlots, m_oldWallSlots; ///< sorted by (disc, wall)
    std::vector<std::uint32_t> m_wallStart; ///< wall slots of disc i: [m_wallStart[i], [i + 1])
    std::vector<Real> m_refX, m_refY;       ///< positions at the last rebuild
    std::vector<Real> m_vx, m_vy, m_w;      ///< velocities predicted at the end of the step
    std::vector<std::uint32_t>
        m_inStart; ///< slots with partner j: m_inSlots[m_inStart[j] .. [j + 1])
    std::vector<std::uint32_t> m_inSlots; ///< slot indices grouped by partner j, in increasing i
    bool m_rebuild = true;
    bool m_haveOld = false;
    bool m_restorePending = false; ///< m_old* hold restored history to merge
    long long m_rebuildCount = 0;
    int m_threads = 0;
    Real m_time = 0;
    long long m_steps = 0;
};

} // namespace lbdem::solver::dem
