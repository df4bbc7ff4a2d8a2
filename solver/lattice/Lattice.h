// The D2Q9 lattice: distributions, node flags, boundary link lists and the fused time step.
#pragma once

#include "solver/core/HugePageAllocator.h"
#include "solver/core/Real.h"
#include "solver/lattice/Collision.h"
#include "solver/lattice/D2Q9.h"
#include "solver/lattice/PopulationStorage.h"
#include "solver/lattice/SideType.h"

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace lbdem::solver::lattice {

/// One side's condition; Zou–He sides exist on the left and right only.
struct SideCondition {
    SideType type = SideType::Wall;
    Real ux = 0, uy = 0;       ///< wall velocity (Wall) or uniform normal velocity (ZouHeVelocity)
    Real rho = 1;              ///< density of Pressure / ZouHePressure sides
    std::vector<Real> profile; ///< ZouHeVelocity: ux per lattice row (empty: uniform ux)
};

/// Everything the lattice needs at construction, in lattice units.
struct LatticeSetup {
    int nx = 0, ny = 0; ///< fluid nodes across the domain (ghost layers are added)
    SideCondition left, right, bottom, top;
    CollisionParams collision;
    Real fx = 0, fy = 0; ///< uniform body force density (Guo forcing)
    PopulationStorage storage = PopulationStorage::Double; ///< number format of the populations
};

/// Force and torque on one obstacle (momentum exchange), lattice units, about its reference point.
struct ObstacleLoad {
    Real fx = 0, fy = 0, torque = 0;
};

/// D2Q9 lattice with structure-of-arrays storage f[q * cells + cell] (x fastest) in ONE buffer,
/// updated in place by the AA pattern (Bailey et al. 2009): a step from an even step count
/// reads and writes only the node's own nine values (storing f*_i in slot opp(i)); a step from
/// an odd count reads the populations arriving from the neighbours and writes the results back
/// where they came from. Both move 144 bytes per update (72 with float storage) with no
/// write-allocate traffic, in half the memory of a two-lattice scheme. Where a population sits
/// therefore depends on the parity of the step count: postSlot() and inSlot() say where, and
/// population() / setPopulation() are the way in from outside, since a float slot holds
/// f_i - w_i (PopulationStorage); only hot loops (the grain links) address the stored values
/// directly, through storedDoubles() / storedFloats() and postSlotOffset(). Boundary passes write
/// the populations that solid neighbours send into the fluid before the bulk kernel, so the kernel
/// itself has no branches.
class Lattice {
public:
    /// Build the lattice at rest (rho = 1, u = 0) with its ghost layers and wall links.
    explicit Lattice(const LatticeSetup& setup);

    int nx() const { return m_nx; } ///< nodes in x including ghost layers
    int ny() const { return m_ny; } ///< nodes in y including ghost layers
    long long cells() const { return m_cells; }
    int firstFluidX() const { return m_ghostLeft; }   ///< index of the first domain column
    int firstFluidY() const { return m_ghostBottom; } ///< index of the first domain row
    const LatticeSetup& setup() const { return m_setup; }
    PopulationStorage storage() const {
        return m_setup.storage;
    } ///< number format of the populations
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
    template <class Field> void initialise(const Field& field);
    /// Replace the collision parameters (applies from the next step).
    void setCollision(const CollisionParams& params) { m_setup.collision = params; }
    /// Replace the uniform body force density.
    void setBodyForce(Real fx, Real fy) {
        m_setup.fx = fx;
        m_setup.fy = fy;
    }

    /// One fused stream-collide step: boundary links, bulk kernel, Zou-He nodes, solid reset.
    void step();
    /// Have the bulk kernel sweep row y last (from row y + 1 on, wrapping round), so that the rows
    /// up to y are the freshest in cache when the grain coupling comes next. Rows are independent:
    /// any order gives the same populations. Default: the top row (rows swept bottom to top).
    void setLastSweptRow(int y) { m_lastSweptRow = y; }
    long long stepCount() const { return m_step; }
    /// Set the step counter (checkpoint restore; the populations through importStoredValues()).
    void setStepCount(long long step) { m_step = step; }

    /// Slot of the post-collision population f*_dir of `cell` after the last step.
    long long postSlot(long long cell, int dir) const { return postSlotAt(cell, dir, m_step & 1); }
    /// Slot that the next step reads as the population arriving at `cell`
    /// along `dir` (sent from cell - c_dir): boundary passes write solid neighbours' values here.
    long long inSlot(long long cell, int dir) const { return inSlotAt(cell, dir, m_step & 1); }
    /// postSlot() for all kQ directions of one cell at once (one division instead of kQ).
    void postSlots(long long cell, long long slots[kQ]) const;
    /// postSlots() of the node at column i, row j (no division: for loops that walk the grid).
    void postSlots(int i, int j, long long slots[kQ]) const;
    /// postSlot() of the node at column i, row j (no division).
    long long postSlot(int i, int j, int dir) const {
        return m_step & 1 ? kOpposite[dir] * m_cells + index(i, j)
                          : dir * m_cells + neighbour(i, j, dir);
    }
    /// The population of direction `dir` held at `slot` (a postSlot/inSlot index for `dir`).
    Real population(long long slot, int dir) const {
        return m_setup.storage == PopulationStorage::Float
                   ? StoredPopulation<float>::load(m_f32[slot], kW[dir])
                   : m_f64[slot];
    }
    /// Store the population of direction `dir` at `slot`.
    void setPopulation(long long slot, int dir, Real value) {
        if (m_setup.storage == PopulationStorage::Float)
            m_f32[slot] = StoredPopulation<float>::store(value, kW[dir]);
        else
            m_f64[slot] = value;
    }
    /// The stored values in slot order (f_i for double storage, f_i - w_i for float; null for the
    /// other storage), for kernels outside the lattice that address slots themselves.
    double* storedDoubles() { return m_f64.data(); }
    float* storedFloats() { return m_f32.data(); }
    const double* storedDoubles() const { return m_f64.data(); }
    const float* storedFloats() const { return m_f32.data(); }
    /// Node flags (kFluid, kSolid, ...) per cell, for kernels outside the lattice.
    const std::uint8_t* flags() const { return m_flags.data(); }
    /// Offset from postSlot(cell, dir) to cell for every node whose neighbours need no wrapping:
    /// postSlot(cell, dir) = cell + postSlotOffset(dir) at the current parity.
    long long postSlotOffset(int dir) const {
        return m_step & 1 ? kOpposite[dir] * m_cells
                          : dir * m_cells + kCx[dir] + static_cast<long long>(kCy[dir]) * m_nx;
    }
    /// Record, in every following step, the incoming (streamed, pre-collision) populations of
    /// these cells after the boundary passes: partially saturated cells re-collide from them.
    void setRecordedCells(const std::vector<long long>& cells) {
        m_recordedCells.assign(cells.begin(), cells.end());
    }
    /// The incoming populations recorded in the last step, kQ per recorded cell in the given order.
    const std::vector<Real>& recordedIncoming() const { return m_recorded; }

    /// Density of a node (from the current post-collision populations).
    Real density(long long cell) const;
    /// Velocity of a node, u = (sum c_i f_i - F/2) / rho for post-collision populations.
    void velocity(long long cell, Real& ux, Real& uy) const;
    /// Sum of the populations over fluid nodes.
    Real totalMass() const;
    /// Load on obstacle `owner` from the last step.
    const ObstacleLoad& obstacleLoad(int owner) const { return m_loads.at(owner); }
    /// Every population f_i as a double, in slot order (layout per postSlot/inSlot at stepCount()).
    std::vector<double> exportPopulations() const;
    /// Replace every population from exportPopulations()'s layout; throws InputError on a size
    /// mismatch.
    void importPopulations(const std::vector<double>& f);
    /// The stored numbers exactly, as doubles in slot order: f_i for double storage, f_i - w_i for
    /// float (a checkpoint's bit-exact image; f_i itself may round differently on the way back).
    std::vector<double> exportStoredValues() const;
    /// Replace the stored numbers from exportStoredValues() of a lattice with the same storage;
    /// throws InputError on a size mismatch.
    void importStoredValues(const std::vector<double>& values);
    /// Number of boundary links of each kind (copy, pressure, obstacle).
    std::size_t linkCount() const {
        return m_copyLinks.size() + m_pressureLinks.size() + m_obstacleLinks.size();
    }

    static constexpr std::uint8_t kFluid = 0, kSolid = 1, kPressureGhost = 2, kObstacle = 3;

private:
    struct CopyLink {
        long long slot[2], source[2];
        Real add;
    }; // f[slot] = f[source] + add, per parity
    struct PressureLink {
        long long node;
        int dir;
        Real rho;
    }; // dir: into the ghost
    struct ObstacleLink {
        long long node;
        int dir;
        Real q;
        int owner;
        bool interior;
    };
    struct Owner {
        Real cx, cy;
    };

    void buildSides();
    void buildWallLinks();
    void rebuildLinks();
    /// postSlot() when the step count has the given parity (0 even, 1 odd).
    long long postSlotAt(long long cell, int dir, long long parity) const {
        return parity ? kOpposite[dir] * m_cells + cell : dir * m_cells + neighbour(cell, dir);
    }
    /// inSlot() when the step count has the given parity.
    long long inSlotAt(long long cell, int dir, long long parity) const {
        return parity ? kOpposite[dir] * m_cells + neighbour(cell, kOpposite[dir])
                      : dir * m_cells + cell;
    }
    /// The node at cell + c_dir, wrapping around the domain.
    long long neighbour(long long cell, int dir) const {
        return neighbour(static_cast<int>(cell % m_nx), static_cast<int>(cell / m_nx), dir);
    }
    /// The node at (i, j) + c_dir, wrapping around the domain.
    long long neighbour(int i, int j, int dir) const {
        int in = i + kCx[dir], jn = j + kCy[dir];
        in = in < 0 ? in + m_nx : in >= m_nx ? in - m_nx : in;
        jn = jn < 0 ? jn + m_ny : jn >= m_ny ? jn - m_ny : jn;
        return index(in, jn);
    }
    void applyLinks();
    void computeLoads();
    void applyZouHe();
    void recordIncoming();
    template <class C> void runStep(const C& collide);
    void resetSolids();

    LatticeSetup m_setup;
    int m_nx = 0, m_ny = 0, m_ghostLeft = 0, m_ghostBottom = 0;
    Real m_offsetX = 0.5, m_offsetY = 0.5;
    long long m_cells = 0, m_step = 0;
    int m_lastSweptRow = -1;  // -1: the top row
    HugeVector<double> m_f64; // double storage: populations, in place (AA pattern)
    HugeVector<float> m_f32;  // float storage: f_i - w_i, in place; one of the two is empty
    std::vector<long long> m_recordedCells; // cells whose incoming populations each step records
    std::vector<Real> m_recorded;           // kQ per recorded cell
    HugeVector<std::uint8_t> m_flags;
    std::vector<int> m_side; // for ghost nodes: which side (0 L, 1 R, 2 B, 3 T)
    std::vector<CopyLink> m_copyLinks;
    std::vector<PressureLink> m_pressureLinks;
    std::vector<ObstacleLink> m_obstacleLinks;
    std::vector<long long> m_solids;
    std::vector<long long> m_zouHeCells[2]; // left, right
    std::vector<Owner> m_owners;
    std::vector<ObstacleLoad> m_loads;
    // Per owner: link fraction q(x, y, dir) where the link from (x, y) along dir meets the wall.
    std::vector<std::function<Real(Real, Real, int)>> m_shapes;
};

inline void Lattice::postSlots(int i, int j, long long slots[kQ]) const {
    const long long cell = index(i, j);
    if (m_step & 1) {
        for (int q = 0; q < kQ; ++q)
            slots[q] = kOpposite[q] * m_cells + cell;
        return;
    }
    if (i == 0 || j == 0 || i == m_nx - 1 || j == m_ny - 1) { // the neighbour may wrap
        for (int q = 0; q < kQ; ++q)
            slots[q] = q * m_cells + neighbour(i, j, q);
        return;
    }
    for (int q = 0; q < kQ; ++q)
        slots[q] = q * m_cells + cell + kCx[q] + static_cast<long long>(kCy[q]) * m_nx;
}

template <class Field> void Lattice::initialise(const Field& field) {
    for (int j = 0; j < m_ny; ++j)
        for (int i = 0; i < m_nx; ++i) {
            const long long c = index(i, j);
            Real rho = 1, ux = 0, uy = 0;
            if (isFluid(c)) field(nodeX(i), nodeY(j), rho, ux, uy);
            for (int q = 0; q < kQ; ++q)
                setPopulation(postSlot(c, q), q, equilibrium(q, rho, ux, uy));
        }
}

} // namespace lbdem::solver::lattice
