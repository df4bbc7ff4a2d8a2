// Shared set-ups of the coupling tests: a periodic MRT box and coupling parameters in lattice
// units.
#pragma once

#include "solver/coupling/Coupling.h"
#include "solver/lattice/Lattice.h"

namespace lbdem::solver::test {

inline constexpr double kPi = 3.14159265358979323846;

/// A square n x n lattice, periodic on every side, MRT at tau = 0.8.
inline lattice::LatticeSetup periodicBox(int n) {
    lattice::LatticeSetup s;
    s.nx = s.ny = n;
    s.left.type = s.right.type = s.bottom.type = s.top.type = lattice::SideType::Periodic;
    s.collision.model = lattice::CollisionModel::Mrt;
    s.collision.tau = 0.8;
    return s;
}

/// Coupling parameters in lattice units (h = dt = 1), r_h = R.
inline coupling::CouplingParams latticeUnits(coupling::CouplingMethod method) {
    coupling::CouplingParams p;
    p.method = method;
    p.hydro_radius_ratio = 1.0;
    return p;
}

} // namespace lbdem::solver::test
