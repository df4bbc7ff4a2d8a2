// DEM state to and from named arrays.
#include "solver/scene/ColumnState.h"

#include <stdexcept>

namespace lbdem::solver {

namespace {

/// The per-disc arrays that define the state, with their archive names.
std::vector<std::pair<const char*, std::vector<Real>*>> discArrays(dem::Particles& p) {
    return {{"dem/x", &p.x},
            {"dem/y", &p.y},
            {"dem/vx", &p.vx},
            {"dem/vy", &p.vy},
            {"dem/omega", &p.omega},
            {"dem/fx", &p.fx},
            {"dem/fy", &p.fy},
            {"dem/torque", &p.torque},
            {"dem/ext_fx", &p.ext_fx},
            {"dem/ext_fy", &p.ext_fy},
            {"dem/ext_torque", &p.ext_torque}};
}

} // namespace

void saveColumnState(const ColumnScene& column, StateArchive& archive) {
    const auto& system = column.system();
    auto& particles = const_cast<dem::Particles&>(system.particles()); // read only below
    for (const auto& [name, values] : discArrays(particles))
        archive.reals[name] = *values;
    archive.reals["dem/radius"] = particles.radius;
    archive.reals["dem/time"] = {system.time()};
    archive.integers["dem/steps"] = {system.stepCount()};
    std::vector<std::int64_t> wallActive;
    for (const auto& wall : system.walls())
        wallActive.push_back(wall.active ? 1 : 0);
    archive.integers["dem/wall_active"] = wallActive;
    auto& pairs = archive.integers["dem/history_pairs"];
    auto& springs = archive.reals["dem/history_springs"];
    for (const auto& h : system.contactHistory()) {
        pairs.insert(pairs.end(), {h.i, h.j, h.is_wall ? 1 : 0});
        springs.insert(springs.end(), {h.ut, h.ur});
    }
}

void restoreColumnState(const StateArchive& archive, ColumnScene& column) {
    auto& system = column.system();
    auto& particles = system.particles();
    if (archive.real("dem/x").size() != particles.size())
        throw std::runtime_error("the checkpoint holds " +
                                 std::to_string(archive.real("dem/x").size()) +
                                 " discs but the case builds " + std::to_string(particles.size()));
    for (const auto& [name, values] : discArrays(particles))
        *values = archive.real(name);
    particles.radius = archive.real("dem/radius");
    system.setClock(archive.real("dem/time").at(0), archive.integer("dem/steps").at(0));
    const auto& active = archive.integer("dem/wall_active");
    for (std::size_t w = 0; w < active.size() && w < system.walls().size(); ++w)
        system.setWallActive(w, active[w] != 0);
    const auto& pairs = archive.integer("dem/history_pairs");
    const auto& springs = archive.real("dem/history_springs");
    std::vector<dem::ContactHistory> history(pairs.size() / 3);
    for (std::size_t k = 0; k < history.size(); ++k) {
        history[k].i = static_cast<std::int32_t>(pairs[3 * k]);
        history[k].j = static_cast<std::int32_t>(pairs[3 * k + 1]);
        history[k].is_wall = pairs[3 * k + 2] != 0;
        history[k].ut = springs[2 * k];
        history[k].ur = springs[2 * k + 1];
    }
    system.invalidateNeighbours();
    system.restoreContactHistory(history);
}

} // namespace lbdem::solver
