// Number format of the stored populations: double, or float holding the shifted f_i - w_i.
#pragma once

#include "solver/lattice/Collision.h"

#include <array>

namespace lbdem::solver::lattice {

/// How the lattice stores its populations. The bulk kernel collides in the stored type (float
/// storage: float arithmetic on the deviations, Collision.h); everything else works in double.
enum class PopulationStorage {
    Double, ///< f_i as double: 8 bytes per value, 144 bytes moved per AA update
    Float,  ///< f_i - w_i as float (DDF shifting): 4 bytes per value, 72 bytes per update
};

/// The case-file word of each population storage (fluid.storage).
constexpr std::array<EnumWord<PopulationStorage>, 2> enumWords(PopulationStorage) {
    return {{{PopulationStorage::Double, "double"}, {PopulationStorage::Float, "float"}}};
}

/// Conversion between a stored number of type S and the population f_i of a direction of
/// weight w_i. Float stores the deviation from the rest equilibrium, f_i - w_i (rho = 1,
/// u = 0): near rest it is small, so float's relative rounding error acts on the deviation and
/// not on the O(1) weight ("DDF shifting": Lehmann, Krause, Amati et al. 2022, Phys. Rev. E 106,
/// 015308). Opposite directions share a weight, so the shift of a slot does not depend on which
/// of the two directions the AA pattern keeps in it.
template <class S> struct StoredPopulation;

/// Double storage: the population itself.
template <> struct StoredPopulation<double> {
    /// Whether the passes over these values read and write subnormal numbers as zero: never
    /// reached in double (its least normal number is 2.2e-308).
    static constexpr bool kFlushSubnormals = false;
    /// The population held by a stored value.
    static LBDEM_KERNEL_INLINE double load(double stored, double) { return stored; }
    /// The value that stores population f.
    static LBDEM_KERNEL_INLINE double store(double f, double) { return f; }
};

/// Float storage: the deviation f_i - w_i, widened to double for the accessors and boundary passes.
template <> struct StoredPopulation<float> {
    /// Still fluid's deviations fall below float's least normal number (1.2e-38), where each
    /// operation costs a microcode assist: the passes over these values flush them
    /// (solver/core/FlushSubnormals.h).
    static constexpr bool kFlushSubnormals = true;
    /// The population held by a stored deviation.
    static LBDEM_KERNEL_INLINE double load(float stored, double w) {
        return static_cast<double>(stored) + w;
    }
    /// The deviation that stores population f, rounded to float.
    static LBDEM_KERNEL_INLINE float store(double f, double w) { return static_cast<float>(f - w); }
};

} // namespace lbdem::solver::lattice
