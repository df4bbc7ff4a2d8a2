// The scenes a case can ask for.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace lbdem::solver {

/// Scene builders known to this build.
enum class SceneKind {
    ColumnCollapse, ///< the paper's granular column collapse, dry or submerged
    Poiseuille,     ///< body-force channel flow (verification)
    TaylorGreen,    ///< decaying Taylor-Green vortex (verification)
    Cavity,         ///< lid-driven cavity (verification)
    Cylinder,       ///< Schäfer-Turek cylinder in a channel (verification)
    SettlingDisc,   ///< a single disc settling in a channel (verification)
};

/// The case-file word of every scene, in enum order.
const std::vector<std::string>& sceneNames();
/// The scene for a case-file word; the word must be one of sceneNames().
SceneKind sceneFromName(std::string_view name);
/// The case-file word of a scene.
const std::string& sceneName(SceneKind kind);

} // namespace lbdem::solver
