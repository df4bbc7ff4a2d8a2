// Permeability of a fixed random disc packing against the hydrodynamic radius (the paper's Figure
// 3).
#include "solver/core/Constants.h"
#include "solver/verification/CouplingVerification.h"

#include "solver/core/InputError.h"
#include "solver/dem/DemSystem.h"
#include "solver/lattice/Collision.h"
#include "solver/lattice/Lattice.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <random>

namespace lbdem::solver {

namespace {

using Clock = std::chrono::steady_clock;

struct Disc {
    Real x, y, r;
};

/// Seeded random sequential addition in a periodic square box of side `side` (lattice units):
/// diameters uniform in [dMin, 1.8 dMin] drawn until their area reaches 60 % of the box, then
/// placed largest first, each at the first of 4000 random positions that overlaps no disc
/// (minimum image); discs that find no place are dropped (with this size spread all find one).
std::vector<Disc> randomPacking(Real dMin, Real side, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<Real> diameter(dMin, 1.8 * dMin), position(0, side);
    std::vector<Real> radii;
    Real area = 0;
    while (area < 0.6 * side * side) {
        radii.push_back(diameter(rng) / 2);
        area += kPi * radii.back() * radii.back();
    }
    std::sort(radii.rbegin(), radii.rend());
    std::vector<Disc> discs;
    for (Real r : radii) {
        for (int attempt = 0; attempt < 4000; ++attempt) {
            const Real x = position(rng), y = position(rng);
            bool free = true;
            for (const Disc& o : discs) {
                Real dx = x - o.x, dy = y - o.y;
                dx -= side * std::round(dx / side);
                dy -= side * std::round(dy / side);
                if (dx * dx + dy * dy < (r + o.r) * (r + o.r)) {
                    free = false;
                    break;
                }
            }
            if (free) {
                discs.push_back({x, y, r});
                break;
            }
        }
    }
    return discs;
}

/// MRT with walls half-way independently of tau (Lambda = 3/16, Ginzburg & d'Humieres 2003).
lattice::LatticeSetup permeabilityLattice(int side, Real tau, Real g) {
    lattice::LatticeSetup s;
    s.nx = s.ny = side;
    s.left.type = s.right.type = s.bottom.type = s.top.type = lattice::SideType::Periodic;
    s.collision.model = lattice::CollisionModel::Mrt;
    s.collision.tau = tau;
    s.collision.s_q = lattice::sqForMagicLambda(tau, lattice::kHalfWayLambda);
    s.fx = g;
    return s;
}

} // namespace

std::vector<PermeabilityPoint> permeabilitySweep(coupling::CouplingMethod method, int nodes,
                                                 int box, const std::vector<double>& ratios) {
    const int side = nodes * box;
    const std::vector<Disc> discs = randomPacking(nodes, side, 20261123);
    Real dMean = 0;
    for (const Disc& d : discs)
        dMean += 2 * d.r;
    dMean /= static_cast<Real>(discs.size());
    const Real tau = 1.0, nu = (tau - 0.5) / 3, g = 1e-6;
    std::vector<PermeabilityPoint> points;
    for (double ratio : ratios) {
        const auto start = Clock::now();
        lattice::Lattice lattice(permeabilityLattice(side, tau, g));
        dem::DemSystem grains;
        for (const Disc& d : discs)
            grains.addDisc(d.x, d.y, d.r);
        coupling::CouplingParams params;
        params.method = method;
        params.hydro_radius_ratio = ratio;
        params.psm_weight = coupling::PsmWeight::Nt;
        const auto link = coupling::makeCoupling(lattice, grains, params);
        // Body-force-driven flow through the fixed packing until the superficial momentum
        // (sum of (1 - solid fraction) rho u_x over the box) changes by < 1e-6 relative per 500
        // steps. Momentum rather than velocity: interpolated bounce-back leaks a little mass, and
        // Darcy's law mu U = K F holds with mu = rho nu whatever the density has drifted to.
        Real u = 0, last = 0;
        for (long long steps = 0; steps < 200000;) {
            for (int k = 0; k < 500; ++k, ++steps) {
                link->mapGrains();
                lattice.step();
                link->collectForces();
            }
            Real sum = 0;
            for (long long c = 0; c < lattice.cells(); ++c) {
                Real ux, uy;
                lattice.velocity(c, ux, uy);
                sum += (1 - link->solidFraction()[c]) * lattice.density(c) * ux;
            }
            u = sum / static_cast<Real>(lattice.cells());
            if (!std::isfinite(u)) break;
            if (steps > 1000 && std::abs(u - last) <= 1e-6 * std::abs(u)) break;
            last = u;
        }
        PermeabilityPoint p;
        p.ratio = ratio;
        Real solid = 0;
        for (const Disc& d : discs)
            solid += kPi * ratio * ratio * d.r * d.r;
        p.porosity = 1 - solid / (static_cast<Real>(side) * side);
        // Darcy: mu U = rho nu U = K F for the body force density F = g (Guo forcing).
        p.k_over_d2 = nu * u / g / (dMean * dMean);
        const Real n = p.porosity;
        p.ck_spheres = n * n * n / (180 * (1 - n) * (1 - n));
        p.ck_cylinders = n * n * n / (80 * (1 - n) * (1 - n));
        p.wall_s = secondsSince(start);
        points.push_back(p);
    }
    return points;
}

void writePermeabilityCsv(const std::string& path, const std::vector<std::string>& methods,
                          const std::vector<std::vector<PermeabilityPoint>>& sweeps) {
    std::ofstream out(path);
    if (!out) throw InputError("cannot write " + path);
    out << "method,hydro_radius_ratio,quasi_porosity,k_over_d2,carman_kozeny_spheres,"
           "carman_kozeny_cylinders,wall_s\n";
    out.precision(8);
    for (std::size_t m = 0; m < methods.size() && m < sweeps.size(); ++m)
        for (const PermeabilityPoint& p : sweeps[m])
            out << methods[m] << ',' << p.ratio << ',' << p.porosity << ',' << p.k_over_d2 << ','
                << p.ck_spheres << ',' << p.ck_cylinders << ',' << p.wall_s << '\n';
}

} // namespace lbdem::solver
