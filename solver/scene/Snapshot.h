// An immutable copy of what viewing and export need at one output time (float precision).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lbdem::solver {

/// Discs at one instant, structure of arrays, SI units.
struct SnapshotGrains {
    std::vector<float> x, y;               ///< centre [m]
    std::vector<float> radius;             ///< contact radius R [m]
    std::vector<float> vx, vy;             ///< velocity [m/s]
    std::vector<float> omega;              ///< angular velocity [rad/s], counter-clockwise positive
    std::vector<float> fx, fy;             ///< total force per unit thickness [N/m]
    std::vector<float> hydro_fx, hydro_fy; ///< hydrodynamic part of the force [N/m] (empty if dry)
    std::size_t size() const { return x.size(); }
};

/// Grain-grain and grain-wall contacts; a wall contact has j = -1 and its point in (wx, wy).
struct SnapshotContacts {
    std::vector<std::int32_t> i, j;      ///< disc indices (j = -1: wall)
    std::vector<float> wx, wy;           ///< contact point on the wall [m] (wall contacts only)
    std::vector<float> normal_force;     ///< magnitude of the normal force [N/m]
    std::vector<float> tangential_force; ///< magnitude of the tangential force [N/m]
    std::size_t size() const { return i.size(); }
};

/// Fluid fields on a (possibly down-sampled) regular grid, x fastest: index = iy * nx + ix.
struct SnapshotFluid {
    int nx = 0, ny = 0;               ///< grid points
    float spacing_m = 0;              ///< distance between grid points
    float origin_x = 0, origin_y = 0; ///< position of point (0, 0) [m]
    std::vector<float> ux, uy;        ///< velocity [m/s]
    std::vector<float> pressure;      ///< excess pore pressure [Pa]
    std::vector<float> vorticity;     ///< du_y/dx - du_x/dy [1/s]
    std::vector<float> solid;         ///< solid fraction 0..1
};

/// A wall segment of the scene (domain walls, gate, fixed obstacles).
struct SnapshotWall {
    float x0, y0, x1, y1;
};

/// Samples of one quantity along a probe line (e.g. excess pore pressure along the failure plane).
struct SnapshotProbe {
    std::string quantity;      ///< column name with its SI unit, e.g. excess_pore_pressure_pa
    std::vector<double> s;     ///< distance along the line from its start [m]
    std::vector<double> x, y;  ///< position of each sample [m]
    std::vector<double> value; ///< the quantity; NaN where the point is not in the fluid
    std::size_t size() const { return s.size(); }
};

/// Everything consumers may look at; never points into live solver memory.
struct Snapshot {
    std::string case_name;
    long long step = 0;
    double time_s = 0;
    double tc_s = 0; ///< tau_c, so that time_s / tc_s is t / tau_c
    double domain_width_m = 0, domain_height_m = 0;
    double slope_deg = 0;
    SnapshotGrains grains;
    SnapshotContacts contacts;
    std::optional<SnapshotFluid> fluid; ///< absent in dry scenes
    std::vector<SnapshotWall> walls;
    std::vector<std::pair<float, float>> outline; ///< flow-front outline polyline [m]
    std::map<std::string, double> metrics;        ///< timeseries.csv columns at this time
    std::map<std::string, SnapshotProbe> probes;  ///< probe lines by name (submerged scenes)

    double timeOverTc() const { return tc_s > 0 ? time_s / tc_s : 0.0; }
};

using SnapshotPtr = std::shared_ptr<const Snapshot>;

} // namespace lbdem::solver
