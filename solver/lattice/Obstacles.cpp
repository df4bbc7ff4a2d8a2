// Fixed obstacles (discs, polygons): solid marking and interpolated bounce-back links.
#include "solver/lattice/Lattice.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lbdem::solver::lattice {

namespace {

using Point = std::pair<Real, Real>;

bool insidePolygon(const std::vector<Point>& poly, Real x, Real y) {
    bool inside = false;
    for (std::size_t a = 0, b = poly.size() - 1; a < poly.size(); b = a++) {
        const auto [xa, ya] = poly[a];
        const auto [xb, yb] = poly[b];
        if ((ya > y) != (yb > y) && x < (xb - xa) * (y - ya) / (yb - ya) + xa) inside = !inside;
    }
    return inside;
}

// Smallest t in [0, 1] where p + t c crosses a polygon edge; 0.5 if none (grazing link).
Real polygonCrossing(const std::vector<Point>& poly, Real px, Real py, Real cx, Real cy) {
    Real best = std::numeric_limits<Real>::max();
    for (std::size_t a = 0, b = poly.size() - 1; a < poly.size(); b = a++) {
        const Real ex = poly[a].first - poly[b].first, ey = poly[a].second - poly[b].second;
        const Real den = cx * ey - cy * ex;
        if (std::abs(den) < 1e-14) continue;
        const Real wx = poly[b].first - px, wy = poly[b].second - py;
        const Real t = (wx * ey - wy * ex) / den;
        const Real s = (wx * cy - wy * cx) / den;
        if (t >= 0 && t <= 1 && s >= 0 && s <= 1) best = std::min(best, t);
    }
    return best <= 1 ? best : 0.5;
}

} // namespace

int Lattice::addDisc(Real cx, Real cy, Real radius) {
    const int owner = static_cast<int>(m_owners.size());
    m_owners.push_back({cx, cy});
    m_loads.emplace_back();
    std::vector<long long> solids;
    for (int j = 0; j < m_ny; ++j)
        for (int i = 0; i < m_nx; ++i) {
            const Real dx = nodeX(i) - cx, dy = nodeY(j) - cy;
            if (isFluid(index(i, j)) && dx * dx + dy * dy < radius * radius)
                solids.push_back(index(i, j));
        }
    auto crossing = [=](Real px, Real py, int d) {
        // |p + t c - centre| = r, the root entering the disc.
        const Real ox = px - cx, oy = py - cy;
        const Real a = kCx[d] * kCx[d] + kCy[d] * kCy[d];
        const Real b = 2 * (ox * kCx[d] + oy * kCy[d]);
        const Real c = ox * ox + oy * oy - radius * radius;
        const Real disc = std::max(b * b - 4 * a * c, Real(0));
        return std::clamp((-b - std::sqrt(disc)) / (2 * a), Real(0), Real(1));
    };
    for (long long c : solids) {
        m_flags[c] = kObstacle;
        m_side[c] = owner;
        m_solids.push_back(c);
    }
    m_shapes.push_back(crossing);
    rebuildLinks();
    return owner;
}

int Lattice::addPolygon(const std::vector<std::pair<Real, Real>>& vertices) {
    const int owner = static_cast<int>(m_owners.size());
    Real sx = 0, sy = 0;
    for (const auto& v : vertices) {
        sx += v.first;
        sy += v.second;
    }
    m_owners.push_back({sx / vertices.size(), sy / vertices.size()});
    m_loads.emplace_back();
    for (int j = 0; j < m_ny; ++j)
        for (int i = 0; i < m_nx; ++i) {
            const long long c = index(i, j);
            if (isFluid(c) && insidePolygon(vertices, nodeX(i), nodeY(j))) {
                m_flags[c] = kObstacle;
                m_side[c] = owner;
                m_solids.push_back(c);
            }
        }
    m_shapes.push_back([vertices](Real px, Real py, int d) {
        return polygonCrossing(vertices, px, py, kCx[d], kCy[d]);
    });
    rebuildLinks();
    return owner;
}

void Lattice::rebuildLinks() {
    m_copyLinks.clear();
    m_pressureLinks.clear();
    m_obstacleLinks.clear();
    buildWallLinks();
    for (int s = 0; s < 2; ++s)
        m_zouHeCells[s].erase(std::remove_if(m_zouHeCells[s].begin(), m_zouHeCells[s].end(),
                                             [this](long long c) { return !isFluid(c); }),
                              m_zouHeCells[s].end());
    for (long long c = 0; c < m_cells; ++c) {
        if (!isFluid(c)) continue;
        const int i = static_cast<int>(c % m_nx), j = static_cast<int>(c / m_nx);
        for (int d = 1; d < kQ; ++d) {
            const long long n = neighbour(c, d);
            if (m_flags[n] != kObstacle) continue;
            const int owner = m_side[n];
            const Real q = m_shapes[owner](nodeX(i), nodeY(j), d);
            const bool interior = isFluid(neighbour(c, kOpposite[d]));
            m_obstacleLinks.push_back({c, d, q, owner, interior});
        }
    }
}

} // namespace lbdem::solver::lattice
