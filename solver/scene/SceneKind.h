// The scenes a case can ask for, and what each declares about itself.
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

/// What a scene declares about itself: its case-file word, the number of summary.json a study of
/// it compares when none is named, and the key that sets its lattice resolution.
struct SceneDecl {
    SceneKind kind;
    std::string name;          ///< the case-file word
    std::string studyMetric;   ///< a study's default metric; empty: the scene cannot be studied
    std::string studyFallback; ///< the default instead when a case does not report studyMetric
                               ///< (the cavity away from Ghia's Re = 100); empty: none
    std::string resolutionKey; ///< the key that sets the resolution (a study over it reports
                               ///< the observed order of convergence); empty: none
};

/// The declaration of every scene, in enum order.
const std::vector<SceneDecl>& sceneDecls();
/// The declaration of a scene.
const SceneDecl& sceneDecl(SceneKind kind);

/// The case-file word of every scene, in enum order.
const std::vector<std::string>& sceneNames();
/// The scene for a case-file word; the word must be one of sceneNames().
SceneKind sceneFromName(std::string_view name);
/// The case-file word of a scene.
const std::string& sceneName(SceneKind kind);

} // namespace lbdem::solver
