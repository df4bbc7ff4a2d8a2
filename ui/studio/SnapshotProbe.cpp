// Looking up fluid and grain values of a snapshot at a point.
#include "ui/studio/SnapshotProbe.h"

#include <QObject>

#include <cmath>

namespace lbdem::studio {

ProbeResult probeSnapshot(const solver::Snapshot& snapshot, double x, double y) {
    ProbeResult result;
    result.x = x;
    result.y = y;
    result.inDomain =
        x >= 0 && y >= 0 && x <= snapshot.domain_width_m && y <= snapshot.domain_height_m;
    if (snapshot.fluid && snapshot.fluid->spacing_m > 0) {
        const auto& fluid = *snapshot.fluid;
        const long ix = std::lround((x - fluid.origin_x) / fluid.spacing_m);
        const long iy = std::lround((y - fluid.origin_y) / fluid.spacing_m);
        if (ix >= 0 && iy >= 0 && ix < fluid.nx && iy < fluid.ny) {
            const std::size_t k = std::size_t(iy) * std::size_t(fluid.nx) + std::size_t(ix);
            auto at = [k](const std::vector<float>& field) -> std::optional<float> {
                return k < field.size() ? std::optional<float>(field[k]) : std::nullopt;
            };
            result.ux = at(fluid.ux);
            result.uy = at(fluid.uy);
            result.pressure = at(fluid.pressure);
            result.vorticity = at(fluid.vorticity);
            result.solid = at(fluid.solid);
        }
    }
    const auto& grains = snapshot.grains;
    for (std::size_t i = 0; i < grains.size(); ++i) {
        const double dx = x - grains.x[i], dy = y - grains.y[i];
        if (dx * dx + dy * dy > double(grains.radius[i]) * grains.radius[i]) continue;
        result.grain = i;
        result.grainRadius = grains.radius[i];
        result.grainSpeed = std::hypot(grains.vx[i], grains.vy[i]);
        result.grainOmega = i < grains.omega.size() ? grains.omega[i] : 0.f;
        result.grainForce = i < grains.fx.size() ? std::hypot(grains.fx[i], grains.fy[i]) : 0.f;
        break;
    }
    return result;
}

QString describeProbe(const ProbeResult& r) {
    if (!r.inDomain) return QObject::tr("outside the domain");
    QString text = QString("x %1 m, y %2 m").arg(r.x, 0, 'g', 4).arg(r.y, 0, 'g', 4);
    if (r.ux && r.uy)
        text += QString(" | fluid u (%1, %2) m/s").arg(*r.ux, 0, 'g', 3).arg(*r.uy, 0, 'g', 3);
    if (r.pressure) text += QString(", p %1 Pa").arg(*r.pressure, 0, 'g', 4);
    if (r.vorticity) text += QString(", vorticity %1 1/s").arg(*r.vorticity, 0, 'g', 3);
    if (r.solid) text += QString(", solid %1").arg(*r.solid, 0, 'f', 2);
    if (r.grain)
        text += QString(" | grain %1: d %2 mm, speed %3 m/s, omega %4 rad/s, force %5 N/m")
                    .arg(*r.grain)
                    .arg(2e3 * r.grainRadius, 0, 'g', 3)
                    .arg(r.grainSpeed, 0, 'g', 3)
                    .arg(r.grainOmega, 0, 'g', 3)
                    .arg(r.grainForce, 0, 'g', 3);
    return text;
}

} // namespace lbdem::studio
