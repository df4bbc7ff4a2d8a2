// Packing generator: seeded columns of polydisperse discs at a target packing fraction.
#pragma once

#include "solver/core/Real.h"
#include "solver/dem/ContactLaw.h"

#include <cstdint>
#include <string>
#include <vector>

namespace lbdem::solver::dem {

/// What column to build. Diameters are uniform in [d_min, size_ratio d_min].
struct PackingRequest {
    int count = 1000;        ///< number of discs N
    Real d_min = 1.2e-3;     ///< smallest diameter [m]
    Real size_ratio = 1.8;   ///< d_max / d_min
    Real target = 0.83;      ///< packing fraction to reach (dense 0.83, loose 0.79)
    Real aspect_ratio = 0.8; ///< a = H_i / L_i of the settled column
    Real tolerance = 0.005;  ///< accepted |achieved - target|
    Real gravity = 9.81;     ///< gravity during deposition [m/s^2], pointing to -y
    Material material;       ///< the contact law of the run (used for the final relaxation)
    std::uint64_t seed = 1;  ///< seed of the diameters and the initial placement
    bool fixed_friction =
        false; ///< deposit once with the material's friction, no search for target
};

/// A settled column resting on y = 0 between walls at x = 0 and x = width.
struct Packing {
    std::vector<Real> x, y, radius;
    Real width = 0;         ///< L_i, the distance between the side walls [m]
    Real height = 0;        ///< H_i, equivalent column height (see packingFraction) [m]
    Real fraction = 0;      ///< achieved packing fraction (see packingFraction)
    Real target = 0;        ///< requested fraction
    Real prep_friction = 0; ///< friction coefficient used during deposition
    int depositions = 0;    ///< deposition runs the search needed
    double wall_s = 0;      ///< generation time (0 when read from the cache)
    bool from_cache = false;
    bool converged = false; ///< |fraction - target| <= tolerance
};

/// Where generated packings are cached and whether to use the cache.
struct PackingOptions {
    bool use_cache = true;
    std::string cache_dir; ///< empty: defaultPackingCacheDir()
};

/// Generate (or read from the cache) the column of a request. The column width follows from the
/// drawn diameters: L_i = sqrt(sum(pi R^2) / (a target)). Discs are deposited under gravity in a
/// box of that width from a loose seeded lattice; the deposition friction is searched (lower
/// friction packs denser) until the settled fraction is within tolerance, then the column is
/// relaxed with the run's contact law. The depositions run on one thread: the DEM's force sums
/// depend on how its rows are split between threads, and the column (which a chaotic deposition
/// amplifies from rounding to whole grains) must not depend on the run's thread count, nor the
/// cached file on which run made it first. Throws SimulationError if the target is out of reach.
Packing generatePacking(const PackingRequest& request, const PackingOptions& options = {});

/// Packing fraction of a column resting on y = 0 in [0, width]: total disc area over width * H,
/// where H is twice the area-weighted mean height of the discs, i.e. the height of the uniform
/// rectangle with the same area centroid. Unlike the highest disc tops, H does not jump when a
/// single disc sits proud of the surface. Returns the fraction and writes H to height.
Real packingFraction(const std::vector<Real>& y, const std::vector<Real>& r, Real width,
                     Real& height);

/// Cache folder: $LBDEM_CACHE_DIR, else $XDG_CACHE_HOME/lbdem, else $HOME/.cache/lbdem.
std::string defaultPackingCacheDir();

/// Cache key: a hash of every parameter that influences the packing (and the generator version).
std::string packingCacheKey(const PackingRequest& request);

/// Read a cached packing into packing; false when absent, unreadable, or damaged (its checksum
/// line missing or not matching), so that the caller generates it again and overwrites it.
bool readCachedPacking(const std::string& path, Packing& packing);
/// Write a packing (hex floats, exact round trip, a checksum line last) atomically; false on
/// failure.
bool writeCachedPacking(const std::string& path, const Packing& packing);

} // namespace lbdem::solver::dem
