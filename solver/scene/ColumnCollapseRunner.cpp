// The column collapse as a SceneRunner: DEM column, optional lattice and coupling, diagnostics.
#include "solver/scene/ColumnCollapseRunner.h"
#include "solver/core/Constants.h"
#include "solver/core/InputError.h"

#include "solver/coupling/Coupling.h"
#include "solver/dem/DemGuard.h"
#include "solver/diagnostics/MassDiagnostics.h"
#include "solver/diagnostics/MassOutline.h"
#include "solver/lattice/AbsorbingLayer.h"
#include "solver/lattice/EnergyFluxRelaxation.h"
#include "solver/lattice/FluidMotion.h"
#include "solver/lattice/StabilityGuard.h"
#include "solver/scene/ColumnScene.h"
#include "solver/scene/ColumnState.h"
#include "solver/scene/FluidFields.h"
#include "solver/scene/LatticeState.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

namespace lbdem::solver {

namespace {

/// Two discs touch while their gap is below this fraction of d_min. The main mass links discs
/// across gaps up to one largest diameter d_max (see mainMass): a lone disc parting from or
/// rejoining a chain then moves the front by at most its own diameter plus a contact gap.
constexpr double kContactGapOfDmin = 0.05;
/// The front window (flowing front layer, base stress) spans this many mean diameters behind the
/// front.
constexpr double kFrontLengthInDiameters = 15.0;
/// Failure-plane probe: from the gate's foot at this angle to the slope [deg] (Rankine active
/// wedge 45 + phi/2 for phi = 26 deg), sampled at this many points.
constexpr double kFailurePlaneDeg = 58.0;
constexpr int kProbePoints = 64;
/// The far field of the acoustic-noise measure starts this many column widths from the column.
constexpr double kFarFieldWidths = 2.0;

lattice::LatticeSetup columnLatticeSetup(const CaseSpec& spec, const Plan& plan) {
    lattice::LatticeSetup setup;
    setup.nx = plan.nx;
    setup.ny = plan.ny;
    setup.collision = collisionOf(spec, plan.tau);
    setup.storage = spec.fluid.storage;
    setup.left.type = setup.bottom.type = lattice::SideType::Wall; // no-slip floor and back wall
    setup.top.type = spec.domain.top;
    setup.right.type = spec.domain.right;
    if (setup.right.type == lattice::SideType::Periodic)
        setup.left.type = lattice::SideType::Periodic;
    return setup;
}

lattice::AbsorbingLayerSetup absorbingLayerSetup(const CaseSpec& spec) {
    lattice::AbsorbingLayerSetup layer;
    layer.nodes = spec.domain.absorbing_layer_nodes;
    layer.strength = spec.domain.absorbing_layer_strength;
    layer.rho = lattice::SideCondition{}.rho; // the pressure sides' density
    return layer;
}

coupling::CouplingParams couplingParams(const CaseSpec& spec, const Plan& plan) {
    coupling::CouplingParams p;
    p.method = spec.coupling.method;
    p.psm_weight = spec.coupling.psm_weight;
    p.hydro_radius_ratio = spec.coupling.hydro_radius_ratio;
    p.refill = spec.coupling.refill;
    p.link_mass_correction = spec.coupling.link_mass_correction;
    p.h = plan.h_m;
    p.dt = plan.dt_s;
    p.rho_f = spec.fluid.density_kg_m3;
    return p;
}

GrainArrays viewOf(const dem::Particles& p) {
    return {p.size(),    p.x.data(),     p.y.data(),    p.radius.data(), p.vx.data(),
            p.vy.data(), p.omega.data(), p.mass.data(), p.inertia.data()};
}

class ColumnCollapseRunner final : public SceneRunner {
public:
    ColumnCollapseRunner(const CaseSpec& spec, const Plan& plan)
        : m_spec(spec), m_plan(plan), m_column(spec, plan) {
        const double dMean = spec.grains.d_min_m * (1 + spec.grains.size_ratio) / 2;
        m_params.contact_gap_m = kContactGapOfDmin * spec.grains.d_min_m;
        // The hole a lone disc leaves in a touching chain: its diameter plus two contact gaps.
        m_params.bridge_gap_m =
            spec.grains.d_min_m * spec.grains.size_ratio + 2 * m_params.contact_gap_m;
        m_params.column_width_m = m_column.initialWidth();
        m_params.slope_rad = spec.domain.slope_deg * kPi / 180;
        m_params.gravity_m_s2 = spec.domain.gravity_m_s2;
        m_params.grain_density = spec.grains.density_kg_m3;
        m_params.fluid_density = plan.has_fluid ? spec.fluid.density_kg_m3 : 0;
        m_params.bin_width_m = dMean;
        m_params.front_length_m = kFrontLengthInDiameters * dMean;
        // E_p0 = sum m g h with the full gravity and h normal to the slope base, dry and
        // submerged alike, so that E_k / E_p0 compares (Kumar's thesis).
        m_params.initial_potential_j_m = initialPotential();
        if (plan.has_fluid) {
            m_lattice.emplace(columnLatticeSetup(spec, plan));
            m_coupling =
                coupling::makeCoupling(*m_lattice, m_column.system(), couplingParams(spec, plan));
            m_layer.emplace(*m_lattice, absorbingLayerSetup(spec));
            m_guard.emplace(plan.h_m);
            if (spec.fluid.magic_lambda_links_only && spec.fluid.magic_lambda > 0) {
                const double linkSq = lattice::sqForMagicLambda(plan.tau, spec.fluid.magic_lambda);
                m_linkFluxFactor = lattice::energyFluxFactor(spec.fluid.s_q, linkSq);
                m_wallLinkCells = wallLinkCells(*m_lattice);
                m_linkMark.assign(static_cast<std::size_t>(m_lattice->cells()), 0);
            }
        }
    }

