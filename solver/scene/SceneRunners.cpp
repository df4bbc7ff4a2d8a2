// The factory that picks the SceneRunner of a case's scene.
#include "solver/scene/SceneRunner.h"

#include "solver/core/InputError.h"
#include "solver/scene/ColumnCollapseRunner.h"
#include "solver/scene/FlowPlan.h"
#include "solver/scene/FlowSceneRunner.h"
#include "solver/scene/SceneKind.h"

namespace lbdem::solver {

std::unique_ptr<SceneRunner> makeSceneRunner(const CaseSpec& spec, const Plan& plan) {
    const SceneKind kind = spec.scene;
    if (isFlowScene(kind)) {
        if (!spec.fluid.enabled)
            throw InputError("", 0, "fluid.enabled",
                             std::string("scene '") + enumWord(kind) +
                                 "' is a flow: it needs fluid.enabled = true");
        return makeFlowSceneRunner(spec, plan);
    }
    if (kind == SceneKind::ColumnCollapse) return makeColumnCollapseRunner(spec, plan);
    throw InputError("", 0, "scene",
                     std::string("'") + enumWord(kind) +
                         "' is run by `lbdem verify` only, not by `lbdem run`");
}

} // namespace lbdem::solver
