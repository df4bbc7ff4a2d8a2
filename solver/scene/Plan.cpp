// Planning: from SI case parameters to lattice units, time steps and a cost estimate.
#include "solver/scene/Plan.h"
#include "solver/core/Constants.h"

#include "solver/core/InputError.h"
#include "solver/dem/ContactLaw.h"
#include "solver/lattice/D2Q9.h"
#include "solver/scene/FlowPlan.h"
#include "solver/scene/FluidStability.h"
#include "solver/scene/SceneKind.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lbdem::solver {

namespace {

// The longest submerged runout the paper's first author reports (thesis, Delta L ~ 3.1 for the
// loose cases): a submerged domain should leave a front at least this much room.
constexpr double kLongestExpectedRunout = 3.1;
// The largest number of DEM sub-steps per fluid step (the top of coupling.substeps' range).
constexpr double kMaxSubsteps = 10000;
// Contacts of a grain in a hexagonal packing (sets the DEM's stiffest mode).
constexpr double kPackedNeighbours = 6;
// Assumed throughputs for the run-time estimate; `lbdem bench` measures the real ones.
constexpr double kAssumedLatticeUpdatesPerS = 100e6;
constexpr double kAssumedParticleStepsPerS = 10e6;

// Bytes per node and per grain of what a run writes, uncompressed (an upper bound: the VTK
// files are zlib-compressed). Fluid image: velocity (3 floats), speed, pressure, vorticity,
// solid fraction. Particles: point, radius, velocity, speed, omega, force, hydrodynamic force
// and the cell arrays. Contacts (about 3 per grain): two end points' ids, offsets, type,
// normal and tangential force, grain indices. Checkpoint: 9 doubles per node, the owner map
// and coupling arrays, and the grain state (13 doubles and the contact history).
constexpr double kVtiBytesPerNode = 28;
constexpr double kSnapshotBytesPerNode = 20;
constexpr double kParticleBytes = 96, kContactBytes = 3 * 72;
constexpr double kCheckpointBytesPerNode = 9 * 8 + 3 * 8;
constexpr double kCheckpointBytesPerGrain = 13 * 8 + 4 * 40;
// timeseries.csv row, outline and failure-plane profiles of one output.
constexpr double kRowBytes = 600, kProfileBytes = 12e3;

/// Fluid nodes kept in a snapshot (every fluid_downsample-th node each way).
double outputNodes(const CaseSpec& spec, const Plan& plan) {
    if (!plan.has_fluid) return 0;
    const double every = std::max(1, spec.output.fluid_downsample);
    return std::ceil(plan.nx / every) * std::ceil(plan.ny / every);
}

/// Upper bound of the disk space a run needs at its peak: per output a timeseries row and
/// profiles, VTK files every vtk_every outputs, and two checkpoints (each new one is written
/// in full next to the previous one before it replaces it).
double estimateOutputBytes(const CaseSpec& spec, const Plan& plan) {
    const double interval = spec.run.output_interval_tc * plan.tc_s;
    const double outputs = interval > 0 ? std::floor(plan.end_time_s / interval + 1e-9) + 2 : 2;
    const double vtkOutputs =
        spec.output.vtk ? std::ceil(outputs / std::max(1, spec.output.vtk_every)) : 0;
    const double grains = static_cast<double>(plan.grains);
    const double vtkBytes =
        outputNodes(spec, plan) * kVtiBytesPerNode + grains * (kParticleBytes + kContactBytes);
    const double nodes = static_cast<double>(plan.nx) * plan.ny;
    const double checkpoint = nodes * kCheckpointBytesPerNode + grains * kCheckpointBytesPerGrain;
    return outputs * (kRowBytes + kProfileBytes) + vtkOutputs * vtkBytes + 2 * checkpoint;
}

std::string format(const char* pattern, double a, double b = 0) {
    char buffer[256];
    std::snprintf(buffer, sizeof buffer, pattern, a, b);
    return buffer;
}

double discMass(double diameter, double density) {
    return density * kPi * diameter * diameter / 4;
}

void planGrains(const CaseSpec& spec, Plan& plan) {
    const auto& g = spec.grains;
    plan.has_grains = g.count > 0;
    plan.grains = g.count;
    plan.column = columnGeometry(g);
    const double lightest = discMass(g.d_min_m, g.density_kg_m3);
    // A grain pressed by the six neighbours of a hexagonal packing oscillates faster than a pair:
    // omega^2 = 6 k / m, i.e. a pair's with three times the stiffness. (The default case ran
    // stably at 0.46 of the pair's limit and blew up within 8 steps at 0.91 of it; this limit is
    // 0.58 of it.)
    plan.dem_dt_stable_s =
        stableDemStep(kPackedNeighbours / 2 * g.normal_stiffness_n_m, lightest / 2, g.restitution);
    // Never above the stability limit (a large dt_safety with strong damping would be).
    plan.dem_dt_safe_s =
        std::min(g.dt_safety * contactDuration(g.normal_stiffness_n_m, lightest / 2, g.restitution),
                 plan.dem_dt_stable_s);
    plan.dem_dt_s = plan.dem_dt_safe_s;
    if (plan.column.width_m > spec.domain.width_m || plan.column.height_m > spec.domain.height_m)
        plan.warnings.push_back(
            format("the column (%.4g m wide, %.4g m high) does not fit the domain",
                   plan.column.width_m, plan.column.height_m));
}

/// The DEM step of a coupled run is dt / substeps: refuse one beyond the integrator's stability
/// limit (the grains would blow up within a few steps), warn beyond the case's safety factor.
void checkDemStep(const CaseSpec& spec, Plan& plan) {
    plan.dem_dt_s = plan.dt_s / plan.substeps;
    const int needed = static_cast<int>(std::floor(plan.dt_s / plan.dem_dt_safe_s)) + 1;
    char text[400];
    if (plan.dem_dt_s > plan.dem_dt_stable_s) {
        std::snprintf(
            text, sizeof text,
            "%d sub-steps per fluid step of %.3g s give a DEM step of %.3g s, above the stability "
            "limit %.3g s of the DEM integrator (contact stiffness, lightest grain); use at least "
            "%d, or 0 to choose automatically",
            spec.coupling.substeps, plan.dt_s, plan.dem_dt_s, plan.dem_dt_stable_s, needed);
        throw InputError("", 0, "coupling.substeps", text);
    }
    if (plan.dem_dt_s > plan.dem_dt_safe_s * (1 + 1e-12)) {
        std::snprintf(
            text, sizeof text,
            "coupling.substeps = %d gives a DEM step of %.3g s, above grains.dt_safety times the "
            "contact duration (%.3g s); %d sub-steps keep within it",
            spec.coupling.substeps, plan.dem_dt_s, plan.dem_dt_safe_s, needed);
        plan.warnings.push_back(text);
    }
}

void planFluid(const CaseSpec& spec, Plan& plan) {
    const auto& f = spec.fluid;
    plan.has_fluid = true;
    plan.h_m = spec.grains.d_min_m / f.resolution;
    plan.nx = static_cast<int>(std::lround(spec.domain.width_m / plan.h_m));
    plan.ny = static_cast<int>(std::lround(spec.domain.height_m / plan.h_m));
    const double reducedGravity =
        spec.domain.gravity_m_s2 * (1.0 - f.density_kg_m3 / spec.grains.density_kg_m3);
    plan.u_expected_m_s = std::sqrt(std::max(reducedGravity, 0.0) * plan.column.height_m);
    // An imposed tau sets the step through the viscosity; else the Mach number sets it.
    plan.dt_s = imposesTau(f.tau) ? (f.tau - 0.5) * plan.h_m * plan.h_m / (3.0 * f.viscosity_m2_s)
                                  : f.target_mach * lattice::kCs * plan.h_m /
                                        std::max(plan.u_expected_m_s, 1e-12);
    plan.tau = relaxationTime(f.tau, f.viscosity_m2_s, plan.dt_s, plan.h_m);
    plan.nu_lattice = (plan.tau - 0.5) / 3.0;
    planAcoustics(f.density_kg_m3, plan);
    const double needed = std::floor(plan.dt_s / plan.dem_dt_safe_s) + 1;
    if (plan.has_grains && spec.coupling.substeps == 0 && !(needed <= kMaxSubsteps))
        throw InputError(
            "", 0, "coupling.substeps",
            format(
                "the fluid step of %.3g s would need %.3g DEM sub-steps (more than 10000); lower "
                "fluid.tau or raise fluid.resolution",
                plan.dt_s, needed));
    plan.substeps = spec.coupling.substeps > 0 ? spec.coupling.substeps
                                               : static_cast<int>(std::min(needed, kMaxSubsteps));
    if (plan.has_grains) checkDemStep(spec, plan);

    addStabilityWarnings(spec, plan);
    const double nodesAcross = spec.coupling.hydro_radius_ratio * f.resolution;
    if (plan.has_grains && nodesAcross < 5)
        plan.warnings.push_back(format("only %.3g lattice nodes across the smallest hydrodynamic "
                                       "diameter (fewer than 5): grain forces will be inaccurate",
                                       nodesAcross));
}

/// The absorbing layer's thickness, and how far a front can run before it meets the end of the
/// domain or the layer: said in a note, with a warning when a submerged front may run further.
void planDomain(const CaseSpec& spec, Plan& plan) {
    const auto& d = spec.domain;
    if (plan.has_fluid &&
        (d.right == lattice::SideType::Pressure || d.top == lattice::SideType::Pressure) &&
        d.absorbing_layer_strength > 0)
        plan.absorbing_layer_nodes = d.absorbing_layer_nodes;
    if (!plan.has_grains || plan.column.width_m <= 0) return;
    const double layer =
        d.right == lattice::SideType::Pressure ? plan.absorbing_layer_nodes * plan.h_m : 0.0;
    const double end = d.width_m - layer, widths = d.width_m / plan.column.width_m;
    plan.runout_room = (end - plan.column.width_m) / plan.column.width_m;
    const char* meets = layer > 0 ? "the absorbing layer" : "the end of the domain";
    char text[400];
    const int used = std::snprintf(
        text, sizeof text,
        "the domain is %.3g m long (domain.width_m) = %.3g column widths: a front meets %s "
        "at Delta L = %.2f",
        d.width_m, widths, meets, plan.runout_room);
    if (plan.has_fluid && used > 0 && used < static_cast<int>(sizeof text)) {
        const bool room = plan.runout_room >= kLongestExpectedRunout;
        std::snprintf(
            text + used, sizeof text - used,
            ", %s the longest submerged runout the paper's first author reports (Delta L ~ %.1f)%s",
            room ? "beyond" : "short of", kLongestExpectedRunout,
            room ? "" : "; a front that runs further is a lower bound (0.4 m leaves room)");
    }
    plan.notes.push_back(text);
}

} // namespace

