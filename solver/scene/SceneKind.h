// The scenes a case can ask for.
#pragma once

#include "solver/core/EnumWords.h"

#include <array>

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

} // namespace lbdem::solver
