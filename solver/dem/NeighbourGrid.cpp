// Uniform cell list: counting sort of discs into cells, then a 3x3-cell stencil per disc.
#include "solver/dem/NeighbourGrid.h"

#include <algorithm>
#include <cmath>

namespace lbdem::solver::dem {

namespace {

// Cap on cells per disc: a stray disc far from the pile must not make the grid huge.
constexpr double kMaxCellsPerDisc = 8.0;

void sortRow(std::int32_t* begin, std::int32_t* end) {
    // Rows are short (a handful of partners): insertion sort beats std::sort here.
    for (std::int32_t* a = begin + 1; a < end; ++a) {
        const std::int32_t v = *a;
        std::int32_t* b = a;
        while (b > begin && *(b - 1) > v) {
            *b = *(b - 1);
            --b;
        }
        *b = v;
    }
}

} // namespace

void NeighbourGrid::reserve(std::size_t n) {
    m_cellStart.reserve(static_cast<std::size_t>(kMaxCellsPerDisc * static_cast<double>(n) + 64) +
                        1);
    m_items.reserve(n);
    m_cellOf.reserve(n);
}

void NeighbourGrid::build(const Real* x, const Real* y, std::size_t n, Real cellSize) {
    Real xmin = 0, xmax = 0, ymin = 0, ymax = 0;
    if (n > 0) {
        xmin = xmax = x[0];
        ymin = ymax = y[0];
    }
    for (std::size_t i = 1; i < n; ++i) {
        xmin = std::min(xmin, x[i]);
        xmax = std::max(xmax, x[i]);
        ymin = std::min(ymin, y[i]);
        ymax = std::max(ymax, y[i]);
    }
    Real size = cellSize;
    const double maxCells = kMaxCellsPerDisc * static_cast<double>(n) + 64;
    while ((std::floor((xmax - xmin) / size) + 1) * (std::floor((ymax - ymin) / size) + 1) >
           maxCells)
        size *= 2;
    m_inv = 1 / size;
    m_x0 = xmin;
    m_y0 = ymin;
    m_nx = static_cast<int>((xmax - xmin) * m_inv) + 1;
    m_ny = static_cast<int>((ymax - ymin) * m_inv) + 1;
    const std::size_t cells = static_cast<std::size_t>(m_nx) * m_ny;
    m_cellStart.assign(cells + 1, 0);
    m_cellOf.resize(n);
    m_items.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const int cx = std::min(m_nx - 1, static_cast<int>((x[i] - m_x0) * m_inv));
        const int cy = std::min(m_ny - 1, static_cast<int>((y[i] - m_y0) * m_inv));
        m_cellOf[i] = cy * m_nx + cx;
        ++m_cellStart[m_cellOf[i] + 1];
    }
    for (std::size_t c = 0; c < cells; ++c)
        m_cellStart[c + 1] += m_cellStart[c];
    // Fill each cell in increasing disc index (stable counting sort).
    std::vector<std::uint32_t>& fill = m_cellStart; // reuse: shift back afterwards
    for (std::size_t i = 0; i < n; ++i)
        m_items[fill[m_cellOf[i]]++] = static_cast<std::int32_t>(i);
    for (std::size_t c = cells; c > 0; --c)
        fill[c] = fill[c - 1];
    fill[0] = 0;
}

void NeighbourGrid::pairs(const Real* x, const Real* y, const Real* r, Real skin,
                          PairRows& rows) const {
    const std::size_t n = m_cellOf.size();
    rows.start.resize(n + 1);
    rows.cols.clear();
    rows.start[0] = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const int cx = m_cellOf[i] % m_nx, cy = m_cellOf[i] / m_nx;
        for (int ny = std::max(cy - 1, 0); ny <= std::min(cy + 1, m_ny - 1); ++ny) {
            for (int nx = std::max(cx - 1, 0); nx <= std::min(cx + 1, m_nx - 1); ++nx) {
                const int c = ny * m_nx + nx;
                for (std::uint32_t k = m_cellStart[c]; k < m_cellStart[c + 1]; ++k) {
                    const std::int32_t j = m_items[k];
                    if (j <= static_cast<std::int32_t>(i)) continue;
                    const Real dx = x[j] - x[i], dy = y[j] - y[i], reach = r[i] + r[j] + skin;
                    if (dx * dx + dy * dy < reach * reach) rows.cols.push_back(j);
                }
            }
        }
        rows.start[i + 1] = static_cast<std::uint32_t>(rows.cols.size());
        sortRow(rows.cols.data() + rows.start[i], rows.cols.data() + rows.start[i + 1]);
    }
}

void bruteForcePairs(const Real* x, const Real* y, const Real* r, std::size_t n, Real skin,
                     PairRows& rows) {
    rows.start.assign(n + 1, 0);
    rows.cols.clear();
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            const Real dx = x[j] - x[i], dy = y[j] - y[i], reach = r[i] + r[j] + skin;
            if (dx * dx + dy * dy < reach * reach)
                rows.cols.push_back(static_cast<std::int32_t>(j));
        }
        rows.start[i + 1] = static_cast<std::uint32_t>(rows.cols.size());
    }
}

} // namespace lbdem::solver::dem
