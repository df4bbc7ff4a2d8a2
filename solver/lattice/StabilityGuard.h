// Detects a diverging fluid (NaN, a density far from 1, Mach above a limit) and says why.
#pragma once

#include "solver/lattice/Lattice.h"

namespace lbdem::solver::lattice {

/// Checks the lattice every `interval` steps. A run that diverges produces NaN within tens of
/// steps of the first sign, and the Mach limit catches most runs before that, so a check every
/// kDefaultInterval = 50 steps costs ~1/50 of a step's memory traffic and stops a bad run at
/// most 50 steps after it goes wrong. Callers also check before writing any output, so no
/// output is ever written from a bad state: the last written output is the last good state.
class StabilityGuard {
public:
    static constexpr int kDefaultInterval = 50;
    /// Lattice Mach number |u| / c_s above which the run is stopped (0.5: |u| ~ 0.29).
    static constexpr Real kDefaultMaxMach = 0.5;
    /// Densities outside [kMinDensity, kMaxDensity] stop the run: the lattice pressure is
    /// rho c_s^2, so the fluid there is no longer nearly incompressible (a column's pore pressure
    /// is |rho - 1| ~ 0.03).
    static constexpr Real kMinDensity = 0.5;
    static constexpr Real kMaxDensity = 2.0;

    /// A guard for a lattice of spacing h_m [m] (used to state positions in metres).
    explicit StabilityGuard(Real h_m, int interval = kDefaultInterval,
                            Real maxMach = kDefaultMaxMach);

    /// True when the step count is a multiple of the check interval.
    bool due(long long step) const { return step % m_interval == 0; }
    /// Scan every fluid node; throw SimulationError naming step, node, position and likely cause.
    void check(const Lattice& lattice) const;
    int interval() const { return m_interval; }

private:
    Real m_h;
    int m_interval;
    Real m_maxMach;
};

} // namespace lbdem::solver::lattice
