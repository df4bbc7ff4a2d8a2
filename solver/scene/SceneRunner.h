// The scene-specific part of a Simulation: how one kind of scene steps, reports and saves.
#pragma once

#include "solver/core/StageTimer.h"
#include "solver/core/StateArchive.h"
#include "solver/scene/CaseSpec.h"
#include "solver/scene/Plan.h"
#include "solver/scene/Snapshot.h"

#include <map>
#include <memory>
#include <string>

namespace lbdem::solver {

/// One kind of scene (a fluid-only verification flow, the column collapse ...). Called once per
/// step, never inside kernels, so a virtual interface costs nothing measurable here.
class SceneRunner {
public:
    virtual ~SceneRunner() = default;
    /// Advance one step of plan.dt_s, timing each stage.
    virtual void step(StageTimer& timer) = 0;
    /// Physical time [s].
    virtual double time() const = 0;
    /// Fill grains, contacts, fluid, walls and outline of snapshot (fluid every downsample nodes).
    virtual void fillSnapshot(Snapshot& snapshot, int downsample) const = 0;
    /// Add this scene's diagnostics (SI units) to metrics.
    virtual void addMetrics(std::map<std::string, double>& metrics) const = 0;
    /// Save the complete state.
    virtual void save(StateArchive& archive) const = 0;
    /// Restore a state saved by save() of a runner built from the same case and plan.
    virtual void restore(const StateArchive& archive) = 0;
};

/// Build the runner of spec.scene; throws InputError when the case cannot be built.
std::unique_ptr<SceneRunner> makeSceneRunner(const CaseSpec& spec, const Plan& plan);

} // namespace lbdem::solver
