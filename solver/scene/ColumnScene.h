// The granular column-collapse scene: a seeded column against the left wall, released at t = 0.
#pragma once

#include "solver/core/Vec2.h"
#include "solver/dem/DemSystem.h"
#include "solver/dem/Packing.h"
#include "solver/scene/CaseSpec.h"
#include "solver/scene/Plan.h"
#include "solver/scene/Snapshot.h"

#include <cstddef>

namespace lbdem::solver {

/// The contact law of a case's grains (friction angle converted to tan).
dem::Material grainMaterial(const GrainSpec& grains);

/// Acceleration on the grains: g (sin theta, -cos theta) with +x downslope, times the buoyancy
/// factor (1 - rho_f / rho_s) when the case is submerged (docs/design.md §5: gravity acts on grains
/// only).
Vec2 grainGravity(const CaseSpec& spec);

/// The packing request of a case's column (grains section; gravity of the domain).
dem::PackingRequest packingRequest(const CaseSpec& spec);

/// Column collapse on a slope: a packing of width L_i from the generator rests on the floor
/// against the left wall, held by a gate at x = L_i that is removed at t = 0 (or at
/// run.gate_release_tc). Walls: floor y = 0 and left wall x = 0 over the domain, a right wall at
/// the domain width. Dry cases allocate no fluid; submerged ones add buoyancy and take hydrodynamic
/// loads through the particles' external force and torque arrays (held fixed across advance()).
class ColumnScene {
public:
    /// Build the column of spec (packing from the cache when present); uses plan.dem_dt_s.
    /// Throws InputError when the column does not fit the domain, SimulationError when the
    /// packing target cannot be reached.
    ColumnScene(const CaseSpec& spec, const Plan& plan, const dem::PackingOptions& options = {});
    /// Build the scene around a given column (e.g. one poured without a target fraction);
    /// the packing must rest on y = 0 between x = 0 and its width.
    ColumnScene(const CaseSpec& spec, const Plan& plan, dem::Packing packing);

    /// Advance one DEM step of the planned length; throws SimulationError naming the DEM when
    /// the grains have become unstable.
    void step();
    /// Advance dt in substeps equal steps, external loads held fixed (the fluid-coupling step);
    /// throws SimulationError naming the DEM when the grains have become unstable.
    void advance(double dt, int substeps);

    double time() const { return m_system.time(); }
    long long stepIndex() const { return m_system.stepCount(); }
    /// The DEM step of the plan [s].
    double demTimeStep() const { return m_dt; }

    dem::DemSystem& system() { return m_system; }
    const dem::DemSystem& system() const { return m_system; }
    const dem::Packing& packing() const { return m_packing; }
    /// Initial column width L_i (the gate position) and equivalent height H_i [m].
    double initialWidth() const { return m_packing.width; }
    double initialHeight() const { return m_packing.height; }
    bool submerged() const { return m_submerged; }
    /// How long the column settled under the run's gravity before t = 0 [s] (plan and logs).
    double settleTime() const { return m_settleTime; }
    /// Index of the gate among the walls (inactive from run.gate_release_tc on, at once by
    /// default).
    std::size_t gateWall() const { return m_gate; }

    /// Fill the grains, contacts and walls of a snapshot (and step, time, domain, slope).
    void fillSnapshot(Snapshot& snapshot) const;

private:
    void build(const CaseSpec& spec);
    /// Let the column come to rest under the run's gravity against the gate, then start the clock.
    void settleBeforeRelease();
    /// Switch the gate off once the clock reaches the release time (forces follow the new walls).
    void releaseGateWhenDue();

    dem::Packing m_packing;
    dem::DemSystem m_system;
    double m_dt = 0;
    bool m_submerged = false;
    std::size_t m_gate = 0;
    double m_gateReleaseS = 0; ///< the gate opens at this time [s]
    double m_settleTime = 0;   ///< how long the column settled before t = 0 [s]
};

/// Copy the discs, touching contacts and active walls of a DEM system into a snapshot
/// (hydro_fx/hydro_fy from the external loads when withHydro). Pair contacts also carry their
/// contact point in wx, wy.
void fillSnapshotGrains(const dem::DemSystem& system, bool withHydro, Snapshot& snapshot);

} // namespace lbdem::solver