    void step(StageTimer& timer) override {
        auto t = StageTimer::Clock::now();
        if (!m_lattice) {
            m_column.step();
            timer.lap(Stage::DemSubsteps, t);
            return;
        }
        m_coupling->mapGrains();
        t = timer.lap(Stage::MapGrains, t);
        m_lattice->step();
        if (m_linkFluxFactor != 0) relaxLinkNodes();
        t = timer.lap(Stage::StreamCollide, t);
        m_coupling->collectForces();
        t = timer.lap(Stage::HydrodynamicForces, t);
        // After the loads: they read this step's post-collision populations as the kernel left
        // them.
        m_layer->apply(*m_lattice);
        t = timer.lap(Stage::Boundaries, t);
        // After collectForces: covered nodes hold leftovers of the bulk kernel until then.
        if (m_guard->due(m_lattice->stepCount())) m_guard->check(*m_lattice);
        t = timer.lap(Stage::Diagnostics, t);
        try {
            m_column.advance(m_plan.dt_s, m_plan.substeps);
        } catch (const SimulationError&) {
            // Grains fed by a fluid that diverged since the guard's last check fail first: name
            // the fluid's failure (node, position, cause) rather than the DEM step.
            m_guard->check(*m_lattice);
            throw;
        }
        timer.lap(Stage::DemSubsteps, t);
    }

    double time() const override { return m_column.time(); }

    void fillSnapshot(Snapshot& snapshot, int downsample) const override {
        m_column.fillSnapshot(snapshot);
        const GrainArrays grains = viewOf(m_column.system().particles());
        MassOutlineParams outline;
        outline.length_m = m_params.bin_width_m; // one mean diameter
        const auto main = mainMass(grains, m_params.contact_gap_m, m_params.bridge_gap_m);
        for (const auto& [x, y] : massOutline(grains, main, outline))
            snapshot.outline.emplace_back(float(x), float(y));
        if (m_lattice) {
            m_guard->check(*m_lattice); // no output from a diverged state
            snapshot.fluid.emplace();
            const LatticeScales scales{m_plan.nx, m_plan.ny, m_plan.h_m, m_plan.dt_s,
                                       m_spec.fluid.density_kg_m3};
            fillFluidSnapshot(*m_lattice, scales, downsample, &m_coupling->solidFraction(),
                              *snapshot.fluid);
            snapshot.probes["pore_pressure_failure_plane"] = failurePlaneProbe();
        }
    }

