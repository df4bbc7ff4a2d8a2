// Re-relaxing the MRT energy-flux moments of chosen nodes after the bulk collision.
#pragma once

#include "solver/core/Real.h"
#include "solver/lattice/Lattice.h"

#include <vector>

namespace lbdem::solver::lattice {

/// The factor that turns the energy-flux non-equilibrium q + j left by a collision at rate
/// `bulk` into the one a collision at rate `local` leaves: (1 - local) / (1 - bulk). `bulk` must
/// not be 1 (that collision leaves no non-equilibrium to scale).
Real energyFluxFactor(Real bulk, Real local);

/// Scale the non-equilibrium energy flux q + j of the post-collision populations of `cells` by
/// `factor` (energyFluxFactor), changing no other moment of Lallemand & Luo's basis: as if those
/// nodes had collided with their own s_q. Exact for a lattice without body force (the collision
/// conserves j there); each node once, so the list must hold no cell twice.
void rescaleEnergyFlux(Lattice& lattice, const std::vector<long long>& cells, Real factor);

} // namespace lbdem::solver::lattice
