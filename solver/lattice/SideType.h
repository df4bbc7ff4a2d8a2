// The boundary conditions a side of the lattice can carry, and their words.
#pragma once

#include "solver/core/EnumWords.h"

#include <array>

namespace lbdem::solver::lattice {

/// Boundary condition on one side of the rectangular domain.
enum class SideType {
    Periodic,      ///< wraps to the opposite side (both sides must say so)
    Wall,          ///< half-way bounce-back, optionally moving with (ux, uy)
    FreeSlip,      ///< specular reflection: zero normal flux, no tangential stress
    Pressure,      ///< constant-pressure open boundary (anti-bounce-back at density rho)
    ZouHeVelocity, ///< Zou & He (1997) velocity boundary on the outermost fluid column
    ZouHePressure, ///< Zou & He (1997) pressure boundary on the outermost fluid column
};

/// The word of each side type.
constexpr std::array<EnumWord<SideType>, 6> enumWords(SideType) {
    return {{// the sides a case file's domain.top and domain.right can name
             {SideType::Periodic, "periodic"},
             {SideType::Wall, "wall"},
             {SideType::FreeSlip, "free_slip"},
             {SideType::Pressure, "pressure"},
             // the inflow and outflow columns of the verification flows
             {SideType::ZouHeVelocity, "zou_he_velocity"},
             {SideType::ZouHePressure, "zou_he_pressure"}}};
}

} // namespace lbdem::solver::lattice
