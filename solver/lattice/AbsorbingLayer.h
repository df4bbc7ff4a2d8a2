// Absorbing (sponge) layer in front of the constant-pressure sides: sound leaves the domain.
#pragma once

#include "solver/core/Real.h"

#include <cstddef>
#include <vector>

namespace lbdem::solver::lattice {

class Lattice;

/// Thickness and strength of the layer, lattice units.
struct AbsorbingLayerSetup {
    int nodes = 24;      ///< thickness in nodes along each constant-pressure side; 0: no layer
    Real strength = 0.3; ///< sigma_max, the relaxation per step at the outer edge (0 < sigma <= 1)
    Real rho = 1;        ///< target density rho_0 (the pressure sides' density)
};

/// A sponge layer (Israeli & Orszag 1981, J. Comput. Phys. 41, 115; for the lattice Boltzmann
/// method Xu & Sagaut 2013, J. Comput. Phys. 245, 14) along every constant-pressure side
/// (SideType::Pressure) of a lattice. After each step, every fluid node of the layer relaxes its
/// equilibrium part toward the rest state at rho_0:
///     f_i <- f_i - sigma(d) [ f_i^eq(rho, u) - f_i^eq(rho_0, 0) ],
/// which adds -sigma (rho - rho_0) to the mass and -sigma rho u to the momentum equation and
/// leaves the non-equilibrium (viscous) part alone. The strength rises smoothly from zero at the
/// layer's inner edge to sigma_max at the side: sigma(d) = sigma_max ((N - d) / N)^2, d the
/// node's distance from the side in nodes (half a node for the outermost row), N the thickness;
/// at a corner the larger of the two sides' values applies.
/// Why density and momentum at the same rate: in linear acoustics the two Riemann invariants
/// p' +- rho_0 c u_n then obey w_t +- c w_x = -sigma(x) w, uncoupled, so a plane wave entering
/// the layer is damped without any reflection from the ramp, whatever its wavelength. What comes
/// back is only what reaches the side (where the constant pressure reflects it with the opposite
/// sign) and returns, damped twice: by exp(-2 int sigma dx / c_s) = exp(-2 sigma_max N /
/// (3 c_s)) per round trip (c_s = 1/sqrt 3), about 2e-4 at N = 24, sigma_max = 0.3.
/// Damping only the density (toward the local velocity) would not have this property.
/// In two dimensions the damping does not separate so cleanly (the field behind a circular
/// front is damped too, and that change travels back): measured with the defaults, a plane
/// pulse comes back at 0.12 % of its amplitude, a circular pulse meeting the two open sides of
/// a corner at every angle at about 3 % (bare pressure sides: 81 % and 49 %).
/// The pass runs outside the bulk kernel: call apply() after Lattice::step() and after anything
/// that reads the step's post-collision populations (the grain coupling's loads).
class AbsorbingLayer {
public:
    /// The layer along the lattice's constant-pressure sides; none when setup.nodes is 0 or
    /// no side is a pressure side. Throws InputError on a negative thickness or a strength
    /// outside [0, 1].
    AbsorbingLayer(const Lattice& lattice, const AbsorbingLayerSetup& setup);

    /// Relax the layer's fluid nodes one step toward rest at rho_0 (post-collision populations).
    void apply(Lattice& lattice) const;
    /// Number of nodes the layer touches each step.
    std::size_t nodeCount() const { return m_cells.size(); }
    /// The relaxation sigma of the k-th layer node (for tests and reports).
    Real strengthAt(std::size_t k) const { return m_sigma.at(k); }
    /// The lattice cell of the k-th layer node.
    long long cellAt(std::size_t k) const { return m_cells.at(k); }

private:
    /// Consecutive layer cells of one row, all with or all without neighbours that wrap.
    struct Run {
        long long firstCell;    // lattice cell of the first
        std::size_t firstIndex; // its index in m_cells and m_sigma
        int count;              // cells in the run
        bool interior;          // no neighbour wraps: slots at the parity's fixed offsets
    };
    static constexpr int kMaxRun = 512; // longest run, so that the threads share the top rows

    /// apply() on the stored values S (PopulationStorage).
    template <class S> void relaxStored(Lattice& lattice, S* stored) const;

    std::vector<long long> m_cells; // fluid cells inside the layer, row by row
    std::vector<Real> m_sigma;      // their relaxation per step
    std::vector<Run> m_runs;        // the cells in runs, in m_cells order
    Real m_rho = 1;
};

} // namespace lbdem::solver::lattice
