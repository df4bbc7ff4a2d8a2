// Separable Gaussian smoothing and marching squares (edge-keyed segments chained into loops).
#include "solver/diagnostics/Contour.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace lbdem::solver {

namespace {

/// One pass of a 1-D convolution along i (along == true) or j of the grid with kernel.
void convolve(ScalarGrid& grid, const std::vector<double>& kernel, bool along) {
    const auto radius = static_cast<long>(kernel.size() / 2);
    const std::vector<double> source = grid.values;
    const auto n = static_cast<long>(along ? grid.nx : grid.ny);
    for (std::size_t j = 0; j < grid.ny; ++j)
        for (std::size_t i = 0; i < grid.nx; ++i) {
            const long centre = static_cast<long>(along ? i : j);
            double sum = 0;
            for (long k = -radius; k <= radius; ++k) {
                const long m = centre + k;
                if (m < 0 || m >= n) continue;
                const std::size_t index =
                    along ? j * grid.nx + std::size_t(m) : std::size_t(m) * grid.nx + i;
                sum += kernel[std::size_t(k + radius)] * source[index];
            }
            grid.at(i, j) = sum;
        }
}

/// Crossing points keyed by their grid edge, and the two crossings each one is joined to.
struct SegmentGraph {
    std::unordered_map<std::int64_t, std::pair<double, double>> point;
    std::unordered_map<std::int64_t, std::array<std::int64_t, 2>> links;

    void join(std::int64_t a, std::int64_t b) {
        for (auto [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
            auto [it, fresh] = links.try_emplace(from, std::array<std::int64_t, 2>{-1, -1});
            it->second[it->second[0] < 0 ? 0 : 1] = to;
        }
    }
};

} // namespace

void gaussianSmooth(ScalarGrid& grid, double sigma) {
    if (sigma <= 0 || grid.values.empty()) return;
    const auto radius = static_cast<long>(std::ceil(3 * sigma / grid.h));
    std::vector<double> kernel(std::size_t(2 * radius + 1));
    double total = 0;
    for (long k = -radius; k <= radius; ++k) {
        const double x = k * grid.h / sigma;
        total += kernel[std::size_t(k + radius)] = std::exp(-0.5 * x * x);
    }
    for (double& weight : kernel)
        weight /= total;
    convolve(grid, kernel, true);
    convolve(grid, kernel, false);
}

std::vector<Polyline> marchingSquares(const ScalarGrid& grid, double level) {
    std::vector<Polyline> loops;
    if (grid.nx < 3 || grid.ny < 3) return loops;
    const std::size_t nx = grid.nx, ny = grid.ny;
    auto inside = [&](std::size_t i, std::size_t j) {
        return i > 0 && j > 0 && i + 1 < nx && j + 1 < ny && grid.at(i, j) > level;
    };
    auto horizontal = [&](std::size_t i, std::size_t j) { return std::int64_t(2 * (j * nx + i)); };
    auto vertical = [&](std::size_t i, std::size_t j) {
        return std::int64_t(2 * (j * nx + i) + 1);
    };
    SegmentGraph graph;
    // The crossing on the edge from node (ia, ja) to (ib, jb), interpolated linearly.
    auto crossing = [&](std::int64_t id, std::size_t ia, std::size_t ja, std::size_t ib,
                        std::size_t jb) {
        if (graph.point.count(id)) return id;
        const double va = grid.at(ia, ja), vb = grid.at(ib, jb);
        const double t = vb != va ? std::clamp((level - va) / (vb - va), 0.0, 1.0) : 0.5;
        graph.point[id] = {grid.x0 + grid.h * (double(ia) + t * double(ib - ia)),
                           grid.y0 + grid.h * (double(ja) + t * double(jb - ja))};
        return id;
    };
    for (std::size_t j = 0; j + 1 < ny; ++j)
        for (std::size_t i = 0; i + 1 < nx; ++i) {
            // Corners counter-clockwise from (i, j); edge k runs from corner k to corner k + 1.
            const std::array<bool, 4> in = {inside(i, j), inside(i + 1, j), inside(i + 1, j + 1),
                                            inside(i, j + 1)};
            const std::array<std::int64_t, 4> edge = {horizontal(i, j), vertical(i + 1, j),
                                                      horizontal(i, j + 1), vertical(i, j)};
            std::array<std::int64_t, 4> at{-1, -1, -1, -1};
            int crossings = 0;
            if (in[0] != in[1]) at[0] = crossing(edge[0], i, j, i + 1, j), ++crossings;
            if (in[1] != in[2]) at[1] = crossing(edge[1], i + 1, j, i + 1, j + 1), ++crossings;
            if (in[3] != in[2]) at[2] = crossing(edge[2], i, j + 1, i + 1, j + 1), ++crossings;
            if (in[0] != in[3]) at[3] = crossing(edge[3], i, j, i, j + 1), ++crossings;
            if (crossings == 2) {
                std::int64_t ends[2];
                int n = 0;
                for (std::int64_t id : at)
                    if (id >= 0) ends[n++] = id;
                graph.join(ends[0], ends[1]);
            } else if (crossings == 4) {
                // Saddle: cut off the two corners that the mean does not side with; corner k
                // touches edges k - 1 and k.
                const double mean = 0.25 * (grid.at(i, j) + grid.at(i + 1, j) +
                                            grid.at(i + 1, j + 1) + grid.at(i, j + 1));
                const bool centreInside = mean > level;
                for (int k = 0; k < 4; ++k)
                    if (in[std::size_t(k)] != centreInside)
                        graph.join(at[std::size_t((k + 3) % 4)], at[std::size_t(k)]);
            }
        }
    std::unordered_map<std::int64_t, bool> visited;
    for (const auto& [start, unused] : graph.links) {
        if (visited[start]) continue;
        Polyline loop;
        std::int64_t previous = -1, current = start;
        do {
            visited[current] = true;
            loop.push_back(graph.point[current]);
            const auto& next = graph.links[current];
            const std::int64_t step = next[0] != previous ? next[0] : next[1];
            previous = current;
            current = step;
        } while (current != start && current >= 0 && !visited[current]);
        if (loop.size() >= 3) loops.push_back(std::move(loop));
    }
    return loops;
}

double signedArea(const Polyline& loop) {
    double twice = 0;
    for (std::size_t k = 0; k < loop.size(); ++k) {
        const auto& [x0, y0] = loop[k];
        const auto& [x1, y1] = loop[(k + 1) % loop.size()];
        twice += x0 * y1 - x1 * y0;
    }
    return 0.5 * twice;
}

} // namespace lbdem::solver
