// Runout by connected components on a cell grid, energies, outline, packing and Froude number.
#include "solver/diagnostics/MassDiagnostics.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace lbdem::solver {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Union-find with path halving.
class DisjointSets {
public:
    explicit DisjointSets(std::size_t n) : m_parent(n) { std::iota(m_parent.begin(), m_parent.end(), 0); }
    std::size_t find(std::size_t i) {
        while (m_parent[i] != i) i = m_parent[i] = m_parent[m_parent[i]];
        return i;
    }
    void unite(std::size_t a, std::size_t b) { m_parent[find(a)] = find(b); }

private:
    std::vector<std::size_t> m_parent;
};

/// Join every pair of discs closer than gap; a uniform grid of the largest diameter keeps it O(N).
void joinTouching(const GrainArrays& g, double gap, DisjointSets& sets) {
    double xMin = g.x[0], yMin = g.y[0], rMax = 0;
    for (std::size_t i = 0; i < g.count; ++i) {
        xMin = std::min(xMin, double(g.x[i]));
        yMin = std::min(yMin, double(g.y[i]));
        rMax = std::max(rMax, double(g.radius[i]));
    }
    const double cell = 2 * rMax + gap;
    std::vector<std::pair<long long, std::size_t>> keyed(g.count);
    auto cellOf = [&](std::size_t i) {
        return std::make_pair(static_cast<long long>((g.x[i] - xMin) / cell),
                              static_cast<long long>((g.y[i] - yMin) / cell));
    };
    constexpr long long kStride = 1LL << 31;
    for (std::size_t i = 0; i < g.count; ++i) {
        const auto [cx, cy] = cellOf(i);
        keyed[i] = {cx * kStride + cy, i};
    }
    std::sort(keyed.begin(), keyed.end());
    auto rangeOf = [&](long long key) {
        return std::equal_range(keyed.begin(), keyed.end(), std::make_pair(key, std::size_t(0)),
                                [](const auto& a, const auto& b) { return a.first < b.first; });
    };
    for (std::size_t i = 0; i < g.count; ++i) {
        const auto [cx, cy] = cellOf(i);
        for (long long dx = -1; dx <= 1; ++dx) {
            for (long long dy = -1; dy <= 1; ++dy) {
                const auto [begin, end] = rangeOf((cx + dx) * kStride + (cy + dy));
                for (auto it = begin; it != end; ++it) {
                    const std::size_t j = it->second;
                    if (j <= i) continue;
                    const double distance = std::hypot(g.x[i] - g.x[j], g.y[i] - g.y[j]);
                    if (distance - g.radius[i] - g.radius[j] < gap) sets.unite(i, j);
                }
            }
        }
    }
}

/// Upper surface of the main mass per column of width bin; returns the heights per column.
std::vector<double> surfaceHeights(const GrainArrays& g, const std::vector<bool>& main, double bin,
                                   double front) {
    const std::size_t columns = static_cast<std::size_t>(std::ceil(std::max(front, bin) / bin));
    std::vector<double> top(columns, 0.0);
    for (std::size_t i = 0; i < g.count; ++i) {
        if (!main[i]) continue;
        // A disc covers every column its horizontal extent reaches.
        const double left = std::max(0.0, double(g.x[i] - g.radius[i]));
        const double right = double(g.x[i] + g.radius[i]);
        const auto first = static_cast<std::size_t>(left / bin);
        const auto last = std::min(columns - 1, static_cast<std::size_t>(right / bin));
        for (std::size_t c = first; c <= last && c < columns; ++c)
            top[c] = std::max(top[c], double(g.y[i] + g.radius[i]));
    }
    return top;
}

} // namespace

double potentialEnergy(const GrainArrays& g, double gravity, double slopeRad) {
    double energy = 0;
    for (std::size_t i = 0; i < g.count; ++i)
        energy += g.mass[i] * gravity * (g.y[i] * std::cos(slopeRad) - g.x[i] * std::sin(slopeRad));
    return energy;
}

