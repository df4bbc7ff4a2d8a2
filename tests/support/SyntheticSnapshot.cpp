// Synthetic snapshots: closed-form fields, so every run of a test sees the same data.
#include "tests/support/SyntheticSnapshot.h"

#include "ui/vis/VtkRunWriter.h"

#include <cmath>
#include <vector>

namespace lbdem::support {

namespace {

constexpr double kWidth = 0.2, kHeight = 0.1; // domain [m]
constexpr double kSpacing = 3e-3;             // hexagonal lattice spacing = largest diameter [m]
constexpr double kColumnHeight = 0.05;        // initial column height [m]
constexpr double kPi = 3.14159265358979323846;

/// The x of the granular surface at height y for frame `frame` (spreads and lowers with time).
double frontAt(double y, int frame) {
    const double height = kColumnHeight * (1.0 - 0.08 * frame);
    if (y >= height) return 0;
    return 0.035 + (0.045 + 0.012 * frame) * std::pow(1.0 - y / height, 1.5);
}

void addGrains(solver::Snapshot& s, int frame, std::vector<std::vector<int>>& lattice) {
    const double height = kColumnHeight * (1.0 - 0.08 * frame);
    const int rows = static_cast<int>(height / (kSpacing * std::sqrt(3.0) / 2)) + 1;
    const int cols = static_cast<int>(kWidth / kSpacing);
    lattice.assign(static_cast<std::size_t>(rows),
                   std::vector<int>(static_cast<std::size_t>(cols), -1));
    auto& g = s.grains;
    for (int row = 0; row < rows; ++row)
        for (int col = 0; col < cols; ++col) {
            const int n = static_cast<int>(g.size());
            const double r =
                0.5 * kSpacing * (0.85 + 0.15 * (0.5 + 0.5 * std::sin(1.7 * (row * cols + col))));
            const double x = 0.5 * kSpacing + (row % 2) * 0.5 * kSpacing + col * kSpacing;
            const double y = 0.5 * kSpacing + row * kSpacing * std::sqrt(3.0) / 2;
            if (x + r > frontAt(y, frame)) continue;
            lattice[static_cast<std::size_t>(row)][static_cast<std::size_t>(col)] = n;
            const double speed =
                0.15 * (y / kColumnHeight) * (x / frontAt(0, frame)) * (frame + 1) / 4.0;
            g.x.push_back(static_cast<float>(x));
            g.y.push_back(static_cast<float>(y));
            g.radius.push_back(static_cast<float>(r));
            g.vx.push_back(static_cast<float>(speed));
            g.vy.push_back(static_cast<float>(-0.3 * speed));
            g.omega.push_back(static_cast<float>(-speed / r * 0.5));
            g.fx.push_back(static_cast<float>(1e-3 * std::cos(0.3 * n)));
            g.fy.push_back(static_cast<float>(-0.02 * r / 1.5e-3));
            g.hydro_fx.push_back(static_cast<float>(-2e-4 * speed));
            g.hydro_fy.push_back(static_cast<float>(1e-4));
        }
}

void addContact(solver::Snapshot& s, int i, int j, float wx, float wy) {
    auto& c = s.contacts;
    const double depth = (kColumnHeight - s.grains.y[static_cast<std::size_t>(i)]) / kColumnHeight;
    const double force = 0.5 * depth * (1.0 + 0.6 * std::sin(0.7 * c.size() + 0.3 * i));
    c.i.push_back(i);
    c.j.push_back(j);
    c.wx.push_back(wx);
    c.wy.push_back(wy);
    c.normal_force.push_back(static_cast<float>(std::abs(force) + 0.01));
    c.tangential_force.push_back(static_cast<float>(0.3 * std::abs(force)));
}

void addContacts(solver::Snapshot& s, const std::vector<std::vector<int>>& lattice) {
    const int rows = static_cast<int>(lattice.size());
    for (int row = 0; row < rows; ++row) {
        const auto& line = lattice[static_cast<std::size_t>(row)];
        const int cols = static_cast<int>(line.size());
        for (int col = 0; col < cols; ++col) {
            const int i = line[static_cast<std::size_t>(col)];
            if (i < 0) continue;
            if (col + 1 < cols && line[static_cast<std::size_t>(col + 1)] >= 0)
                addContact(s, i, line[static_cast<std::size_t>(col + 1)], 0, 0);
            if (row + 1 < rows) {
                // Upper neighbours on a hexagonal lattice: odd rows are shifted half a spacing
                // right.
                const int left = col - 1 + row % 2, right = col + row % 2;
                for (const int up : {left, right})
                    if (up >= 0 && up < cols &&
                        lattice[static_cast<std::size_t>(row + 1)][static_cast<std::size_t>(up)] >=
                            0)
                        addContact(s, i,
                                   lattice[static_cast<std::size_t>(row + 1)]
                                          [static_cast<std::size_t>(up)],
                                   0, 0);
            }
            if (row == 0) addContact(s, i, -1, s.grains.x[static_cast<std::size_t>(i)], 0.0f);
            if (col == 0 && row % 2 == 0)
                addContact(s, i, -1, 0.0f, s.grains.y[static_cast<std::size_t>(i)]);
        }
    }
}

void addFluid(solver::Snapshot& s, int frame) {
    solver::SnapshotFluid f;
    f.nx = 101;
    f.ny = 51;
    f.spacing_m = static_cast<float>(kWidth / (f.nx - 1));
    const std::size_t n = static_cast<std::size_t>(f.nx) * f.ny;
    f.ux.resize(n), f.uy.resize(n), f.pressure.resize(n), f.vorticity.resize(n), f.solid.resize(n);
    // Lamb-Oseen vortex: u_theta = G/(2 pi r) (1 - exp(-r^2/rc^2)), vorticity G/(pi rc^2)
    // exp(-r^2/rc^2).
    const double gamma = 0.01, core = 0.015;
    const double cx = frontAt(0, frame) + 0.02, cy = 0.035;
    for (int iy = 0; iy < f.ny; ++iy)
        for (int ix = 0; ix < f.nx; ++ix) {
            const std::size_t k = static_cast<std::size_t>(iy) * f.nx + ix;
            const double x = ix * f.spacing_m, y = iy * f.spacing_m;
            const double dx = x - cx, dy = y - cy, r2 = dx * dx + dy * dy + 1e-12;
            const double decay = std::exp(-r2 / (core * core));
            const double utheta = gamma / (2 * kPi * std::sqrt(r2)) * (1 - decay);
            f.ux[k] = static_cast<float>(-utheta * dy / std::sqrt(r2) + 0.02 * y / kHeight);
            f.uy[k] = static_cast<float>(utheta * dx / std::sqrt(r2));
            f.vorticity[k] = static_cast<float>(gamma / (kPi * core * core) * decay);
            f.pressure[k] = static_cast<float>(-500.0 * utheta * utheta + 2.0 * (0.5 - x / kWidth));
            f.solid[k] = x < frontAt(y, frame) ? 0.6f : 0.0f;
        }
    s.fluid = std::move(f);
}

} // namespace

solver::Snapshot syntheticSnapshot(int frame, bool wet) {
    solver::Snapshot s;
    s.case_name = "synthetic";
    s.step = 1000LL * frame;
    s.time_s = 0.025 * frame;
    s.tc_s = 0.1;
    s.domain_width_m = kWidth;
    s.domain_height_m = kHeight;
    s.slope_deg = 5.0;
    std::vector<std::vector<int>> lattice;
    addGrains(s, frame, lattice);
    addContacts(s, lattice);
    if (wet) addFluid(s, frame);
    const double height = kColumnHeight * (1.0 - 0.08 * frame);
    s.outline.emplace_back(0.0f, static_cast<float>(height));
    for (int k = 0; k <= 40; ++k) {
        const double y = height * (1.0 - k / 40.0);
        s.outline.emplace_back(static_cast<float>(frontAt(y - 1e-9, frame)), static_cast<float>(y));
    }
    s.walls = {
        {0, 0, static_cast<float>(kWidth), 0},
        {0, 0, 0, static_cast<float>(kHeight)},
        {static_cast<float>(kWidth), 0, static_cast<float>(kWidth), static_cast<float>(kHeight)}};
    s.metrics["runout_m"] = frontAt(0, frame);
    s.metrics["t_over_tc"] = s.timeOverTc();
    return s;
}

void writeSyntheticRun(const std::string& runDir, int frames, bool wet) {
    vis::VtkRunWriter writer(runDir);
    for (int frame = 0; frame < frames; ++frame)
        writer.write(syntheticSnapshot(frame, wet));
}

} // namespace lbdem::support
