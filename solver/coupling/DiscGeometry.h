// Disc geometry on the lattice: exact disc-square overlap areas and link-wall crossing fractions.
#pragma once

#include "solver/core/Real.h"

#include <algorithm>
#include <cmath>

namespace lbdem::solver::coupling {

/// Exact area of the disc (centre cx, cy, radius r) inside the rectangle [x0, x1] x [y0, y1],
/// by integrating the chord height piecewise between the points where the circle crosses the
/// rectangle's horizontal edges (each piece has a closed-form antiderivative).
Real discRectangleOverlap(Real cx, Real cy, Real r, Real x0, Real y0, Real x1, Real y1);

/// Solid fraction of the unit lattice cell centred at (px, py): overlap area with the disc.
/// Cells wholly inside or outside (farthest / nearest point tested) skip the integration.
inline Real cellSolidFraction(Real cx, Real cy, Real r, Real px, Real py) {
    const Real dx = std::abs(px - cx), dy = std::abs(py - cy);
    const Real fx = dx + Real(0.5), fy = dy + Real(0.5);
    if (fx * fx + fy * fy <= r * r) return 1;
    const Real nx = std::max(dx - Real(0.5), Real(0)), ny = std::max(dy - Real(0.5), Real(0));
    if (nx * nx + ny * ny >= r * r) return 0;
    return discRectangleOverlap(cx, cy, r, px - Real(0.5), py - Real(0.5), px + Real(0.5),
                                py + Real(0.5));
}

/// Fraction q in [0, 1] of the link from (px, py) along (ex, ey) where it enters the circle of
/// radius r centred at the origin-relative offset: (px, py) is measured from the disc centre.
/// Inline: it runs once per moving-wall link.
inline Real linkWallFraction(Real px, Real py, int ex, int ey, Real r) {
    // |p + t e| = r: the smaller root is where the link enters the disc.
    const Real a = Real(ex * ex + ey * ey);
    const Real b = 2 * (px * ex + py * ey);
    const Real c = px * px + py * py - r * r;
    const Real disc = std::max(b * b - 4 * a * c, Real(0));
    // a is 1 or 2: scaling by 0.5 / a is exactly the division by 2a, without a divide.
    return std::clamp((-b - std::sqrt(disc)) * (Real(0.5) / a), Real(0), Real(1));
}

} // namespace lbdem::solver::coupling
