// Lattice-to-SI field conversion for snapshots.
#include "solver/scene/FluidFields.h"

#include "solver/diagnostics/GridNoise.h"
#include "solver/lattice/Collision.h"

#include <algorithm>
#include <cstdint>

namespace lbdem::solver {

lattice::CollisionParams collisionOf(const CaseSpec& spec, double tau) {
    lattice::CollisionParams p;
    p.model = spec.fluid.collision;
    p.tau = tau;
    p.s_e = spec.fluid.s_e;
    p.s_eps = spec.fluid.s_eps;
    const bool everywhere = spec.fluid.magic_lambda > 0 && !spec.fluid.magic_lambda_links_only;
    p.s_q = everywhere ? lattice::sqForMagicLambda(tau, spec.fluid.magic_lambda) : spec.fluid.s_q;
    p.smagorinsky = spec.fluid.smagorinsky;
    return p;
}

void fillFluidSnapshot(const lattice::Lattice& lat, const LatticeScales& scales, int downsample,
                       const std::vector<Real>* solidFraction, SnapshotFluid& out) {
    const int step = std::max(downsample, 1);
    const int i0 = lat.firstFluidX(), j0 = lat.firstFluidY();
    const int nx = (scales.nx + step - 1) / step, ny = (scales.ny + step - 1) / step;
    const double velocityScale = scales.h_m / scales.dt_s;
    const double pressureScale = scales.rho_kg_m3 * velocityScale * velocityScale;
    out = SnapshotFluid{};
    out.nx = nx;
    out.ny = ny;
    out.spacing_m = static_cast<float>(scales.h_m * step);
    out.origin_x = static_cast<float>(lat.nodeX(i0) * scales.h_m);
    out.origin_y = static_cast<float>(lat.nodeY(j0) * scales.h_m);
    const std::size_t n = static_cast<std::size_t>(nx) * ny;
    out.ux.resize(n);
    out.uy.resize(n);
    out.pressure.resize(n);
    out.vorticity.resize(n);
    out.solid.resize(n);
    auto velocity = [&](int i, int j, double& ux, double& uy) {
        const long long c = lat.index(i, j);
        ux = uy = 0;
        if (lat.isFluid(c)) lat.velocity(c, ux, uy);
    };
    for (int b = 0; b < ny; ++b)
        for (int a = 0; a < nx; ++a) {
            const int i = i0 + a * step, j = j0 + b * step;
            const long long c = lat.index(i, j);
            const std::size_t k = static_cast<std::size_t>(b) * nx + a;
            double ux, uy;
            velocity(i, j, ux, uy);
            const bool fluid = lat.isFluid(c);
            out.ux[k] = static_cast<float>(ux * velocityScale);
            out.uy[k] = static_cast<float>(uy * velocityScale);
            out.pressure[k] =
                fluid ? static_cast<float>((lat.density(c) - 1.0) * lattice::kCs2 * pressureScale)
                      : 0.f;
            out.solid[k] =
                solidFraction ? static_cast<float>((*solidFraction)[c]) : (fluid ? 0.f : 1.f);
            // Central differences (one-sided at the domain edge), lattice units -> 1/s.
            const int im = std::max(i - 1, i0), ip = std::min(i + 1, i0 + scales.nx - 1);
            const int jm = std::max(j - 1, j0), jp = std::min(j + 1, j0 + scales.ny - 1);
            double uxA, uyA, uxB, uyB, uxC, uyC, uxD, uyD;
            velocity(ip, j, uxA, uyA);
            velocity(im, j, uxB, uyB);
            velocity(i, jp, uxC, uyC);
            velocity(i, jm, uxD, uyD);
            const double dvdx = (uyA - uyB) / std::max(ip - im, 1),
                         dudy = (uxC - uxD) / std::max(jp - jm, 1);
            out.vorticity[k] = static_cast<float>((dvdx - dudy) / scales.dt_s);
        }
}

double fluidGridNoise(const lattice::Lattice& lat, const std::vector<Real>* solidFraction) {
    const auto cells = static_cast<std::size_t>(lat.cells());
    std::vector<double> ux(cells, 0.0), uy(cells, 0.0);
    std::vector<std::uint8_t> solid(cells, 0);
#pragma omp parallel for schedule(static)
    for (long long c = 0; c < lat.cells(); ++c) {
        const auto k = static_cast<std::size_t>(c);
        if (lat.isFluid(c) && !(solidFraction && (*solidFraction)[k] > 0))
            lat.velocity(c, ux[k], uy[k]);
        else
            solid[k] = 1;
    }
    // Ghost layers are solid nodes; a periodic side has none and wraps, a Zou-He column is the
    // lattice's edge, beyond which the measure counts solid.
    const GridNoiseField field{lat.nx(),
                               lat.ny(),
                               ux.data(),
                               uy.data(),
                               solid.data(),
                               lat.setup().left.type == lattice::SideType::Periodic,
                               lat.setup().bottom.type == lattice::SideType::Periodic};
    return gridNoise(field).share;
}

} // namespace lbdem::solver
