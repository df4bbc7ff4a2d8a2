// Grid-scale share of vorticity over fluid nodes away from solids (GridNoise.h).
#include "solver/diagnostics/GridNoise.h"

#include <cmath>
#include <limits>
#include <vector>

namespace lbdem::solver {

namespace {

/// Index of node (i, j) after wrapping across periodic sides, -1 beyond a closed edge.
long long wrapped(const GridNoiseField& f, int i, int j) {
    if (i < 0 || i >= f.nx) {
        if (!f.periodic_x) return -1;
        i = (i % f.nx + f.nx) % f.nx;
    }
    if (j < 0 || j >= f.ny) {
        if (!f.periodic_y) return -1;
        j = (j % f.ny + f.ny) % f.ny;
    }
    return static_cast<long long>(j) * f.nx + i;
}

/// True when no solid node (or closed edge) lies within kGridNoiseSolidDistance - 1 nodes along
/// both axes: distance below 3 on the integer grid is exactly the 5 x 5 block.
bool farFromSolids(const GridNoiseField& f, int i, int j) {
    constexpr int reach = kGridNoiseSolidDistance - 1;
    for (int dj = -reach; dj <= reach; ++dj)
        for (int di = -reach; di <= reach; ++di) {
            const long long n = wrapped(f, i + di, j + dj);
            if (n < 0 || f.solid[n]) return false;
        }
    return true;
}

/// Central-difference vorticity at (i, j); its four neighbours must exist.
double vorticity(const GridNoiseField& f, int i, int j) {
    return 0.5 * (f.uy[wrapped(f, i + 1, j)] - f.uy[wrapped(f, i - 1, j)]) -
           0.5 * (f.ux[wrapped(f, i, j + 1)] - f.ux[wrapped(f, i, j - 1)]);
}

/// Whether all four neighbours of (i, j) exist (across periodic sides or inside the grid).
bool hasNeighbours(const GridNoiseField& f, int i, int j) {
    return wrapped(f, i + 1, j) >= 0 && wrapped(f, i - 1, j) >= 0 && wrapped(f, i, j + 1) >= 0 &&
           wrapped(f, i, j - 1) >= 0;
}

/// Sums of one row: squared deviation from the box mean, squared vorticity, nodes.
struct RowSums {
    double deviation2 = 0, vorticity2 = 0;
    long long nodes = 0;
};

/// The row's sums from the vorticity of every node (omega, row by row; 0 where undefined, which
/// no node far from solids reads).
RowSums rowSums(const GridNoiseField& f, const std::vector<double>& omega, int j) {
    RowSums row;
    for (int i = 0; i < f.nx; ++i) {
        if (!farFromSolids(f, i, j)) continue;
        double box = 0;
        for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di)
                box += omega[static_cast<std::size_t>(wrapped(f, i + di, j + dj))];
        const double here = omega[static_cast<std::size_t>(wrapped(f, i, j))];
        const double deviation = here - box / 9.0;
        row.deviation2 += deviation * deviation;
        row.vorticity2 += here * here;
        ++row.nodes;
    }
    return row;
}

} // namespace

GridNoise gridNoise(const GridNoiseField& field) {
    const std::size_t nx = static_cast<std::size_t>(field.nx > 0 ? field.nx : 0);
    const std::size_t ny = static_cast<std::size_t>(field.ny > 0 ? field.ny : 0);
    // Each node's vorticity once: the box means read it nine times.
    std::vector<double> omega(nx * ny, 0.0);
#pragma omp parallel for schedule(static)
    for (int j = 0; j < field.ny; ++j)
        for (int i = 0; i < field.nx; ++i)
            if (hasNeighbours(field, i, j))
                omega[static_cast<std::size_t>(j) * nx + static_cast<std::size_t>(i)] =
                    vorticity(field, i, j);
    std::vector<RowSums> rows(ny);
#pragma omp parallel for schedule(static)
    for (int j = 0; j < field.ny; ++j)
        rows[static_cast<std::size_t>(j)] = rowSums(field, omega, j);
    RowSums total;
    for (const RowSums& row : rows) { // row order: the same sum on any thread count
        total.deviation2 += row.deviation2;
        total.vorticity2 += row.vorticity2;
        total.nodes += row.nodes;
    }
    GridNoise result;
    result.nodes = total.nodes;
    if (total.nodes == 0)
        result.share = std::numeric_limits<double>::quiet_NaN();
    else if (total.vorticity2 > 0)
        result.share = std::sqrt(total.deviation2 / total.vorticity2);
    return result;
}

} // namespace lbdem::solver
