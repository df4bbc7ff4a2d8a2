// Closed-form disc-rectangle overlap (the partially saturated cells' solid fractions).
#include "solver/coupling/DiscGeometry.h"

#include <algorithm>
#include <cmath>

namespace lbdem::solver::coupling {

namespace {

// Antiderivative of sqrt(r^2 - x^2) on [-r, r].
Real chordPrimitive(Real x, Real r) {
    const Real t = std::clamp(x / r, Real(-1), Real(1));
    return Real(0.5) *
           (x * r * std::sqrt(std::max(Real(1) - t * t, Real(0))) + r * r * std::asin(t));
}

} // namespace

Real discRectangleOverlap(Real cx, Real cy, Real r, Real x0, Real y0, Real x1, Real y1) {
    // Work relative to the centre; the integrand over x is
    // clamp(s, y0, y1) - clamp(-s, y0, y1) with s = sqrt(r^2 - x^2) the half chord.
    x0 -= cx;
    x1 -= cx;
    y0 -= cy;
    y1 -= cy;
    const Real a = std::max(x0, -r), b = std::min(x1, r);
    if (a >= b || y0 >= r || y1 <= -r || r <= 0) return 0;
    // Break points: where s equals |y0| or |y1| (the chord end crosses an edge), tangent points
    // included so that no piece changes regime at its midpoint.
    Real breaks[6] = {a, b, 0, 0, 0, 0};
    int n = 2;
    for (Real y : {y0, y1}) {
        if (std::abs(y) <= r) {
            const Real x = std::sqrt(r * r - y * y);
            for (Real xb : {-x, x})
                if (xb > a && xb < b) breaks[n++] = xb;
        }
    }
    for (int k = 1; k < n; ++k) // insertion sort of at most six values
        for (int m = k; m > 0 && breaks[m] < breaks[m - 1]; --m)
            std::swap(breaks[m], breaks[m - 1]);
    Real area = 0;
    for (int k = 0; k + 1 < n; ++k) {
        const Real l = breaks[k], u = breaks[k + 1];
        if (u - l <= 0) continue;
        const Real m = Real(0.5) * (l + u);
        const Real s = std::sqrt(std::max(r * r - m * m, Real(0)));
        // On this piece each chord end is either the circle (+-s) or an edge (y0, y1) throughout.
        const Real chord = chordPrimitive(u, r) - chordPrimitive(l, r); // integral of s
        Real top, bottom;
        if (s >= y1)
            top = y1 * (u - l);
        else if (s <= y0)
            top = y0 * (u - l);
        else
            top = chord;
        if (-s <= y0)
            bottom = y0 * (u - l);
        else if (-s >= y1)
            bottom = y1 * (u - l);
        else
            bottom = -chord;
        area += top - bottom;
    }
    return std::max(area, Real(0));
}

} // namespace lbdem::solver::coupling
