// The main mass's outline: its solid fraction rasterised with mirror images in the base and the
// left wall, smoothed, contoured, clipped to the domain and cut open along the base.
#include "solver/diagnostics/MassOutline.h"

#include <algorithm>
#include <cmath>

namespace lbdem::solver {

namespace {

/// Adds the disc at (cx, cy) of radius r to grid as its area coverage of each node's cell
/// (anti-aliased over one cell), keeping the larger value where discs overlap.
void rasterise(ScalarGrid& grid, double cx, double cy, double r) {
    const double h = grid.h;
    const auto first = [&](double lo, double origin) {
        return static_cast<long>(std::floor((lo - origin) / h));
    };
    const long i0 = std::max(0L, first(cx - r - h, grid.x0));
    const long i1 = std::min(long(grid.nx) - 1, first(cx + r + h, grid.x0) + 1);
    const long j0 = std::max(0L, first(cy - r - h, grid.y0));
    const long j1 = std::min(long(grid.ny) - 1, first(cy + r + h, grid.y0) + 1);
    for (long j = j0; j <= j1; ++j)
        for (long i = i0; i <= i1; ++i) {
            const double d = std::hypot(grid.x0 + i * h - cx, grid.y0 + j * h - cy);
            const double cover = std::clamp((r - d) / h + 0.5, 0.0, 1.0);
            double& value = grid.at(std::size_t(i), std::size_t(j));
            value = std::max(value, cover);
        }
}

/// The loop clipped to x >= 0, y >= 0 (the mirror images fold onto the walls), without repeated
/// points and with the inner points of straight runs along a wall dropped.
Polyline clipToQuadrant(const Polyline& loop) {
    Polyline clipped;
    for (auto [x, y] : loop) {
        const std::pair<double, double> point{std::max(0.0, x), std::max(0.0, y)};
        if (clipped.empty() || clipped.back() != point) clipped.push_back(point);
    }
    while (clipped.size() > 1 && clipped.front() == clipped.back())
        clipped.pop_back();
    Polyline merged;
    const std::size_t n = clipped.size();
    for (std::size_t k = 0; k < n; ++k) {
        const auto& prev = clipped[(k + n - 1) % n];
        const auto& here = clipped[k];
        const auto& next = clipped[(k + 1) % n];
        const bool onBase = prev.second == 0 && here.second == 0 && next.second == 0;
        const bool onWall = prev.first == 0 && here.first == 0 && next.first == 0;
        if (!onBase && !onWall) merged.push_back(here);
    }
    return merged;
}

} // namespace

Polyline massOutline(const GrainArrays& g, const std::vector<bool>& main,
                     const MassOutlineParams& p) {
    double xmax = 0, ymax = 0, rmax = 0;
    bool any = false;
    for (std::size_t i = 0; i < g.count; ++i) {
        if (!main[i]) continue;
        any = true;
        xmax = std::max(xmax, double(g.x[i] + g.radius[i]));
        ymax = std::max(ymax, double(g.y[i] + g.radius[i]));
        rmax = std::max(rmax, double(g.radius[i]));
    }
    if (!any || p.length_m <= 0) return {};
    const double h = p.cell * p.length_m, sigma = p.smoothing * p.length_m;
    // Wide enough that the smoothing sees every mirror image that reaches the domain.
    const double margin = 3 * sigma + rmax + 2 * h;
    const auto nodes = [&](double extent) { return std::size_t(std::ceil(extent / h)) + 1; };
    ScalarGrid grid(nodes(xmax + 2 * margin), nodes(ymax + 2 * margin), -margin, -margin, h);
    for (std::size_t i = 0; i < g.count; ++i) {
        if (!main[i]) continue;
        const double x = g.x[i], y = g.y[i], r = g.radius[i];
        for (double sx : {1.0, -1.0})
            for (double sy : {1.0, -1.0})
                rasterise(grid, sx * x, sy * y, r);
    }
    gaussianSmooth(grid, sigma);
    Polyline best;
    double bestArea = 0;
    for (const Polyline& loop : marchingSquares(grid, p.level)) {
        Polyline clipped = clipToQuadrant(loop);
        const double area = std::abs(signedArea(clipped));
        if (clipped.size() >= 3 && area > bestArea) best = std::move(clipped), bestArea = area;
    }
    if (best.empty()) return best;
    // Clockwise (y up): up the back, along the top, down the front, back along the base.
    if (signedArea(best) > 0) std::reverse(best.begin(), best.end());
    const std::size_t n = best.size();
    std::size_t baseEnd = n; // the point where the longest stretch along the base ends
    double baseLength = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const auto& a = best[k];
        const auto& b = best[(k + 1) % n];
        if (a.second == 0 && b.second == 0 && std::abs(a.first - b.first) > baseLength)
            baseLength = std::abs(a.first - b.first), baseEnd = (k + 1) % n;
    }
    if (baseEnd == n) {
        // Clear of the base: the closed loop from its lowest point.
        const auto lowest = std::min_element(best.begin(), best.end(),
                                             [](auto& a, auto& b) { return a.second < b.second; });
        std::rotate(best.begin(), lowest, best.end());
        best.push_back(best.front());
        return best;
    }
    std::rotate(best.begin(), best.begin() + long(baseEnd), best.end());
    return best;
}

double axisAlignedShare(const Polyline& line) {
    std::size_t segments = 0, aligned = 0;
    for (std::size_t k = 0; k + 1 < line.size(); ++k) {
        const double dx = std::abs(line[k + 1].first - line[k].first);
        const double dy = std::abs(line[k + 1].second - line[k].second);
        const double length = std::hypot(dx, dy);
        if (length == 0) continue;
        ++segments;
        aligned += std::min(dx, dy) <= 1e-3 * length;
    }
    return segments ? double(aligned) / double(segments) : 0.0;
}

} // namespace lbdem::solver
