// Iso-contours of a scalar field on a regular grid: Gaussian smoothing and marching squares.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace lbdem::solver {

/// Values at the nodes of a regular grid: node (i, j) lies at (x0 + i h, y0 + j h).
struct ScalarGrid {
    std::size_t nx = 0, ny = 0;
    double x0 = 0, y0 = 0, h = 1;
    std::vector<double> values; ///< nx * ny, row by row (i fastest)

    /// A grid of nx x ny zeros.
    ScalarGrid(std::size_t nx_, std::size_t ny_, double x0_, double y0_, double h_)
        : nx(nx_), ny(ny_), x0(x0_), y0(y0_), h(h_), values(nx_ * ny_, 0.0) {}
    double& at(std::size_t i, std::size_t j) { return values[j * nx + i]; }
    double at(std::size_t i, std::size_t j) const { return values[j * nx + i]; }
};

using Polyline = std::vector<std::pair<double, double>>;

/// Convolve the grid with a Gaussian of standard deviation sigma [length units], separably,
/// the field taken as zero outside the grid.
void gaussianSmooth(ScalarGrid& grid, double sigma);

/// The closed contours where the field crosses level (inside: value > level), by marching
/// squares with linear interpolation along the cell edges; a saddle cell is resolved by the
/// mean of its corners. The outermost ring of nodes is taken as outside, so every contour closes.
/// Each loop lists its points once (the last joins the first).
std::vector<Polyline> marchingSquares(const ScalarGrid& grid, double level);

/// Signed area of a closed polyline (positive counter-clockwise, y up).
double signedArea(const Polyline& loop);

} // namespace lbdem::solver
