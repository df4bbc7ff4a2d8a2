// The function that runs each verification case, one per case of the registry's table; each
// lives in its module (fluid, DEM, coupling, rest, column permeability).
#pragma once

#include "solver/verification/Verification.h"

#include <vector>

namespace lbdem::solver {

/// `poiseuille`: body-force channel flow against the parabola, and its order of convergence.
std::vector<VerificationResult> verifyPoiseuille(const VerificationOptions& options);

/// `taylor-green`: the decay rate of the vortex, its order, and with LES.
std::vector<VerificationResult> verifyTaylorGreen(const VerificationOptions& options);

/// `cavity-re100`: centreline velocities against Ghia et al. (1982).
std::vector<VerificationResult> verifyCavity(const VerificationOptions& options);

/// `cylinder-2d1`: drag and pressure drop against Schäfer & Turek (1996).
std::vector<VerificationResult> verifyCylinder(const VerificationOptions& options);

/// `stability`: the cavity at tau - 1/2 = 1e-4 (FluidVerificationCases.cpp).
std::vector<VerificationResult> verifyStability(const VerificationOptions& options);

/// `grid-noise`: the cylinder wake at Re = 100 keeps fluid_grid_noise small
/// (GridNoiseVerification.cpp).
std::vector<VerificationResult> verifyGridNoise(const VerificationOptions& options);

/// `restitution`: binary disc-disc and disc-wall collisions reach the target e.
std::vector<VerificationResult> verifyRestitution(const VerificationOptions& options);

/// `incline`: a disc on a slope, frictionless, rolling and slipping.
std::vector<VerificationResult> verifyIncline(const VerificationOptions& options);

/// `packing`: the generator meets the dense and loose targets (DemVerificationPacking.cpp).
std::vector<VerificationResult> packingResults(const VerificationOptions& options);

/// `dry-collapse-scaling`: runout against aspect ratio; empty in the quick run.
std::vector<VerificationResult> dryCollapseScalingResults(const VerificationOptions& options);

/// `settling-disc` with both coupling methods (Wachs 2009).
std::vector<VerificationResult> verifySettlingDisc(const VerificationOptions& options);

/// `gebart-square` with both coupling methods (Gebart 1992).
std::vector<VerificationResult> verifyGebartSquare(const VerificationOptions& options);

/// `disc-shear`: a free disc in simple shear turns at half the vorticity.
std::vector<VerificationResult> verifyDiscShear(const VerificationOptions& options);

/// `permeability`: K of a random packing against r_h / R and Carman-Kozeny.
std::vector<VerificationResult> verifyPermeability(const VerificationOptions& options);

/// `near-contact`: discs at rest in still fluid near each other and the floor feel no force
/// (CouplingRestCases.cpp).
std::vector<VerificationResult> verifyNearContact(const VerificationOptions& options);

/// `column-at-rest`: the held column puts its buoyant weight on the walls.
std::vector<VerificationResult> verifyColumnAtRest(const VerificationOptions& options);

/// `column-permeability` (slow): dense and loose columns, both methods
/// (ColumnPermeabilityCases.cpp).
std::vector<VerificationResult> verifyColumnPermeability(const VerificationOptions& options);

} // namespace lbdem::solver
