// Uniform cell list: bins discs into square cells and lists candidate pairs in O(N).
#pragma once

#include "solver/core/Real.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lbdem::solver::dem {

/// Candidate neighbour pairs in compressed rows: row i holds the j > i with
/// |x_i - x_j| < R_i + R_j + skin, in increasing j.
struct PairRows {
    std::vector<std::uint32_t> start; ///< row i is cols[start[i] .. start[i + 1])
    std::vector<std::int32_t> cols;   ///< partner indices j
};

/// A uniform grid of square cells over the bounding box of the discs.
class NeighbourGrid {
public:
    /// Reserve room for n discs (and the most cells the grid uses for them) so builds do not
    /// allocate.
    void reserve(std::size_t n);

    /// Bin n discs into cells of side cellSize (at least the largest contact distance).
    void build(const Real* x, const Real* y, std::size_t n, Real cellSize);

    /// Fill rows with every pair closer than R_i + R_j + skin (cellSize must cover 2 R_max + skin).
    void pairs(const Real* x, const Real* y, const Real* r, Real skin, PairRows& rows) const;

    /// Disc indices ordered cell by cell (row-major in y, then x): a locality-friendly order.
    const std::vector<std::int32_t>& cellOrder() const { return m_items; }

    int cellsX() const { return m_nx; }
    int cellsY() const { return m_ny; }

private:
    int m_nx = 0, m_ny = 0;
    Real m_x0 = 0, m_y0 = 0, m_inv = 1;
    std::vector<std::uint32_t>
        m_cellStart; ///< items of cell c are m_items[m_cellStart[c] .. [c + 1])
    std::vector<std::int32_t> m_items;
    std::vector<std::int32_t> m_cellOf;
};

/// Reference O(N^2) pair search with the same contract as NeighbourGrid::pairs (for tests).
void bruteForcePairs(const Real* x, const Real* y, const Real* r, std::size_t n, Real skin,
                     PairRows& rows);

} // namespace lbdem::solver::dem
