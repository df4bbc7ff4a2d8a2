// The column-collapse scene: packing, walls, gate release, and its snapshot.
#include "solver/scene/ColumnScene.h"
#include "solver/core/Constants.h"

#include "solver/core/InputError.h"
#include "solver/dem/DemGuard.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace lbdem::solver {

namespace {
/// Before release the column settles under the run's gravity until its fastest disc is slower
/// than this [m/s] (the column-at-rest check asks for 1e-4 after 0.5 tau_c in still water) ...
constexpr double kSettledSpeed = 1e-5;
/// ... or for at most this long [s] (a column on a slope steeper than its friction never settles).
constexpr double kMaxSettleTime = 0.5;
/// DEM steps between two speed checks while settling.
constexpr int kSettleCheckSteps = 500;
} // namespace

dem::Material grainMaterial(const GrainSpec& g) {
    dem::Material m;
    m.normal_stiffness = g.normal_stiffness_n_m;
    m.tangential_stiffness = g.tangential_stiffness_n_m;
    m.restitution = g.restitution;
    m.friction = std::tan(g.friction_deg * kPi / 180);
    m.wall_friction = g.wall_friction;
    m.rolling_resistance = g.rolling_resistance;
    m.wall_rolling_resistance = g.wall_rolling_resistance;
    m.contact_torque = g.contact_torque;
    m.density = g.density_kg_m3;
    return m;
}

Vec2 grainGravity(const CaseSpec& spec) {
    const double theta = spec.domain.slope_deg * kPi / 180, g = spec.domain.gravity_m_s2;
    const bool buoyant = spec.fluid.enabled && spec.grains.buoyancy;
    const double buoyancy = buoyant ? 1 - spec.fluid.density_kg_m3 / spec.grains.density_kg_m3 : 1;
    return Vec2(g * std::sin(theta), -g * std::cos(theta)) * buoyancy;
}

dem::PackingRequest packingRequest(const CaseSpec& spec) {
    const GrainSpec& g = spec.grains;
    dem::PackingRequest r;
    r.count = g.count;
    r.d_min = g.d_min_m;
    r.size_ratio = g.size_ratio;
    r.target = g.packing;
    r.aspect_ratio = g.aspect_ratio;
    r.gravity = spec.domain.gravity_m_s2;
    r.material = grainMaterial(g);
    r.seed = static_cast<std::uint64_t>(g.seed);
    return r;
}

ColumnScene::ColumnScene(const CaseSpec& spec, const Plan& plan, const dem::PackingOptions& options)
    : ColumnScene(spec, plan, dem::generatePacking(packingRequest(spec), options)) {}

ColumnScene::ColumnScene(const CaseSpec& spec, const Plan& plan, dem::Packing packing)
    : m_packing(std::move(packing)), m_system(grainMaterial(spec.grains)), m_dt(plan.dem_dt_s),
      m_submerged(spec.fluid.enabled), m_gateReleaseS(spec.run.gate_release_tc * plan.tc_s) {
    build(spec);
}

void ColumnScene::build(const CaseSpec& spec) {
    const double width = spec.domain.width_m, height = spec.domain.height_m;
    if (m_packing.width > width || m_packing.height > height)
        throw InputError(
            "the column (" + std::to_string(m_packing.width) + " m wide, " +
            std::to_string(m_packing.height) + " m high) does not fit the domain (domain.width = " +
            std::to_string(width) + " m, domain.height = " + std::to_string(height) + " m)");
    if (!m_packing.converged)
        throw SimulationError("key 'grains.packing': the packing generator reached " +
                              std::to_string(m_packing.fraction) + " instead of " +
                              std::to_string(m_packing.target) +
                              "; ask for a packing nearer what it reached");
    m_system.reserve(m_packing.x.size());
    m_system.addWall(Vec2(0, 0), Vec2(width, 0));
    m_system.addWall(Vec2(0, 0), Vec2(0, height));
    m_system.addWall(Vec2(width, 0), Vec2(width, height));
    m_gate = m_system.addWall(Vec2(m_packing.width, 0), Vec2(m_packing.width, height));
    for (std::size_t k = 0; k < m_packing.x.size(); ++k)
        m_system.addDisc(m_packing.x[k], m_packing.y[k], m_packing.radius[k]);
    m_system.setGravity(grainGravity(spec));
    settleBeforeRelease();
    m_system.setThreads(spec.run.threads); // 0: OpenMP's default
    // The gate holds the column while it is built and vanishes at t = 0, or later when asked.
    m_system.setWallActive(m_gate, m_gateReleaseS > 0);
    m_system.computeForces();
}

