// The scenes a case can ask for, and what each declares about itself.
#pragma once

#include "solver/core/EnumWords.h"

#include <array>
#include <string>
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

/// The case-file word of each scene (the top-level key scene).
constexpr std::array<EnumWord<SceneKind>, 6> enumWords(SceneKind) {
    return {{{SceneKind::ColumnCollapse, "column_collapse"},
             {SceneKind::Poiseuille, "poiseuille"},
             {SceneKind::TaylorGreen, "taylor_green"},
             {SceneKind::Cavity, "cavity"},
             {SceneKind::Cylinder, "cylinder"},
             {SceneKind::SettlingDisc, "settling_disc"}}};
}

/// What a scene declares about itself: the number of summary.json a study of it compares when
/// none is named, and the key that sets its lattice resolution.
struct SceneDecl {
    SceneKind kind;
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

} // namespace lbdem::solver
