// DemSystem: contact reports, checkpointable contact history and spatial reordering.
#include "solver/dem/DemSystem.h"

#include <algorithm>

namespace lbdem::solver::dem {

std::vector<ContactForce> DemSystem::contacts() const {
    std::vector<ContactForce> out;
    for (std::size_t i = 0; i + 1 < m_rows.start.size(); ++i) {
        for (std::uint32_t k = m_rows.start[i]; k < m_rows.start[i + 1]; ++k) {
            const PairSlot& s = m_slots[k];
            if (s.fn == 0 && s.ft == 0) continue;
            const Real ri = m_p.radius[i], rj = m_p.radius[s.j];
            // Contact point: on the line of centres, splitting the overlap evenly.
            const Real dx = m_p.x[s.j] - m_p.x[i], dy = m_p.y[s.j] - m_p.y[i];
            const Real d = std::max(std::sqrt(dx * dx + dy * dy), Real(1e-300));
            const Real a = (ri + 0.5 * (d - ri - rj)) / d;
            out.push_back({static_cast<std::int32_t>(i), s.j, s.fn, s.ft, m_p.x[i] + a * dx,
                           m_p.y[i] + a * dy});
        }
    }
    for (const WallSlot& s : m_wallSlots)
        if (s.fn != 0 || s.ft != 0) out.push_back({s.i, -1, s.fn, s.ft, s.px, s.py});
    return out;
}

std::vector<ContactHistory> DemSystem::contactHistory() const {
    std::vector<ContactHistory> out;
    for (std::size_t i = 0; i + 1 < m_rows.start.size(); ++i)
        for (std::uint32_t k = m_rows.start[i]; k < m_rows.start[i + 1]; ++k) {
            const PairSlot& s = m_slots[k];
            if (s.ut != 0 || s.ur != 0 || s.fn != 0)
                out.push_back({static_cast<std::int32_t>(i), s.j, false, s.ut, s.ur});
        }
    for (const WallSlot& s : m_wallSlots)
        if (s.ut != 0 || s.ur != 0 || s.fn != 0) out.push_back({s.i, s.wall, true, s.ut, s.ur});
    return out;
}

void DemSystem::restoreContactHistory(const std::vector<ContactHistory>& history) {
    const std::size_t n = m_p.size();
    std::vector<ContactHistory> pairs, walls;
    for (const ContactHistory& h : history)
        (h.is_wall ? walls : pairs).push_back(h);
    auto byIndex = [](const ContactHistory& a, const ContactHistory& b) {
        return a.i < b.i || (a.i == b.i && a.j < b.j);
    };
    std::sort(pairs.begin(), pairs.end(), byIndex);
    std::sort(walls.begin(), walls.end(), byIndex);
    m_oldStart.assign(n + 1, 0);
    m_oldSlots.clear();
    // The springs carry over; the rest of a slot is filled by the next force evaluation.
    for (const ContactHistory& h : pairs) {
        m_oldSlots.push_back(PairSlot{h.j, h.ut, h.ur});
        ++m_oldStart[h.i + 1];
    }
    for (std::size_t i = 0; i < n; ++i)
        m_oldStart[i + 1] += m_oldStart[i];
    m_oldWallSlots.clear();
    for (const ContactHistory& h : walls)
        m_oldWallSlots.push_back(WallSlot{h.i, h.j, h.ut, h.ur});
    m_haveOld = true;
    m_restorePending = true;
    m_rebuild = true;
}

std::vector<std::int32_t> DemSystem::sortSpatially() {
    const std::size_t n = m_p.size();
    Real rmax = 0;
    for (Real r : m_p.radius)
        rmax = std::max(rmax, r);
    NeighbourGrid grid;
    grid.build(m_p.x.data(), m_p.y.data(), n, 2 * rmax);
    const std::vector<std::int32_t> order = grid.cellOrder();
    std::vector<std::int32_t> newIndex(n);
    for (std::size_t k = 0; k < n; ++k)
        newIndex[order[k]] = static_cast<std::int32_t>(k);
    std::vector<ContactHistory> history = contactHistory();
    for (ContactHistory& h : history) {
        h.i = newIndex[h.i];
        if (h.is_wall) continue;
        h.j = newIndex[h.j];
        // Swapping the pair flips n and t together, so the slip keeps its sign; spin flips.
        if (h.i > h.j) {
            std::swap(h.i, h.j);
            h.ur = -h.ur;
        }
    }
    std::vector<Real> tmp(n);
    for (std::vector<Real>* a : m_p.arrays()) {
        for (std::size_t k = 0; k < n; ++k)
            tmp[k] = (*a)[order[k]];
        a->swap(tmp);
    }
    m_refX.clear();
    m_refY.clear();
    restoreContactHistory(history);
    return order;
}

} // namespace lbdem::solver::dem