std::vector<bool> largestConnectedGroup(const GrainArrays& g, double contactGap) {
    std::vector<bool> main(g.count, false);
    if (g.count == 0) return main;
    DisjointSets sets(g.count);
    joinTouching(g, contactGap, sets);
    std::vector<std::size_t> size(g.count, 0);
    for (std::size_t i = 0; i < g.count; ++i) ++size[sets.find(i)];
    const auto largest = static_cast<std::size_t>(std::max_element(size.begin(), size.end()) - size.begin());
    for (std::size_t i = 0; i < g.count; ++i) main[i] = sets.find(i) == largest;
    return main;
}

MassDiagnostics computeMassDiagnostics(const GrainArrays& g, const MassDiagnosticsParams& p) {
    MassDiagnostics d;
    if (g.count == 0) return d;
    for (std::size_t i = 0; i < g.count; ++i)
        d.kinetic_energy_j_m += 0.5 * g.mass[i] * (g.vx[i] * g.vx[i] + g.vy[i] * g.vy[i]) +
                                0.5 * g.inertia[i] * g.omega[i] * g.omega[i];
    d.ke_over_ep0 = p.initial_potential_j_m > 0 ? d.kinetic_energy_j_m / p.initial_potential_j_m : 0;

    const std::vector<bool> main = largestConnectedGroup(g, p.contact_gap_m);
    double grainArea = 0;
    for (std::size_t i = 0; i < g.count; ++i) {
        if (!main[i]) continue;
        ++d.main_mass_grains;
        d.front_x_m = std::max(d.front_x_m, double(g.x[i] + g.radius[i]));
        d.height_m = std::max(d.height_m, double(g.y[i] + g.radius[i]));
        grainArea += kPi * g.radius[i] * g.radius[i];
    }
    d.runout_normalised = p.column_width_m > 0 ? (d.front_x_m - p.column_width_m) / p.column_width_m : 0;

    const std::vector<double> top = surfaceHeights(g, main, p.bin_width_m, d.front_x_m);
    double areaUnder = 0;
    d.outline.emplace_back(0.0, 0.0);
    for (std::size_t c = 0; c < top.size(); ++c) {
        const double left = c * p.bin_width_m, right = std::min(d.front_x_m, left + p.bin_width_m);
        areaUnder += top[c] * std::max(0.0, right - left);
        d.outline.emplace_back(left, top[c]);
        d.outline.emplace_back(right, top[c]);
    }
    d.outline.emplace_back(d.front_x_m, 0.0);
    d.packing_fraction = areaUnder > 0 ? grainArea / areaUnder : 0;

    // Front region: main-mass discs within front_length_m behind the front. U is their mean
    // downslope velocity, H the mean surface height of the outline columns they span.
    double sumVelocity = 0;
    std::size_t inFront = 0;
    for (std::size_t i = 0; i < g.count; ++i) {
        if (main[i] && g.x[i] > d.front_x_m - p.front_length_m) {
            sumVelocity += g.vx[i];
            ++inFront;
        }
    }
    double sumHeight = 0;
    std::size_t frontColumns = 0;
    for (std::size_t c = 0; c < top.size(); ++c) {
        if ((c + 1) * p.bin_width_m > d.front_x_m - p.front_length_m && top[c] > 0) {
            sumHeight += top[c];
            ++frontColumns;
        }
    }
    d.front_velocity_m_s = inFront ? sumVelocity / inFront : 0;
    d.front_thickness_m = frontColumns ? sumHeight / frontColumns : 0;
    if (p.fluid_density > 0 && d.front_thickness_m > 0) {
        const double phi = d.packing_fraction;
        const double mixture = phi * p.grain_density + (1 - phi) * p.fluid_density;
        const double reduced = (mixture / p.fluid_density - 1) * p.gravity_m_s2 *
                               d.front_thickness_m * std::cos(p.slope_rad);
        d.froude_densimetric = reduced > 0 ? std::abs(d.front_velocity_m_s) / std::sqrt(reduced) : 0;
    }
    return d;
}

} // namespace lbdem::solver
