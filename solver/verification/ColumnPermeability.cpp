// Permeability of a window of fixed discs under a pressure drop, and the window of a column.
#include "solver/verification/ColumnPermeability.h"

#include "solver/core/Constants.h"
#include "solver/core/InputError.h"
#include "solver/dem/DemSystem.h"
#include "solver/lattice/Lattice.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>

namespace lbdem::solver {

namespace {

using Clock = std::chrono::steady_clock;

/// The window, in d_max, centred on the column's bulk (L_i ~ 27 d_max, H_i ~ 22 d_max): long
/// enough for ten mean diameters between the fit part's ends, short enough that the pressure
/// settles in a few thousand steps where the throats are nearly shut (its relaxation time grows
/// as length^2 / K).
constexpr Real kWindowLength = 12, kWindowHeight = 10;
/// The window keeps at least this many d_max from the walls, the floor and H_i: the wall layers
/// pack differently from the bulk.
constexpr Real kWallClearance = 3;
/// The flux and the pressure gradient leave out this many d_max at the inlet and outlet faces.
constexpr Real kFitMargin = 2;
/// Width of the end slabs whose mean pressures give the gradient, in mean diameters.
constexpr Real kSlab = 2;
/// Darcy velocity of the drive, as U d_mean / nu: Darcy's regime (inertia ~ Re^2) by far.
constexpr Real kTargetReynolds = 0.01;

/// Pressure sides left and right (the density of each from the imposed mean gradient), free-slip
/// sides bottom and top.
lattice::LatticeSetup windowLattice(const WindowFlowSetup& s) {
    lattice::LatticeSetup l;
    l.nx = s.nx;
    l.ny = s.ny;
    const Real dropRho = 3 * s.gradient * s.nx; // p = rho c_s^2, c_s^2 = 1/3
    l.left.type = l.right.type = lattice::SideType::Pressure;
    l.left.rho = 1 + dropRho / 2;
    l.right.rho = 1 - dropRho / 2;
    l.bottom.type = l.top.type = lattice::SideType::FreeSlip;
    l.collision = s.collision;
    return l;
}

/// Flux and pressure line of the fit columns at the current step.
struct FitSample {
    Real mass_flux = 0, gradient = 0, fluid_fraction = 0;
    bool finite = true;
};

FitSample sampleFit(const lattice::Lattice& lattice, const std::vector<Real>& solid,
                    const WindowFlowSetup& s) {
    // Intrinsic-average pressure (fluid nodes only) of the two end slabs of the fit part, and the
    // mass flux of every fit column.
    Real flux = 0, fluid = 0, slabRho[2] = {0, 0}, slabWeight[2] = {0, 0};
    int columns = 0;
    const int j0 = lattice.firstFluidY();
    for (int i = lattice.firstFluidX(); i < lattice.firstFluidX() + s.nx; ++i) {
        const Real x = lattice.nodeX(i);
        if (x < s.fit_x0 || x > s.fit_x1) continue;
        const int slab = x <= s.fit_x0 + s.slab ? 0 : x >= s.fit_x1 - s.slab ? 1 : -1;
        Real columnFlux = 0, weight = 0;
        for (int j = j0; j < j0 + s.ny; ++j) {
            const long long c = lattice.index(i, j);
            const Real w = 1 - solid[c];
            if (w <= 0) continue;
            Real ux, uy;
            lattice.velocity(c, ux, uy);
            const Real rho = lattice.density(c);
            columnFlux += w * rho * ux;
            weight += w;
            if (slab >= 0) {
                slabRho[slab] += w * rho;
                slabWeight[slab] += w;
            }
        }
        flux += columnFlux / s.ny;
        fluid += weight / s.ny;
        ++columns;
    }
    FitSample f;
    if (columns < 2 || slabWeight[0] <= 0 || slabWeight[1] <= 0) {
        f.finite = false;
        return f;
    }
    const Real distance = (s.fit_x1 - s.fit_x0) - s.slab; // between the slabs' centres
    f.gradient = (slabRho[0] / slabWeight[0] - slabRho[1] / slabWeight[1]) / 3 / distance;
    f.mass_flux = flux / columns;
    f.fluid_fraction = fluid / columns;
    f.finite = std::isfinite(f.gradient) && std::isfinite(f.mass_flux);
    return f;
}

Real largestSpeed(const lattice::Lattice& lattice, const std::vector<Real>& solid) {
    Real top = 0;
    for (long long c = 0; c < lattice.cells(); ++c) {
        if (!lattice.isFluid(c) || solid[c] >= 1) continue;
        Real ux, uy;
        lattice.velocity(c, ux, uy);
        top = std::max(top, std::hypot(ux, uy));
    }
    return top;
}

} // namespace

WindowFlowResult measureWindowPermeability(const WindowFlowSetup& s) {
    lattice::Lattice lattice(windowLattice(s));
    const Real rhoIn = lattice.setup().left.rho, rhoOut = lattice.setup().right.rho;
    lattice.initialise([&](Real x, Real, Real& rho, Real& ux, Real& uy) {
        rho = rhoIn + (rhoOut - rhoIn) * x / s.nx;
        ux = uy = 0;
    });
    dem::DemSystem grains;
    for (const WindowDisc& d : s.discs)
        grains.addDisc(d.x, d.y, d.r);
    coupling::CouplingParams params; // lattice units: h = dt = rho_f = 1
    params.method = s.method;
    params.hydro_radius_ratio = s.hydro_radius_ratio;
    const auto coupling = coupling::makeCoupling(lattice, grains, params);
    coupling::Coupling& link = *coupling;
    const Real nu = (s.collision.tau - 0.5) / 3;
    WindowFlowResult result;
    Real last = 0, lastChange = 0;
    int quietChecks = 0;
    while (result.steps < s.max_steps) {
        for (int k = 0; k < s.check_steps; ++k, ++result.steps) {
            link.mapGrains();
            lattice.step();
            link.collectForces();
        }
        const FitSample f = sampleFit(lattice, link.solidFraction(), s);
        result.k = nu * f.mass_flux / f.gradient;
        result.mass_flux = f.mass_flux;
        result.fitted_gradient = f.gradient;
        result.fluid_fraction = f.fluid_fraction;
        if (!f.finite || !std::isfinite(result.k)) {
            result.finite = false;
            break;
        }
        // The slowest mode decays geometrically: with successive changes in ratio q, the change
        // still to come is change q / (1 - q). Quiet: that projection is below the tolerance
        // (0 <= q < 0.95, so that noise is not mistaken for a decay), or the change itself is
        // below a hundredth of it. Two quiet checks in a row: a single small change can be a
        // turning point.
        const Real change = result.k - last, q = lastChange != 0 ? change / lastChange : -1;
        result.projected_change =
            q >= 0 && q < 0.95 ? std::abs(change * q / (1 - q)) : std::abs(change) / 0.05;
        const bool quiet = result.projected_change <= s.tolerance * std::abs(result.k) ||
                           std::abs(change) <= 0.01 * s.tolerance * std::abs(result.k);
        quietChecks = quiet ? quietChecks + 1 : 0;
        last = result.k;
        lastChange = change;
        if (result.steps >= s.min_steps && quietChecks >= 2) {
            result.converged = true;
            break;
        }
    }
    result.max_speed = largestSpeed(lattice, link.solidFraction());
    return result;
}

Real discAreaInRectangle(Real cx, Real cy, Real r, Real x0, Real x1, Real y0, Real y1) {
    const Real a = std::max(cx - r, x0), b = std::min(cx + r, x1);
    if (a >= b || cy - r >= y1 || cy + r <= y0) return 0;
    // Midpoint rule over the chords; 512 strips give the area to ~1e-5 of the disc's.
    constexpr int kStrips = 512;
    const Real dx = (b - a) / kStrips;
    Real area = 0;
    for (int k = 0; k < kStrips; ++k) {
        const Real x = a + (k + 0.5) * dx,
                   half = std::sqrt(std::max(Real(0), r * r - (x - cx) * (x - cx)));
        area += std::max(Real(0), std::min(cy + half, y1) - std::max(cy - half, y0)) * dx;
    }
    return area;
}

ColumnWindow columnWindow(const dem::Packing& packing, Real length, Real height, Real fitMargin,
                          Real hydroRatio) {
    ColumnWindow w;
    Real rMax = 0;
    for (Real r : packing.radius)
        rMax = std::max(rMax, r);
    const Real dMax = 2 * rMax;
    w.x0 = (packing.width - length * dMax) / 2;
    w.x1 = w.x0 + length * dMax;
    w.y0 = (packing.height - height * dMax) / 2;
    w.y1 = w.y0 + height * dMax;
    w.fit_x0 = w.x0 + fitMargin * dMax;
    w.fit_x1 = w.x1 - fitMargin * dMax;
    if (w.x0 < kWallClearance * dMax || w.y0 < kWallClearance * dMax ||
        w.fit_x1 - w.fit_x0 < 4 * dMax)
        throw SimulationError("the column is too small for a permeability window of " +
                              std::to_string(length) + " x " + std::to_string(height) + " d_max " +
                              std::to_string(kWallClearance) + " d_max inside its walls");
    Real solid = 0, quasi = 0, dSum = 0;
    int centred = 0;
    for (std::size_t p = 0; p < packing.radius.size(); ++p) {
        const Real x = packing.x[p], y = packing.y[p], r = packing.radius[p];
        const Real nearX = std::clamp(x, w.x0, w.x1), nearY = std::clamp(y, w.y0, w.y1);
        if (std::hypot(x - nearX, y - nearY) >= r) continue;
        w.x.push_back(x);
        w.y.push_back(y);
        w.r.push_back(r);
        solid += discAreaInRectangle(x, y, r, w.fit_x0, w.fit_x1, w.y0, w.y1);
        quasi += discAreaInRectangle(x, y, hydroRatio * r, w.fit_x0, w.fit_x1, w.y0, w.y1);
        if (x >= w.fit_x0 && x <= w.fit_x1 && y >= w.y0 && y <= w.y1) {
            dSum += 2 * r;
            w.d_max = std::max(w.d_max, 2 * r);
            ++centred;
        }
    }
    const Real area = (w.fit_x1 - w.fit_x0) * (w.y1 - w.y0);
    w.solid_fraction = solid / area;
    w.quasi_porosity = 1 - quasi / area;
    w.d_mean = dSum / std::max(centred, 1);
    return w;
}

ColumnPermeabilityPoint columnPermeability(const CaseSpec& spec, const dem::Packing& packing,
                                           const std::string& packingName, double resolution,
                                           coupling::CouplingMethod method,
                                           lattice::CollisionParams collision) {
    const auto start = Clock::now();
    const Real ratio = spec.coupling.hydro_radius_ratio;
    const ColumnWindow w = columnWindow(packing, kWindowLength, kWindowHeight, kFitMargin, ratio);
    const Real h = spec.grains.d_min_m / resolution, buffer = w.d_max;
    const Real left = w.x0 - buffer;
    WindowFlowSetup s;
    s.nx = static_cast<int>(std::lround((w.x1 - w.x0 + 2 * buffer) / h));
    s.ny = static_cast<int>(std::lround((w.y1 - w.y0) / h));
    for (std::size_t p = 0; p < w.r.size(); ++p)
        s.discs.push_back({(w.x[p] - left) / h, (w.y[p] - w.y0) / h, w.r[p] / h});
    s.collision = collision;
    s.method = method;
    s.hydro_radius_ratio = ratio;
    s.fit_x0 = (w.fit_x0 - left) / h;
    s.fit_x1 = (w.fit_x1 - left) / h;
    s.slab = kSlab * w.d_mean / h;
    // Drive at a Darcy velocity of Reynolds number kTargetReynolds (U d_mean / nu), estimated
    // with the sphere Carman-Kozeny K: deep in the Darcy regime whatever K turns out to be.
    const Real n = w.quasi_porosity, dMean = w.d_mean / h, nu = (collision.tau - 0.5) / 3;
    const Real ckSpheres = n * n * n / (180 * (1 - n) * (1 - n));
    const Real speed = kTargetReynolds * nu / dMean;
    s.gradient = nu * speed / (ckSpheres * dMean * dMean);
    const WindowFlowResult r = measureWindowPermeability(s);
    ColumnPermeabilityPoint p;
    p.packing = packingName;
    p.method = enumWord(method);
    p.collision = enumWord(collision.model);
    p.s_q = collision.s_q;
    p.resolution = resolution;
    p.nx = s.nx;
    p.ny = s.ny;
    p.solid_fraction = w.solid_fraction;
    p.quasi_porosity = n;
    p.lattice_porosity = r.fluid_fraction;
    p.k_over_dmean2 = r.k / (dMean * dMean);
    p.k_over_dmin2 = r.k / (resolution * resolution);
    p.ck_spheres = ckSpheres;
    p.ck_cylinders = n * n * n / (80 * (1 - n) * (1 - n));
    p.k_m2 = r.k * h * h;
    p.reynolds = r.mass_flux / n * dMean / nu;
    p.max_speed_lattice = r.max_speed;
    p.projected_change = r.projected_change / r.k;
    p.steps = r.steps;
    p.converged = r.converged;
    p.finite = r.finite;
    p.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
    return p;
}

void writeColumnPermeabilityCsv(const std::string& path,
                                const std::vector<ColumnPermeabilityPoint>& points) {
    std::ofstream out(path);
    if (!out) throw InputError("cannot write " + path);
    out << "packing,method,collision,s_q,resolution,nx,ny,solid_fraction,quasi_porosity,"
           "lattice_porosity,k_over_dmean2,k_over_dmin2,carman_kozeny_spheres,"
           "carman_kozeny_cylinders,k_m2,pore_reynolds,max_speed_lattice,steps,projected_change,"
           "converged,wall_s\n";
    out.precision(6);
    for (const ColumnPermeabilityPoint& p : points)
        out << p.packing << ',' << p.method << ',' << p.collision << ',' << p.s_q << ','
            << p.resolution << ',' << p.nx << ',' << p.ny << ',' << p.solid_fraction << ','
            << p.quasi_porosity << ',' << p.lattice_porosity << ',' << p.k_over_dmean2 << ','
            << p.k_over_dmin2 << ',' << p.ck_spheres << ',' << p.ck_cylinders << ',' << p.k_m2
            << ',' << p.reynolds << ',' << p.max_speed_lattice << ',' << p.steps << ','
            << p.projected_change << ',' << (p.converged ? 1 : 0) << ',' << p.wall_s << '\n';
}

} // namespace lbdem::solver