void planAcoustics(double fluidDensity, Plan& plan) {
    plan.sound_speed_m_s = lattice::kCs * plan.h_m / plan.dt_s;
    plan.bulk_modulus_pa = fluidDensity * plan.sound_speed_m_s * plan.sound_speed_m_s;
    plan.mach = plan.u_expected_m_s / plan.sound_speed_m_s;
}

double stableDemStep(double stiffness, double effectiveMass, double restitution) {
    const double omega = std::sqrt(stiffness / effectiveMass);
    const double zeta = dem::dampingRatio(restitution);
    return 2.0 / omega * (std::sqrt(1.0 + zeta * zeta) - zeta);
}

double contactDuration(double stiffness, double effectiveMass, double restitution) {
    // One definition shared with the DEM contact law, so that the planned step and the
    // integrator's dashpot follow from the same damping ratio.
    return dem::contactDuration(stiffness, effectiveMass, restitution);
}

ColumnGeometry columnGeometry(const GrainSpec& grains) {
    ColumnGeometry column;
    const double dMin = grains.d_min_m, dMax = grains.d_min_m * grains.size_ratio;
    // E[d^2] for d uniform in [dMin, dMax].
    const double meanSquare =
        grains.size_ratio > 1.0 ? (dMax * dMax * dMax - dMin * dMin * dMin) / (3.0 * (dMax - dMin))
                                : dMin * dMin;
    column.mean_disc_area_m2 = kPi * meanSquare / 4.0;
    column.grain_area_m2 = grains.count * column.mean_disc_area_m2;
    const double area = column.grain_area_m2 / grains.packing;
    column.width_m = std::sqrt(area / grains.aspect_ratio);
    column.height_m = grains.aspect_ratio * column.width_m;
    return column;
}

