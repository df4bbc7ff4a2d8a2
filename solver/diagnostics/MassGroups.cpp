// The main mass: discs linked across small gaps on a cell grid, grouped with union-find.
#include "solver/diagnostics/MassDiagnostics.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace lbdem::solver {

namespace {

/// Union-find with path halving.
class DisjointSets {
public:
    explicit DisjointSets(std::size_t n) : m_parent(n) {
        std::iota(m_parent.begin(), m_parent.end(), 0);
    }
    std::size_t find(std::size_t i) {
        while (m_parent[i] != i)
            i = m_parent[i] = m_parent[m_parent[i]];
        return i;
    }
    void unite(std::size_t a, std::size_t b) { m_parent[find(a)] = find(b); }

private:
    std::vector<std::size_t> m_parent;
};

/// Call visit(i, j, gap) once for every pair i < j whose gap is below maxGap; a uniform grid of
/// cells no smaller than the largest diameter plus maxGap keeps it O(N).
template <typename Visit> void forCloseDiscs(const GrainArrays& g, double maxGap, Visit visit) {
    double xMin = g.x[0], yMin = g.y[0], rMax = 0;
    for (std::size_t i = 0; i < g.count; ++i) {
        xMin = std::min(xMin, double(g.x[i]));
        yMin = std::min(yMin, double(g.y[i]));
        rMax = std::max(rMax, double(g.radius[i]));
    }
    const double cell = 2 * rMax + maxGap;
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
                    const double gap =
                        std::hypot(g.x[i] - g.x[j], g.y[i] - g.y[j]) - g.radius[i] - g.radius[j];
                    if (gap < maxGap) visit(i, j, gap);
                }
            }
        }
    }
}

} // namespace

std::vector<bool> mainMass(const GrainArrays& g, double contactGap, double bridgeGap) {
    std::vector<bool> main(g.count, false);
    if (g.count == 0) return main;
    bridgeGap = std::max(bridgeGap, contactGap);
    DisjointSets sets(g.count);
    std::vector<std::pair<std::size_t, std::size_t>> touching;
    forCloseDiscs(g, bridgeGap, [&](std::size_t i, std::size_t j, double gap) {
        sets.unite(i, j);
        if (gap < contactGap) touching.emplace_back(i, j);
    });
    std::vector<std::size_t> size(g.count, 0);
    for (std::size_t i = 0; i < g.count; ++i)
        ++size[sets.find(i)];
    const auto largest =
        static_cast<std::size_t>(std::max_element(size.begin(), size.end()) - size.begin());
    // A disc of the largest group counts when it touches another disc of that group; a lone
    // disc on its own still links the group across its gap but is not part of the mass. With
    // nothing touching at all (a single disc, a lattice of separate discs) the group counts whole.
    for (const auto& [i, j] : touching)
        if (sets.find(i) == largest && sets.find(j) == largest) main[i] = main[j] = true;
    if (std::none_of(main.begin(), main.end(), [](bool b) { return b; }))
        for (std::size_t i = 0; i < g.count; ++i)
            main[i] = sets.find(i) == largest;
    return main;
}

} // namespace lbdem::solver
