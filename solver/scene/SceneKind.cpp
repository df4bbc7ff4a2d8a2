// Scene names.
#include "solver/scene/SceneKind.h"

#include <stdexcept>

namespace lbdem::solver {

const std::vector<std::string>& sceneNames() {
    static const std::vector<std::string> names{"column_collapse", "poiseuille", "taylor_green",
                                                "cavity",          "cylinder",   "settling_disc"};
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
