// Memory bandwidth by an in-place update over arrays much larger than the last-level cache.
#include "solver/lattice/MemoryBandwidth.h"

#include <algorithm>
#include <chrono>
#include <vector>

namespace lbdem::solver::lattice {

std::vector<double> measureBandwidthPassesGBs(std::size_t bytes, int passes) {
    const std::size_t n = bytes / sizeof(double);
    std::vector<double> a(n);
    // First touch in parallel so that pages land where the threads run.
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i)
        a[i] = 1.0;
    std::vector<double> rates;
    double* pa = a.data();
    for (int pass = 0; pass < passes; ++pass) {
        const auto start = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static)
        for (std::size_t i = 0; i < n; ++i)
            pa[i] = 0.5 * pa[i] + 1.0;
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        rates.push_back(2.0 * n * sizeof(double) / seconds / 1e9);
    }
    // Keep the result observable so the loop cannot be dropped.
    volatile double sink = pa[n / 2];
    (void)sink;
    return rates;
}

} // namespace lbdem::solver::lattice
