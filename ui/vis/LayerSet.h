// Which visual layers a scene shows, and how the fluid and grains are coloured.
#pragma once

#include <string>

namespace lbdem::vis {

/// Scalar the fluid layer colours by.
enum class FluidField { Speed, Pressure, Vorticity };
/// Scalar the grain layer colours by.
enum class GrainColoring { Speed, ContactForce };

/// Visibility of each layer plus the colouring choices; the defaults show everything but
/// streamlines.
struct LayerSet {
    bool fluid = true;
    bool grains = true;
    bool chains = true;
    bool outline = true;
    bool streamlines = false;
    FluidField fluidField = FluidField::Speed;
    GrainColoring grainColoring = GrainColoring::Speed;
};

/// Parses "fluid,grains,chains,outline,streamlines" (any subset, comma separated); an unknown
/// name throws solver::InputError naming the nearest known layer.
LayerSet parseLayerSet(const std::string& text);
/// The comma-separated names of the visible layers (the inverse of parseLayerSet).
std::string layerSetToString(const LayerSet& layers);
/// Parses "speed", "pressure" or "vorticity"; throws solver::InputError otherwise.
FluidField parseFluidField(const std::string& text);
/// Parses "speed" or "force"; throws solver::InputError otherwise.
GrainColoring parseGrainColoring(const std::string& text);

} // namespace lbdem::vis
