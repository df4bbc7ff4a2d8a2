// The fluid-grain coupling methods and partially-saturated weights, and their case-file words.
#pragma once

#include "solver/core/EnumWords.h"

#include <array>

namespace lbdem::solver::coupling {

/// How the fluid sees the grains (docs/design.md §5 Coupling).
enum class CouplingMethod {
    BounceBack, ///< moving solid nodes, Bouzidi moving-wall links, momentum exchange (default)
    Psm,        ///< partially saturated cells (Noble & Torczynski 1998)
};

/// Weight B(eps) of the partially saturated method.
enum class PsmWeight {
    Eps, ///< B = eps
    Nt,  ///< B = eps (tau - 1/2) / ((1 - eps) + (tau - 1/2)); goes to 0 as tau -> 1/2
};

/// What a node that a bounce-back grain uncovers starts from.
enum class RefillRule {
    SurfaceEquilibrium, ///< equilibrium at the neighbours' mean density and the surface velocity
    NeighbourMean,      ///< the mean of the fluid neighbours' populations (their motion and stress)
};

/// The case-file word of each method (coupling.method).
constexpr std::array<EnumWord<CouplingMethod>, 2> enumWords(CouplingMethod) {
    return {{{CouplingMethod::BounceBack, "bounce_back"}, {CouplingMethod::Psm, "psm"}}};
}

/// The case-file word of each weight (coupling.psm_weight).
constexpr std::array<EnumWord<PsmWeight>, 2> enumWords(PsmWeight) {
    return {{{PsmWeight::Eps, "eps"}, {PsmWeight::Nt, "nt"}}};
}

/// The case-file word of each refill rule (coupling.refill).
constexpr std::array<EnumWord<RefillRule>, 2> enumWords(RefillRule) {
    return {{{RefillRule::SurfaceEquilibrium, "surface_equilibrium"},
             {RefillRule::NeighbourMean, "neighbour_mean"}}};
}

} // namespace lbdem::solver::coupling