Plan makePlan(const CaseSpec& spec) {
    Plan plan;
    planGrains(spec, plan);
    plan.tc_s = std::sqrt(plan.column.height_m / std::max(spec.domain.gravity_m_s2, 1e-12));
    const bool flow = spec.fluid.enabled && isFlowScene(spec.scene);
    if (flow) {
        planFlow(spec, plan); // sets its own steps and end time (solver/scene/FlowPlan.cpp)
    } else if (spec.fluid.enabled) {
        planFluid(spec, plan);
    } else {
        plan.dt_s = plan.dem_dt_s;
        plan.substeps = 1;
    }
    if (!flow) {
        planDomain(spec, plan);
        plan.end_time_s = spec.run.end_tc * plan.tc_s;
        plan.steps = static_cast<long long>(std::ceil(plan.end_time_s / plan.dt_s));
    }

    const double nodes = static_cast<double>(plan.nx) * plan.ny;
    const double bytesPerValue =
        spec.fluid.storage == lattice::PopulationStorage::Float ? sizeof(float) : sizeof(double);
    // One distribution set (updated in place), one flag byte, a side index and one solid
    // fraction per node, the coupling's owner map, ~256 B per grain; while a checkpoint is
    // written, three double copies of the state (the saved state, HDF5's in-memory file and
    // the image written from it); while an output is written, the snapshot's and the VTK
    // image's fluid fields.
    plan.memory_bytes = static_cast<std::size_t>(
        nodes * (lattice::kQ * bytesPerValue + 1 + 4 + 8 + 4) +
        3 * nodes * kCheckpointBytesPerNode +
        outputNodes(spec, plan) * (kSnapshotBytesPerNode + kVtiBytesPerNode) +
        static_cast<double>(plan.grains) * 256);
    plan.output_bytes = static_cast<std::size_t>(estimateOutputBytes(spec, plan));
    const double demSteps = static_cast<double>(plan.steps) * plan.substeps;
    plan.estimated_run_s = static_cast<double>(plan.steps) * nodes / kAssumedLatticeUpdatesPerS +
                           demSteps * static_cast<double>(plan.grains) / kAssumedParticleStepsPerS;
    return plan;
}

} // namespace lbdem::solver
