// Conversions shared by every scene with a lattice: case -> collision parameters, lattice -> SI
// fields.
#pragma once

#include "solver/lattice/Lattice.h"
#include "solver/scene/CaseSpec.h"
#include "solver/scene/Snapshot.h"

#include <vector>

namespace lbdem::solver {

/// The collision model and rates of a case's [fluid] section at relaxation time tau (the bulk's
/// s_q when fluid.magic_lambda_links_only holds).
lattice::CollisionParams collisionOf(const CaseSpec& spec, double tau);

/// Scales from lattice to SI units of one lattice.
struct LatticeScales {
    int nx = 0, ny = 0;      ///< domain nodes (without ghost layers)
    double h_m = 0;          ///< spacing
    double dt_s = 0;         ///< time step
    double rho_kg_m3 = 1000; ///< fluid density
};

/// Copy every downsample-th domain node into out in SI units: velocity, excess pressure
/// (rho - 1) c_s^2 rho_f (h/dt)^2, vorticity by central differences, and the solid fraction
/// (from solidFraction per lattice cell when given, else 1 on solid nodes).
void fillFluidSnapshot(const lattice::Lattice& lattice, const LatticeScales& scales, int downsample,
                       const std::vector<Real>* solidFraction, SnapshotFluid& out);

/// The grid-scale share of the lattice's vorticity (diagnostics/GridNoise.h) from its own
/// velocities: solid are the nodes that are not fluid (walls, obstacles, grains under bounce-back,
/// ghost layers) and, when solidFraction is given, every node a grain covers in part (PSM).
double fluidGridNoise(const lattice::Lattice& lattice, const std::vector<Real>* solidFraction);

} // namespace lbdem::solver
