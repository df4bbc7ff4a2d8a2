// Runout of the main mass, energies, packing (under the column-wise surface) and the Froude number
// of the flowing front layer.
#include "solver/diagnostics/MassDiagnostics.h"
#include "solver/core/Constants.h"

#include <algorithm>
#include <cmath>

namespace lbdem::solver {

namespace {

/// Upper surface of the main mass per column of width bin; returns the heights per column.
std::vector<double> surfaceHeights(const GrainArrays& g, const std::vector<bool>& main, double bin,
                                   double front) {
    const std::size_t columns = static_cast<std::size_t>(std::ceil(std::max(front, bin) / bin));
    std::vector<double> top(columns, 0.0);
    for (std::size_t i = 0; i < g.count; ++i) {
        if (!main[i]) continue;
        // A disc covers every column its horizontal extent reaches.
        const double left = std::max(0.0, double(g.x[i] - g.radius[i]));
        const double right = double(g.x[i] + g.radius[i]);
        const auto first = static_cast<std::size_t>(left / bin);
        const auto last = std::min(columns - 1, static_cast<std::size_t>(right / bin));
        for (std::size_t c = first; c <= last && c < columns; ++c)
            top[c] = std::max(top[c], double(g.y[i] + g.radius[i]));
    }
    return top;
}

/// The flowing front layer, and U, H, rho_m and Fr_d from it. The front window holds the main-mass
/// discs whose centres lie within front_length_m behind the front; the layer is those of them that
/// move downslope at least flowing_fraction times as fast as the window's fastest disc (the
/// sliding mass, not the resting flank or deposit the window may still span). U is the layer's
/// mean downslope velocity; in each column of width bin_width_m across the window that holds
/// layer discs (by centre) the layer spans from its lowest disc bottom to its highest disc top, H
/// is the mean of those spans, and the layer's packing fraction phi is its discs' area over the
/// area of those spans, so rho_m = phi rho_s + (1 - phi) rho_w and Fr_d = U / sqrt((rho_m / rho_w -
/// 1) g H cos theta).
void frontLayer(const GrainArrays& g, const std::vector<bool>& main, const MassDiagnosticsParams& p,
                MassDiagnostics& d) {
    const double back = d.front_x_m - p.front_length_m;
    double fastest = 0;
    for (std::size_t i = 0; i < g.count; ++i)
        if (main[i] && g.x[i] > back) fastest = std::max(fastest, double(g.vx[i]));
    if (fastest <= 0 || p.bin_width_m <= 0) return;
    const double threshold = p.flowing_fraction * fastest;
    const auto columns = static_cast<std::size_t>(std::ceil(p.front_length_m / p.bin_width_m)) + 1;
    std::vector<double> bottom(columns, 1e300), top(columns, -1e300);
    double sumVelocity = 0, area = 0;
    std::size_t flowing = 0;
    for (std::size_t i = 0; i < g.count; ++i) {
        if (!main[i] || g.x[i] <= back || g.vx[i] < threshold) continue;
        const auto c =
            std::min(columns - 1, static_cast<std::size_t>((g.x[i] - back) / p.bin_width_m));
        bottom[c] = std::min(bottom[c], double(g.y[i] - g.radius[i]));
        top[c] = std::max(top[c], double(g.y[i] + g.radius[i]));
        sumVelocity += g.vx[i];
        area += kPi * g.radius[i] * g.radius[i];
        ++flowing;
    }
    double sumSpan = 0;
    std::size_t spanned = 0;
    for (std::size_t c = 0; c < columns; ++c)
        if (top[c] > bottom[c]) sumSpan += top[c] - bottom[c], ++spanned;
    if (!flowing || !spanned) return;
    d.front_velocity_m_s = sumVelocity / flowing;
    d.front_thickness_m = sumSpan / spanned;
    d.front_packing_fraction = std::min(1.0, area / (sumSpan * p.bin_width_m));
    if (p.fluid_density <= 0) return;
    const double phi = d.front_packing_fraction;
    const double mixture = phi * p.grain_density + (1 - phi) * p.fluid_density;
    const double reduced = (mixture / p.fluid_density - 1) * p.gravity_m_s2 * d.front_thickness_m *
                           std::cos(p.slope_rad);
    d.froude_densimetric = reduced > 0 ? d.front_velocity_m_s / std::sqrt(reduced) : 0;
}

} // namespace

double potentialEnergy(const GrainArrays& g, double gravity) {
    double energy = 0;
    for (std::size_t i = 0; i < g.count; ++i)
        energy += g.mass[i] * gravity * g.y[i];
    return energy;
}

MassDiagnostics computeMassDiagnostics(const GrainArrays& g, const MassDiagnosticsParams& p) {
    MassDiagnostics d;
    if (g.count == 0) return d;
    for (std::size_t i = 0; i < g.count; ++i)
        d.kinetic_energy_j_m += 0.5 * g.mass[i] * (g.vx[i] * g.vx[i] + g.vy[i] * g.vy[i]) +
                                0.5 * g.inertia[i] * g.omega[i] * g.omega[i];
    d.ke_over_ep0 =
        p.initial_potential_j_m > 0 ? d.kinetic_energy_j_m / p.initial_potential_j_m : 0;

    const std::vector<bool> main = mainMass(g, p.contact_gap_m, p.bridge_gap_m);
    double grainArea = 0;
    for (std::size_t i = 0; i < g.count; ++i) {
        if (!main[i]) continue;
        ++d.main_mass_grains;
        d.front_x_m = std::max(d.front_x_m, double(g.x[i] + g.radius[i]));
        d.height_m = std::max(d.height_m, double(g.y[i] + g.radius[i]));
        grainArea += kPi * g.radius[i] * g.radius[i];
    }
    d.runout_normalised =
        p.column_width_m > 0 ? (d.front_x_m - p.column_width_m) / p.column_width_m : 0;

    const std::vector<double> top = surfaceHeights(g, main, p.bin_width_m, d.front_x_m);
    double areaUnder = 0;
    for (std::size_t c = 0; c < top.size(); ++c) {
        const double left = c * p.bin_width_m, right = std::min(d.front_x_m, left + p.bin_width_m);
        areaUnder += top[c] * std::max(0.0, right - left);
    }
    d.packing_fraction = areaUnder > 0 ? grainArea / areaUnder : 0;

    frontLayer(g, main, p, d);
    return d;
}

} // namespace lbdem::solver
