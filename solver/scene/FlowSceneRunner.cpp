// The SceneRunner of the pure-fluid verification flows (wraps FlowScene).
#include "solver/scene/FlowSceneRunner.h"

#include "solver/scene/FlowScene.h"

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
        for (const auto& [name, value] : m_scene.metrics()) metrics[name] = value;
    }

    void save(StateArchive& archive) const override {
        archive.reals["lattice/f"] = m_scene.lattice().populations();
        archive.integers["lattice/step"] = {m_scene.lattice().stepCount()};
    }

    void restore(const StateArchive& archive) override {
        auto& f = m_scene.lattice().populations();
        const auto& saved = archive.real("lattice/f");
        if (saved.size() != f.size())
            throw std::runtime_error("the checkpoint's lattice does not match the case's plan");
        f = saved;
        m_scene.lattice().setStepCount(archive.integer("lattice/step").at(0));
    }

private:
    FlowScene m_scene;
};

} // namespace

std::unique_ptr<SceneRunner> makeFlowSceneRunner(const CaseSpec& spec, const Plan& plan) {
    return std::make_unique<FlowSceneRunner>(spec, plan);
}

} // namespace lbdem::solver
