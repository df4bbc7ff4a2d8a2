// The scene table: each scene's default study metric and resolution key.
#include "solver/scene/SceneKind.h"

namespace lbdem::solver {

const std::vector<SceneDecl>& sceneDecls() {
    using K = SceneKind;
    static const std::vector<SceneDecl> decls{
        {K::ColumnCollapse, "runout_final", "", "fluid.resolution"},
        {K::Poiseuille, "l2_error", "", "flow.nodes"},
        {K::TaylorGreen, "decay_rate_1_s", "", "flow.nodes"},
        {K::Cavity, "ghia_max_deviation", "max_mach", "flow.nodes"},
        {K::Cylinder, "drag_coefficient", "", "flow.nodes"},
        {K::SettlingDisc, "", "", ""}, // run by `lbdem verify` only
    };
    return decls;
}

const SceneDecl& sceneDecl(SceneKind kind) {
    return sceneDecls().at(static_cast<std::size_t>(kind));
}

} // namespace lbdem::solver
