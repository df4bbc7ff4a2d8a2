// The D2Q9 lattice: distributions, node flags, boundary link lists and the fused time step.
#pragma once

#include "solver/core/Real.h"
#include "solver/lattice/Collision.h"
#include "solver/lattice/D2Q9.h"

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace lbdem::solver::lattice {

/// Boundary condition on one side of the rectangular domain.
enum class SideType {
    Periodic,      ///< wraps to the opposite side (both sides must say so)
    Wall,          ///< half-way bounce-back, optionally moving with (ux, uy)
    FreeSlip,      ///< specular reflection: zero normal flux, no tangential stress
    Pressure,      ///< constant-pressure open boundary (anti-bounce-back at density rho)
    ZouHeVelocity, ///< Zou & He (1997) velocity boundary on the outermost fluid column
    ZouHePressure, ///< Zou & He (1997) pressure boundary on the outermost fluid column
};

/// One side's condition; Zou–He sides exist on the left and right only.
struct SideCondition {
    SideType type = SideType::Wall;
    Real ux = 0, uy = 0;        ///< wall velocity (Wall) or uniform normal velocity (ZouHeVelocity)
    Real rho = 1;               ///< density of Pressure / ZouHePressure sides
    std::vector<Real> profile;  ///< ZouHeVelocity: ux per lattice row (empty: uniform ux)
};

/// Everything the lattice needs at construction, in lattice units.
struct LatticeSetup {
    int nx = 0, ny = 0; ///< fluid nodes across the domain (ghost layers are added)
    SideCondition left, right, bottom, top;
    CollisionParams collision;
    Real fx = 0, fy = 0; ///< uniform body force density (Guo forcing)
};

/// Force and torque on one obstacle (momentum exchange), lattice units, about its reference point.
struct ObstacleLoad {
    Real fx = 0, fy = 0, torque = 0;
};

/// D2Q9 lattice with structure-of-arrays storage f[q * cells + cell] (x fastest) on two buffers.
/// Solid nodes (ghost layers, obstacles) hold the populations that bounce back into the fluid:
/// a boundary pass writes them before the bulk kernel, so the kernel itself has no branches.
class Lattice {
public:
    /// Build the lattice at rest (rho = 1, u = 0) with its ghost layers and wall links.
    explicit Lattice(const LatticeSetup& setup);

    int nx() const { return m_nx; }   ///< nodes in x including ghost layers
    int ny() const { return m_ny; }   ///< nodes in y including ghost layers
    long long cells() const { return m_cells; }
    int firstFluidX() const { return m_ghostLeft; }   ///< index of the first domain column
    int firstFluidY() const { return m_ghostBottom; } ///< index of the first domain row
    const LatticeSetup& setup() const { return m_setup; }
    /// x of node column i in lattice units, measured from the domain's left edge.
    Real nodeX(int i) const { return i - m_ghostLeft + m_offsetX; }
    /// y of node row j in lattice units, measured from the domain's bottom edge.
    Real nodeY(int j) const { return j - m_ghostBottom + m_offsetY; }
    long long index(int i, int j) const { return static_cast<long long>(j) * m_nx + i; }
    bool isFluid(long long cell) const { return m_flags[cell] == kFluid; }

    /// Mark nodes inside the disc solid, with interpolated (Bouzidi) links; returns the owner id.
    int addDisc(Real cx, Real cy, Real radius);
    /// Mark nodes inside the closed polygon solid (Bouzidi links); returns the owner id.
    int addPolygon(const std::vector<std::pair<Real, Real>>& vertices);
    /// Set every fluid node to equilibrium at rho(x, y), u(x, y) (lattice coordinates).
    template <class Field>
    void initialise(const Field& field);
    /// Replace the collision parameters (applies from the next step).
    void setCollision(const CollisionParams& params) { m_setup.collision = params; }
    /// Replace the uniform body force density.
    void setBodyForce(Real fx, Real fy) { m_setup.fx = fx; m_setup.fy = fy; }

    /// One fused stream-collide step: boundary links, bulk kernel, Zou-He nodes, solid reset.
    void step();
    long long stepCount() const { return m_step; }
    /// Set the step counter (checkpoint restore; populations are restored through populations()).
    void setStepCount(long long step) { m_step = step; }

    /// Density of a node (from the current post-collision populations).
    Real density(long long cell) const;
    /// Velocity of a node, u = (sum c_i f_i - F/2) / rho for post-collision populations.
    void velocity(long long cell, Real& ux, Real& uy) const;
    /// Sum of the populations over fluid nodes.
    Real totalMass() const;
    /// Load on obstacle `owner` from the last step.
    const ObstacleLoad& obstacleLoad(int owner) const { return m_loads.at(owner); }
    /// Current populations, f[q * cells + cell].
    const std::vector<Real>& populations() const { return m_f; }
    std::vector<Real>& populations() { return m_f; }
    /// Populations the last step streamed from (post-collision of the step before, boundary slots
    /// filled): what the kernel pulled. Partially saturated cells re-collide from these.
    const std::vector<Real>& previousPopulations() const { return m_g; }
    /// Number of boundary links of each kind (copy, pressure, obstacle).
    std::size_t linkCount() const { return m_copyLinks.size() + m_pressureLinks.size() + m_obstacleLinks.size(); }

    static constexpr std::uint8_t kFluid = 0, kSolid = 1, kPressureGhost = 2, kObstacle = 3;

private:
    struct CopyLink { long long slot, source; Real add; };           // f[slot] = f[source] + add
    struct PressureLink { long long node; int dir; Real rho; };       // dir: into the ghost
    struct ObstacleLink { long long node; int dir; Real q; int owner; bool interior; };
    struct Owner { Real cx, cy; };

    void buildSides();
    void buildWallLinks();
    void rebuildLinks();
    long long neighbour(long long cell, int dir) const;
    void applyLinks();
    void computeLoads();
    template <class C> void runStep(const C& collide);
    void resetSolids(std::vector<Real>& f) const;

    LatticeSetup m_setup;
    int m_nx = 0, m_ny = 0, m_ghostLeft = 0, m_ghostBottom = 0;
    Real m_offsetX = 0.5, m_offsetY = 0.5;
    long long m_cells = 0, m_step = 0;
    std::vector<Real> m_f, m_g;               // current (post-collision) and next populations
    std::vector<Real> m_rowScratch;           // one row of results per thread (bulk kernel)
    std::vector<std::uint8_t> m_flags;
    std::vector<int> m_side;                  // for ghost nodes: which side (0 L, 1 R, 2 B, 3 T)
    std::vector<CopyLink> m_copyLinks;
    std::vector<PressureLink> m_pressureLinks;
    std::vector<ObstacleLink> m_obstacleLinks;
    std::vector<long long> m_solids;
    std::vector<long long> m_zouHeCells[2];   // left, right
    std::vector<Owner> m_owners;
    std::vector<ObstacleLoad> m_loads;
    // Per owner: link fraction q(x, y, dir) where the link from (x, y) along dir meets the wall.
    std::vector<std::function<Real(Real, Real, int)>> m_shapes;
};

template <class Field>
void Lattice::initialise(const Field& field) {
    for (int j = 0; j < m_ny; ++j)
        for (int i = 0; i < m_nx; ++i) {
            const long long c = index(i, j);
            Real rho = 1, ux = 0, uy = 0;
            if (isFluid(c)) field(nodeX(i), nodeY(j), rho, ux, uy);
            for (int q = 0; q < kQ; ++q) m_f[q * m_cells + c] = equilibrium(q, rho, ux, uy);
        }
    m_g = m_f;
}

} // namespace lbdem::solver::lattice
