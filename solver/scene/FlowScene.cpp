// Flow scene builders: lattice set-up, initial state, stepping and SI snapshots.
#include "solver/scene/FlowScene.h"
#include "solver/core/Constants.h"

#include "solver/scene/FluidFields.h"

#include "solver/core/InputError.h"
#include "solver/lattice/D2Q9.h"

#include <algorithm>
#include <cmath>

namespace lbdem::solver {

namespace {

lattice::LatticeSetup flowSetup(const CaseSpec& spec, SceneKind kind, const FlowScales& s) {
    using lattice::SideType;
    lattice::LatticeSetup setup;
    setup.nx = s.nx;
    setup.ny = s.ny;
    setup.collision = collisionOf(spec, s.tau);
    setup.storage = spec.fluid.storage;
    switch (kind) {
    case SceneKind::Poiseuille: {
        // Body-force channel: F = 8 nu U / H^2 gives centreline velocity U between walls H apart.
        setup.left.type = setup.right.type = SideType::Periodic;
        const double height = s.ny;
        setup.fx = 8.0 * s.nu_lattice * s.u_peak / (height * height);
        break;
    }
    case SceneKind::TaylorGreen:
        setup.left.type = setup.right.type = setup.bottom.type = setup.top.type =
            SideType::Periodic;
        break;
    case SceneKind::Cavity:
        setup.top.ux = s.u_peak; // the lid moves to +x; the other walls rest
        break;
    case SceneKind::Cylinder: {
        // Schäfer & Turek (1996): parabolic inflow 4 U_max y (H - y) / H^2, zero-pressure outlet.
        setup.left.type = SideType::ZouHeVelocity;
        setup.right.type = SideType::ZouHePressure;
        setup.right.rho = 1.0;
        const double height = s.ny;
        for (int j = 0; j < s.ny; ++j) {
            const double y = j + 0.5;
            setup.left.profile.push_back(4.0 * s.u_peak * y * (height - y) / (height * height));
        }
        break;
    }
    default:
        throw InputError(std::string("scene '") + enumWord(spec.scene) + "' is not a flow scene");
    }
    return setup;
}

} // namespace

FlowScene::FlowScene(const CaseSpec& spec, const Plan& plan)
    : m_spec(spec), m_kind(spec.scene), m_scales(flowScales(spec)),
      m_lattice(flowSetup(spec, m_kind, m_scales)),
      m_guard(plan.h_m > 0 ? plan.h_m : m_scales.h_m) {
    const FlowScales& s = m_scales;
    if (m_kind == SceneKind::TaylorGreen) {
        // u = -U cos kx sin ky, v = U sin kx cos ky, p = -rho U^2 (cos 2kx + cos 2ky) / 4.
        const double k = 2 * kPi / s.nx, u0 = s.u_peak;
        m_lattice.initialise([=](double x, double y, double& rho, double& ux, double& uy) {
            ux = -u0 * std::cos(k * x) * std::sin(k * y);
            uy = u0 * std::sin(k * x) * std::cos(k * y);
            rho = 1.0 - 3.0 * u0 * u0 / 4.0 * (std::cos(2 * k * x) + std::cos(2 * k * y));
        });
        m_referenceStep = std::max<long long>(1, s.steps / 5);
    } else if (m_kind == SceneKind::Cylinder) {
        const double d = m_spec.flow.nodes;
        // Centre at (0.2 m, 0.2 m) = (2 D, 2 D) from the inlet and the bottom wall.
        m_obstacle = m_lattice.addDisc(2.0 * d, 2.0 * d, 0.5 * d);
        const double height = s.ny, umax = s.u_peak;
        m_lattice.initialise([=](double, double y, double& rho, double& ux, double& uy) {
            rho = 1.0;
            ux = 4.0 * umax * y * (height - y) / (height * height);
            uy = 0.0;
        });
    }
}

void FlowScene::step() {
    m_lattice.step();
    if (m_guard.due(m_lattice.stepCount())) m_guard.check(m_lattice);
    if (m_kind == SceneKind::TaylorGreen && m_lattice.stepCount() == m_referenceStep)
        m_referenceAmplitude = taylorGreenAmplitude();
}

void FlowScene::advance(long long n) {
    for (long long k = 0; k < n; ++k)
        step();
}

void FlowScene::runToEnd() {
    advance(m_scales.steps - stepCount());
    m_guard.check(m_lattice);
}

void FlowScene::fillSnapshot(SnapshotFluid& out, int downsample) const {
    m_guard.check(m_lattice); // no output from a diverged state
    const LatticeScales scales{m_scales.nx, m_scales.ny, m_scales.h_m, m_scales.dt_s,
                               m_spec.fluid.density_kg_m3};
    fillFluidSnapshot(m_lattice, scales, downsample, nullptr, out);
}

void FlowScene::velocityAt(double x, double y, double& ux, double& uy) const {
    const auto& lat = m_lattice;
    const double fi = x - lat.nodeX(0), fj = y - lat.nodeY(0);
    const int i = std::clamp(static_cast<int>(std::floor(fi)), 0, lat.nx() - 2);
    const int j = std::clamp(static_cast<int>(std::floor(fj)), 0, lat.ny() - 2);
    const double tx = fi - i, ty = fj - j;
    ux = uy = 0;
    const double weights[4] = {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty};
    const long long cells[4] = {lat.index(i, j), lat.index(i + 1, j), lat.index(i, j + 1),
                                lat.index(i + 1, j + 1)};
    for (int k = 0; k < 4; ++k) {
        if (!lat.isFluid(cells[k])) continue; // solid nodes count as resting walls
        double a, b;
        lat.velocity(cells[k], a, b);
        ux += weights[k] * a;
        uy += weights[k] * b;
    }
}

double FlowScene::densityAt(double x, double y) const {
    const auto& lat = m_lattice;
    const double fi = x - lat.nodeX(0), fj = y - lat.nodeY(0);
    const int i = std::clamp(static_cast<int>(std::floor(fi)), 0, lat.nx() - 2);
    const int j = std::clamp(static_cast<int>(std::floor(fj)), 0, lat.ny() - 2);
    const double tx = fi - i, ty = fj - j;
    const double weights[4] = {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty};
    const long long cells[4] = {lat.index(i, j), lat.index(i + 1, j), lat.index(i, j + 1),
                                lat.index(i + 1, j + 1)};
    double rho = 0, weight = 0;
    for (int k = 0; k < 4; ++k) {
        if (!lat.isFluid(cells[k])) continue;
        rho += weights[k] * lat.density(cells[k]);
        weight += weights[k];
    }
    return weight > 0 ? rho / weight : 1.0;
}

} // namespace lbdem::solver
