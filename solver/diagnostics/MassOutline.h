// The flow-front outline of the main mass as a smooth contour (for drawing and outline files).
#pragma once

#include "solver/diagnostics/Contour.h"
#include "solver/diagnostics/MassDiagnostics.h"

#include <vector>

namespace lbdem::solver {

/// How the outline contour is drawn, in units of the outline's length scale (a mean diameter).
struct MassOutlineParams {
    double length_m = 0;    ///< the length scale: about one mean disc diameter
    double cell = 0.25;     ///< grid spacing of the solid-fraction field
    double smoothing = 0.5; ///< standard deviation of its Gaussian smoothing
    double level = 0.2;     ///< solid fraction of the contour
};

/// The outline of the discs flagged in main: the level contour of their solid fraction,
/// smoothed, with the base (y = 0) and the left wall (x = 0) as mirrors so that the contour
/// meets them at right angles. It runs from the base at the back (or the left wall's foot) over
/// the upper surface and down the front to the base; the base itself is left out, as the walls
/// close the mass there. Empty when main holds no disc.
Polyline massOutline(const GrainArrays& grains, const std::vector<bool>& main,
                     const MassOutlineParams& params);

/// The share of the polyline's segments (0 to 1) that run along x or y within 1e-3 of their
/// length: 1 for a staircase, near 0 for a contour of a round shape.
double axisAlignedShare(const Polyline& line);

} // namespace lbdem::solver
