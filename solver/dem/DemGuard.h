// Run-time and restore-time checks of the grain state: a DEM that blows up, or a checkpoint
// whose grains cannot be, is stopped with a diagnosis that names the DEM.
#pragma once

#include "solver/core/Real.h"
#include "solver/dem/Particles.h"

namespace lbdem::solver::dem {

/// Fraction of its radius a grain may move in one DEM sub-step before the run is stopped. A
/// stable run moves grains by a small fraction of a percent of their radius per sub-step.
constexpr Real kMaxSubstepTravel = 0.25;

/// Throws SimulationError when a grain's position or velocity is not finite, or when a grain's
/// speed times subStepS exceeds kMaxSubstepTravel of its radius (the integrator has become
/// unstable: the step is too long for the contact stiffness). timeS goes into the message.
/// O(N), no allocation unless it throws.
void checkGrainMotion(const Particles& particles, Real subStepS, Real timeS);

/// Throws InputError when the per-disc arrays differ in length, a grain's state is not finite,
/// or a grain's centre lies outside [-R, width + R] x [-R, 2 height] (a restored state that no
/// case could have produced; the region above the domain is allowed for ejected grains).
void checkRestoredGrains(const Particles& particles, Real widthM, Real heightM);

} // namespace lbdem::solver::dem
