// The SceneRunner of the pure-fluid verification flows (wraps FlowScene).
#include "solver/scene/FlowSceneRunner.h"

#include "solver/scene/FlowScene.h"
#include "solver/scene/LatticeState.h"

namespace lbdem::solver {

namespace {

class FlowSceneRunner final : public SceneRunner {
public:
    FlowSceneRunner(const CaseSpec& spec, const Plan& plan) : m_scene(spec, plan) {}

    void step(StageTimer& timer) override {
        const auto start = StageTimer::Clock::now();
        m_scene.step();
        timer.lap(Stage::StreamCollide, start);
    }

    double time() const override { return m_scene.timeS(); }

    void fillSnapshot(Snapshot& snapshot, int downsample) const override {
        snapshot.fluid.emplace();
        m_scene.fillSnapshot(*snapshot.fluid, downsample);
    }

    void addMetrics(std::map<std::string, double>& metrics) const override {
        for (const auto& [name, value] : m_scene.metrics())
            metrics[name] = value;
    }

    void save(StateArchive& archive) const override {
        saveLatticeState(m_scene.lattice(), archive);
    }

    void restore(const StateArchive& archive) override {
        restoreLatticeState(archive, m_scene.lattice());
    }

private:
    FlowScene m_scene;
};

} // namespace

std::unique_ptr<SceneRunner> makeFlowSceneRunner(const CaseSpec& spec, const Plan& plan) {
    return std::make_unique<FlowSceneRunner>(spec, plan);
}

} // namespace lbdem::solver