    void addMetrics(std::map<std::string, double>& m) const override {
        const auto& particles = m_column.system().particles();
        const auto d = computeMassDiagnostics(viewOf(particles), m_params);
        m["runout_m"] = d.front_x_m;
        m["runout_normalised"] = d.runout_normalised;
        m["height_m"] = d.height_m;
        m["height_normalised"] =
            m_column.initialHeight() > 0 ? d.height_m / m_column.initialHeight() : 0;
        m["kinetic_energy_j_m"] = d.kinetic_energy_j_m;
        m["ke_over_ep0"] = d.ke_over_ep0;
        m["packing_fraction"] = d.packing_fraction;
        m["front_velocity_m_s"] = d.front_velocity_m_s;
        m["front_thickness_m"] = d.front_thickness_m;
        m["main_mass_grains"] = static_cast<double>(d.main_mass_grains);
        m["max_grain_speed_m_s"] = m_column.system().maxSpeed();
        m["base_normal_stress_front_pa"] = baseStressAtFront(d.front_x_m);
        m["floor_normal_force_n_m"] = floorNormalForce();
        m["wall_support_normal_n_m"] = wallSupportNormal();
        if (m_lattice) {
            m["froude_densimetric"] = d.froude_densimetric;
            m["pore_pressure_failure_plane_pa"] = failurePlanePressure();
            const FarFieldRatios farField = farFieldRatios();
            m["far_field_speed_ratio"] = farField.speed;
            m["far_field_acoustic_ratio"] = farField.acoustic;
            m["fluid_grid_noise"] = fluidGridNoise(*m_lattice, &m_coupling->solidFraction());
        }
    }

    void save(StateArchive& archive) const override {
        saveColumnState(m_column, archive);
        if (!m_lattice) return;
        saveLatticeState(*m_lattice, archive);
        const auto state = m_coupling->state();
        archive.integers["coupling/cells"].assign(state.cells.begin(), state.cells.end());
        archive.integers["coupling/grains"].assign(state.grains.begin(), state.grains.end());
        archive.integers["coupling/initialised"] = {state.initialised ? 1 : 0};
        archive.reals["coupling/previous_loads"] = state.previous_loads;
    }

    void restore(const StateArchive& archive) override {
        restoreColumnState(archive, m_column);
        dem::checkRestoredGrains(m_column.system().particles(), m_spec.domain.width_m,
                                 m_spec.domain.height_m);
        if (!m_lattice) return;
        restoreLatticeState(archive, *m_lattice);
        coupling::CouplingState state;
        const auto& cells = archive.integer("coupling/cells");
        const auto& grains = archive.integer("coupling/grains");
        state.cells.assign(cells.begin(), cells.end());
        state.grains.assign(grains.begin(), grains.end());
        state.initialised = archive.integer("coupling/initialised").at(0) != 0;
        if (archive.reals.count("coupling/previous_loads")) // absent in older checkpoints
            state.previous_loads = archive.real("coupling/previous_loads");
        m_coupling->restore(state);
    }

private:
    /// Fluid nodes next to a wall (a solid ghost node), where the floor's and walls' links write.
    static std::vector<long long> wallLinkCells(const lattice::Lattice& lat) {
        std::vector<long long> cells;
        const std::uint8_t* flags = lat.flags();
        for (int j = 0; j < lat.ny(); ++j)
            for (int i = 0; i < lat.nx(); ++i) {
                if (flags[lat.index(i, j)] != lattice::Lattice::kFluid) continue;
                bool nearWall = false;
                for (int q = 1; q < lattice::kQ; ++q) {
                    const int in = (i + lattice::kCx[q] + lat.nx()) % lat.nx();
                    const int jn = (j + lattice::kCy[q] + lat.ny()) % lat.ny();
                    nearWall = nearWall || flags[lat.index(in, jn)] == lattice::Lattice::kSolid;
                }
                if (nearWall) cells.push_back(lat.index(i, j));
            }
        return cells;
    }