void ColumnScene::settleBeforeRelease() {
    // The generator deposits the column dry under vertical gravity; the run tilts gravity by the
    // slope and, under water, reduces it by buoyancy. Settling against the closed gate under the
    // run's own gravity first makes t = 0 an equilibrium (a submerged column at rest puts its
    // buoyant weight on the floor) instead of a jolt that shakes the column as it is released.
    // One thread: the column must not depend on the run's thread count.
    m_system.setThreads(1);
    m_system.computeForces();
    while (m_system.time() < kMaxSettleTime) {
        for (int k = 0; k < kSettleCheckSteps; ++k)
            m_system.step(m_dt);
        if (m_system.maxSpeed() < kSettledSpeed) break;
    }
    m_settleTime = m_system.time();
    m_system.setClock(0, 0);
}

void ColumnScene::releaseGateWhenDue() {
    if (m_system.walls()[m_gate].active && m_system.time() >= m_gateReleaseS) {
        m_system.setWallActive(m_gate, false);
        m_system.computeForces();
    }
}

void ColumnScene::step() {
    releaseGateWhenDue();
    m_system.step(m_dt);
    dem::checkGrainMotion(m_system.particles(), m_dt, m_system.time());
}

void ColumnScene::advance(double dt, int substeps) {
    releaseGateWhenDue();
    m_system.advance(dt, substeps);
    dem::checkGrainMotion(m_system.particles(), dt / std::max(substeps, 1), m_system.time());
}

void ColumnScene::fillSnapshot(Snapshot& snapshot) const {
    snapshot.step = m_system.stepCount();
    snapshot.time_s = m_system.time();
    fillSnapshotGrains(m_system, m_submerged, snapshot);
}

void fillSnapshotGrains(const dem::DemSystem& system, bool withHydro, Snapshot& snapshot) {
    const dem::Particles& p = system.particles();
    const std::size_t n = p.size();
    SnapshotGrains& g = snapshot.grains;
    auto copy = [n](const std::vector<Real>& from, std::vector<float>& to) {
        to.resize(n);
        for (std::size_t k = 0; k < n; ++k)
            to[k] = static_cast<float>(from[k]);
    };
    copy(p.x, g.x);
    copy(p.y, g.y);
    copy(p.radius, g.radius);
    copy(p.vx, g.vx);
    copy(p.vy, g.vy);
    copy(p.omega, g.omega);
    copy(p.fx, g.fx);
    copy(p.fy, g.fy);
    if (withHydro) {
        copy(p.ext_fx, g.hydro_fx);
        copy(p.ext_fy, g.hydro_fy);
    } else {
        g.hydro_fx.clear();
        g.hydro_fy.clear();
    }
    SnapshotContacts& c = snapshot.contacts;
    c = SnapshotContacts{};
    for (const dem::ContactForce& f : system.contacts()) {
        c.i.push_back(f.i);
        c.j.push_back(f.j);
        c.wx.push_back(static_cast<float>(f.px));
        c.wy.push_back(static_cast<float>(f.py));
        c.normal_force.push_back(static_cast<float>(f.fn));
        c.tangential_force.push_back(static_cast<float>(std::abs(f.ft)));
    }
    snapshot.walls.clear();
    for (const dem::Wall& w : system.walls())
        if (w.active)
            snapshot.walls.push_back({static_cast<float>(w.a.x()), static_cast<float>(w.a.y()),
                                      static_cast<float>(w.b.x()), static_cast<float>(w.b.y())});
}

} // namespace lbdem::solver
