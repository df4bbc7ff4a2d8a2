// Lattice construction: ghost layers, side conditions, wall link lists and macroscopic fields.
#include "solver/lattice/Lattice.h"

#include "solver/core/InputError.h"

#include <cmath>
#include <string>

namespace lbdem::solver::lattice {

namespace {

bool hasGhost(const SideCondition& side) {
    return side.type == SideType::Wall || side.type == SideType::FreeSlip ||
           side.type == SideType::Pressure;
}

bool isZouHe(const SideCondition& side) {
    return side.type == SideType::ZouHeVelocity || side.type == SideType::ZouHePressure;
}

// Corners shared by two ghost sides take the stronger condition: wall > free slip > pressure.
int priority(SideType type) {
    return type == SideType::Wall       ? 3
           : type == SideType::FreeSlip ? 2
           : type == SideType::Pressure ? 1
                                        : 0;
}

int directionOf(int cx, int cy) {
    for (int q = 0; q < kQ; ++q)
        if (kCx[q] == cx && kCy[q] == cy) return q;
    return -1;
}

} // namespace

Lattice::Lattice(const LatticeSetup& setup) : m_setup(setup) {
    const auto& s = m_setup;
    if (s.nx < 2 || s.ny < 2) throw InputError("the lattice needs at least 2 x 2 fluid nodes");
    if ((s.left.type == SideType::Periodic) != (s.right.type == SideType::Periodic) ||
        (s.bottom.type == SideType::Periodic) != (s.top.type == SideType::Periodic))
        throw InputError("a periodic side needs a periodic opposite side");
    if (isZouHe(s.bottom) || isZouHe(s.top))
        throw InputError("Zou-He boundaries are available on the left and right sides only");
    m_ghostLeft = hasGhost(s.left) ? 1 : 0;
    m_ghostBottom = hasGhost(s.bottom) ? 1 : 0;
    m_nx = s.nx + m_ghostLeft + (hasGhost(s.right) ? 1 : 0);
    m_ny = s.ny + m_ghostBottom + (hasGhost(s.top) ? 1 : 0);
    m_offsetX = isZouHe(s.left) ? 0.0 : 0.5;
    m_offsetY = 0.5;
    m_cells = static_cast<long long>(m_nx) * m_ny;
    const auto values = static_cast<std::size_t>(kQ * m_cells);
    if (s.storage == PopulationStorage::Float)
        m_f32.assign(values, 0.0f);
    else
        m_f64.assign(values, 0.0);
    m_flags.assign(static_cast<std::size_t>(m_cells), kFluid);
    m_side.assign(static_cast<std::size_t>(m_cells), -1);
    buildSides();
    buildWallLinks();
    initialise([](Real, Real, Real&, Real&, Real&) {});
}

void Lattice::buildSides() {
    const SideCondition* sides[4] = {&m_setup.left, &m_setup.right, &m_setup.bottom, &m_setup.top};
    auto mark = [&](long long c, int side) {
        const SideType type = sides[side]->type;
        if (m_side[c] >= 0 && priority(sides[m_side[c]]->type) >= priority(type)) return;
        m_side[c] = side;
        m_flags[c] = type == SideType::Pressure ? kPressureGhost : kSolid;
    };
    for (int j = 0; j < m_ny; ++j) {
        if (m_ghostLeft) mark(index(0, j), 0);
        if (hasGhost(m_setup.right)) mark(index(m_nx - 1, j), 1);
    }
    for (int i = 0; i < m_nx; ++i) {
        if (m_ghostBottom) mark(index(i, 0), 2);
        if (hasGhost(m_setup.top)) mark(index(i, m_ny - 1), 3);
    }
    for (long long c = 0; c < m_cells; ++c)
        if (m_flags[c] != kFluid) m_solids.push_back(c);
    for (int j = 0; j < m_ny; ++j) {
        if (isZouHe(m_setup.left) && isFluid(index(0, j))) m_zouHeCells[0].push_back(index(0, j));
        if (isZouHe(m_setup.right) && isFluid(index(m_nx - 1, j)))
            m_zouHeCells[1].push_back(index(m_nx - 1, j));
    }
}

void Lattice::buildWallLinks() {
    const SideCondition* sides[4] = {&m_setup.left, &m_setup.right, &m_setup.bottom, &m_setup.top};
    for (long long c = 0; c < m_cells; ++c) {
        if (!isFluid(c)) continue;
        for (int d = 1; d < kQ; ++d) {
            const long long n = neighbour(c, d);
            if (m_flags[n] == kFluid || m_flags[n] == kObstacle) continue;
            const SideCondition& side = *sides[m_side[n]];
            const int in = kOpposite[d];
            if (side.type == SideType::Pressure) {
                m_pressureLinks.push_back({c, d, side.rho});
                continue;
            }
            // Default: bounce-back, the population leaving c along d returns along in.
            long long sourceNode = c;
            int sourceDir = d;
            Real add = 0;
            if (side.type == SideType::Wall) {
                // Moving wall (Ladd 1994): f_in = f_out + 6 w_in rho_0 (c_in . u_w), rho_0 = 1.
                add = 6.0 * kW[in] * (kCx[in] * side.ux + kCy[in] * side.uy);
            } else {
                // Free slip: the incoming population is the mirror image of one leaving a
                // neighbour along the wall; where that neighbour is not fluid, bounce back.
                const bool horizontal = m_side[n] >= 2;
                const int mirror =
                    horizontal ? directionOf(kCx[in], -kCy[in]) : directionOf(-kCx[in], kCy[in]);
                const int ci = static_cast<int>(c % m_nx), cj = static_cast<int>(c / m_nx);
                const long long from = horizontal ? index((ci - kCx[in] + m_nx) % m_nx, cj)
                                                  : index(ci, (cj - kCy[in] + m_ny) % m_ny);
                if (isFluid(from) && from != c) {
                    sourceNode = from;
                    sourceDir = mirror;
                }
            }
            // The source direction has the incoming one's weight (its opposite or its mirror
            // image), so float storage's shift w_i cancels and the link copies stored values.
            CopyLink link{};
            for (int parity = 0; parity < 2; ++parity) {
                link.slot[parity] = inSlotAt(c, in, parity);
                link.source[parity] = postSlotAt(sourceNode, sourceDir, parity);
            }
            link.add = add;
            m_copyLinks.push_back(link);
        }
    }
}

void Lattice::postSlots(long long cell, long long slots[kQ]) const {
    if (m_step & 1) {
        for (int q = 0; q < kQ; ++q)
            slots[q] = kOpposite[q] * m_cells + cell;
        return;
    }
    postSlots(static_cast<int>(cell % m_nx), static_cast<int>(cell / m_nx), slots);
}

Real Lattice::density(long long cell) const {
    long long slots[kQ];
    postSlots(cell, slots);
    Real rho = 0;
    for (int q = 0; q < kQ; ++q)
        rho += population(slots[q], q);
    return rho;
}

void Lattice::velocity(long long cell, Real& ux, Real& uy) const {
    long long slots[kQ];
    postSlots(cell, slots);
    Real rho = 0, jx = 0, jy = 0;
    for (int q = 0; q < kQ; ++q) {
        const Real v = population(slots[q], q);
        rho += v;
        jx += kCx[q] * v;
        jy += kCy[q] * v;
    }
    ux = (jx - 0.5 * m_setup.fx) / rho;
    uy = (jy - 0.5 * m_setup.fy) / rho;
}

Real Lattice::totalMass() const {
    Real mass = 0;
    for (long long c = 0; c < m_cells; ++c)
        if (isFluid(c)) mass += density(c);
    return mass;
}

void Lattice::resetSolids() {
    // Solid nodes are collided by the branch-free bulk kernel too; resetting them to rest keeps
    // their (unused) values finite. Only the slots the link pass writes are ever read.
#pragma omp parallel for schedule(static) if (m_cells >= kParallelMinCells)
    for (std::size_t k = 0; k < m_solids.size(); ++k) {
        long long slots[kQ];
        postSlots(m_solids[k], slots);
        for (int q = 0; q < kQ; ++q)
            setPopulation(slots[q], q, kW[q]);
    }
}

std::vector<double> Lattice::exportPopulations() const {
    std::vector<double> f(static_cast<std::size_t>(kQ * m_cells));
    for (std::size_t k = 0; k < f.size(); ++k)
        f[k] = population(static_cast<long long>(k), static_cast<int>(k / m_cells));
    return f;
}

void Lattice::importPopulations(const std::vector<double>& f) {
    if (f.size() != static_cast<std::size_t>(kQ * m_cells))
        throw InputError("the populations to import (" + std::to_string(f.size()) +
                         ") do not fit the lattice (" + std::to_string(kQ * m_cells) + ")");
    for (std::size_t k = 0; k < f.size(); ++k)
        setPopulation(static_cast<long long>(k), static_cast<int>(k / m_cells), f[k]);
}

std::vector<double> Lattice::exportStoredValues() const {
    if (m_setup.storage == PopulationStorage::Float)
        return std::vector<double>(m_f32.begin(), m_f32.end());
    return std::vector<double>(m_f64.begin(), m_f64.end());
}

void Lattice::importStoredValues(const std::vector<double>& values) {
    if (values.size() != static_cast<std::size_t>(kQ * m_cells))
        throw InputError("the stored populations to import (" + std::to_string(values.size()) +
                         ") do not fit the lattice (" + std::to_string(kQ * m_cells) + ")");
    if (m_setup.storage == PopulationStorage::Float)
        for (std::size_t k = 0; k < values.size(); ++k)
            m_f32[k] = static_cast<float>(values[k]);
    else
        m_f64.assign(values.begin(), values.end());
}

} // namespace lbdem::solver::lattice
