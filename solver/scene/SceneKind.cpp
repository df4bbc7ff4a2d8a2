// The scene table: each scene's word, default study metric and resolution key.
#include "solver/scene/SceneKind.h"

#include <stdexcept>

namespace lbdem::solver {

const std::vector<SceneDecl>& sceneDecls() {
    using K = SceneKind;
    static const std::vector<SceneDecl> decls{
        {K::ColumnCollapse, "column_collapse", "runout_final", "", "fluid.resolution"},
        {K::Poiseuille, "poiseuille", "l2_error", "", "flow.nodes"},
        {K::TaylorGreen, "taylor_green", "decay_rate_1_s", "", "flow.nodes"},
        {K::Cavity, "cavity", "ghia_max_deviation", "max_mach", "flow.nodes"},
        {K::Cylinder, "cylinder", "drag_coefficient", "", "flow.nodes"},
        {K::SettlingDisc, "settling_disc", "", "", ""}, // run by `lbdem verify` only
    };
    return decls;
}

const SceneDecl& sceneDecl(SceneKind kind) {
    return sceneDecls().at(static_cast<std::size_t>(kind));
}

const std::vector<std::string>& sceneNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> words;
        for (const auto& decl : sceneDecls())
            words.push_back(decl.name);
        return words;
    }();
    return names;
}

SceneKind sceneFromName(std::string_view name) {
    const auto& names = sceneNames();
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return static_cast<SceneKind>(i);
    throw std::invalid_argument("unknown scene '" + std::string(name) + "'");
}

const std::string& sceneName(SceneKind kind) {
    return sceneNames().at(static_cast<std::size_t>(kind));
}

} // namespace lbdem::solver