    /// fluid.magic_lambda_links_only: the nodes the links of this step write into (grains' and
    /// walls', each once, none a grain covers) get the energy flux of magic_lambda's s_q.
    void relaxLinkNodes() {
        m_linkCells.clear();
        m_coupling->linkedFluidCells(m_linkCells);
        m_linkCells.insert(m_linkCells.end(), m_wallLinkCells.begin(), m_wallLinkCells.end());
        const auto& solid = m_coupling->solidFraction();
        std::size_t kept = 0;
        for (const long long cell : m_linkCells) {
            auto& mark = m_linkMark[static_cast<std::size_t>(cell)];
            if (mark || solid[static_cast<std::size_t>(cell)] > 0) continue;
            mark = 1;
            m_linkCells[kept++] = cell;
        }
        m_linkCells.resize(kept);
        lattice::rescaleEnergyFlux(*m_lattice, m_linkCells, m_linkFluxFactor);
        for (const long long cell : m_linkCells)
            m_linkMark[static_cast<std::size_t>(cell)] = 0;
    }

    double initialPotential() const {
        return potentialEnergy(viewOf(m_column.system().particles()), m_spec.domain.gravity_m_s2);
    }

    /// Total grain-floor normal force [N/m]: at rest, the column's weight normal to the slope
    /// (buoyant weight when submerged) less what wall friction carries.
    double floorNormalForce() const {
        double force = 0;
        for (const auto& c : m_column.system().contacts())
            if (c.j < 0 && c.py < 1e-9) force += c.fn;
        return force;
    }

    /// Force normal to the floor that all walls exert on the grains [N/m]: the floor's normal
    /// force plus the friction of the back wall and the gate. At rest it balances the column's
    /// weight normal to the slope (buoyant weight when submerged) with the fluid carrying none;
    /// the floor alone does not, since frictional side walls carry part of it (Janssen).
    double wallSupportNormal() const {
        const auto& p = m_column.system().particles();
        double force = 0;
        for (const auto& c : m_column.system().contacts()) {
            if (c.j >= 0) continue;
            const double dx = c.px - p.x[c.i], dy = c.py - p.y[c.i], d = std::hypot(dx, dy);
            if (d > 0)
                force -= (c.fn * dy + c.ft * dx) / d; // y-force on the disc (wall contact law)
        }
        return force;
    }

    /// Grain-floor normal force per unit length over the front region [Pa per unit thickness].
    double baseStressAtFront(double front) const {
        double force = 0;
        for (const auto& c : m_column.system().contacts())
            if (c.j < 0 && c.py < 1e-9 && c.px > front - m_params.front_length_m) force += c.fn;
        return force / m_params.front_length_m;
    }

    /// Excess pore pressure [Pa] at kProbePoints points along the failure plane of the initial
    /// column: from the gate's foot up the slope at kFailurePlaneDeg until it meets the back wall
    /// or the column's top; NaN where the point's node is not fluid or lies inside a grain (solid
    /// fraction of at least one half: a covered node's density is not a pore pressure).
    SnapshotProbe failurePlaneProbe() const {
        const double angle = kFailurePlaneDeg * kPi / 180;
        const double width = m_column.initialWidth(), height = m_column.initialHeight();
        const double length = std::min(width / std::cos(angle), height / std::sin(angle));
        const double scale =
            m_spec.fluid.density_kg_m3 * lattice::kCs2 * std::pow(m_plan.h_m / m_plan.dt_s, 2);
        SnapshotProbe probe;
        probe.quantity = "excess_pore_pressure_pa";
        for (int k = 0; k < kProbePoints; ++k) {
            const double s = (k + 0.5) / kProbePoints * length;
            const double x = width - s * std::cos(angle), y = s * std::sin(angle);
            const int i = m_lattice->firstFluidX() + static_cast<int>(x / m_plan.h_m);
            const int j = m_lattice->firstFluidY() + static_cast<int>(y / m_plan.h_m);
            const long long cell = m_lattice->index(i, j);
            probe.s.push_back(s);
            probe.x.push_back(x);
            probe.y.push_back(y);
            const bool inFluid =
                m_lattice->isFluid(cell) && m_coupling->solidFraction()[cell] < 0.5;
            probe.value.push_back(inFluid ? (m_lattice->density(cell) - 1.0) * scale
                                          : std::numeric_limits<double>::quiet_NaN());
        }
        return probe;
    }

