// Partially saturated cells (Noble & Torczynski 1998): the coupling method that weights a solid
// collision by each cell's solid fraction.
#pragma once

#include "solver/coupling/Coupling.h"

#include <cstdint>
#include <vector>

namespace lbdem::solver::coupling {

/// The partially saturated cells coupling: every cell a grain overlaps gets its covered area as
/// solid fraction eps, and after the bulk step a collision weighted by B(eps) pushes its fluid
/// toward the grain's motion. Keeps no state between steps. Built by makeCoupling.
class PsmCoupling final : public Coupling {
public:
    /// Couple the lattice and the grains; allocates the per-cell arrays once.
    PsmCoupling(lattice::Lattice& lattice, dem::DemSystem& dem, const CouplingParams& params);

    /// Collide the partly solid cells, then hand their loads to the DEM.
    void collectForces() override;
    /// Cell entries (one per cell and grain overlapping it) of the last mapGrains.
    std::size_t boundaryCount() const override { return m_psm.size(); }
    /// The empty state: nothing carries over from one step to the next.
    CouplingState state() const override { return {}; }
    /// Accept only a state without covered nodes (a bounce-back checkpoint does not fit).
    void restore(const CouplingState& state) override;
    /// Nothing to renumber: the next mapGrains rebuilds every entry.
    void renumberGrains(const std::vector<std::int32_t>&) override { resizeGrains(); }

private:
    struct PsmEntry {
        long long cell;
        std::int32_t grain;
        Real eps, rx, ry;
    };

    /// Solid fraction and weight of every cell a grain overlaps.
    void placeGrains() override;
    void collidePsm();

    std::vector<long long> m_linkStart; // first entry of each touched cell (prefix sums)
    std::vector<Real> m_linkLoad;       // per entry: momentum and torque exchanged
    std::vector<PsmEntry> m_psm;
    std::vector<long long> m_psmCells; // cells touched by the last mapping
};

} // namespace lbdem::solver::coupling