    /// Mean excess pore pressure over the points of the failure-plane probe in the fluid [Pa].
    double failurePlanePressure() const {
        const SnapshotProbe probe = failurePlaneProbe();
        double sum = 0;
        int samples = 0;
        for (const double value : probe.value)
            if (!std::isnan(value)) sum += value, ++samples;
        return samples ? sum / samples : 0.0;
    }

    /// Far-field motion over the main mass's mean grain speed (both 0 while the mass is at rest).
    struct FarFieldRatios {
        double speed = 0;    ///< rms fluid speed
        double acoustic = 0; ///< rms acoustic speed (lattice::MotionRms::acoustic)
    };

    /// Acoustic noise measure over the fluid nodes farther than kFarFieldWidths initial column
    /// widths from the initial column, outside the absorbing layer (which damps by design).
    FarFieldRatios farFieldRatios() const {
        std::vector<char> inLayer(static_cast<std::size_t>(m_lattice->cells()), 0);
        for (std::size_t k = 0; k < m_layer->nodeCount(); ++k)
            inLayer[m_layer->cellAt(k)] = 1;
        const double width = m_column.initialWidth(), height = m_column.initialHeight();
        const double reach = kFarFieldWidths * width;
        std::vector<long long> farCells;
        for (int j = 0; j < m_plan.ny; ++j)
            for (int i = 0; i < m_plan.nx; ++i) {
                const double x = (i + 0.5) * m_plan.h_m, y = (j + 0.5) * m_plan.h_m;
                const double dx = std::max(x - width, 0.0), dy = std::max(y - height, 0.0);
                const long long cell =
                    m_lattice->index(m_lattice->firstFluidX() + i, m_lattice->firstFluidY() + j);
                if (dx * dx + dy * dy > reach * reach && !inLayer[cell] && m_lattice->isFluid(cell))
                    farCells.push_back(cell);
            }
        const auto& p = m_column.system().particles();
        const std::vector<bool> main =
            mainMass(viewOf(p), m_params.contact_gap_m, m_params.bridge_gap_m);
        double grainSpeed = 0;
        std::size_t grains = 0;
        for (std::size_t k = 0; k < p.size(); ++k)
            if (main[k]) grainSpeed += std::hypot(p.vx[k], p.vy[k]), ++grains;
        grainSpeed = grains ? grainSpeed / grains : 0;
        if (farCells.empty() || grainSpeed <= 0) return {};
        const lattice::MotionRms motion = lattice::motionRms(*m_lattice, farCells);
        const double velocityScale = m_plan.h_m / m_plan.dt_s;
        return {motion.speed * velocityScale / grainSpeed,
                motion.acoustic * velocityScale / grainSpeed};
    }

    CaseSpec m_spec;
    Plan m_plan;
    ColumnScene m_column;
    MassDiagnosticsParams m_params;
    std::optional<lattice::Lattice> m_lattice;
    std::unique_ptr<coupling::Coupling> m_coupling;
    std::optional<lattice::StabilityGuard> m_guard;
    std::optional<lattice::AbsorbingLayer>
        m_layer;                            // sponge inside the pressure sides (may hold no node)
    double m_linkFluxFactor = 0;            // fluid.magic_lambda_links_only (0: off)
    std::vector<long long> m_wallLinkCells; // fluid nodes next to a wall
    std::vector<long long> m_linkCells;     // this step's link nodes
    std::vector<std::uint8_t> m_linkMark;   // per cell: already in m_linkCells
};

} // namespace

std::unique_ptr<SceneRunner> makeColumnCollapseRunner(const CaseSpec& spec, const Plan& plan) {
    return std::make_unique<ColumnCollapseRunner>(spec, plan);
}

} // namespace lbdem::solver
