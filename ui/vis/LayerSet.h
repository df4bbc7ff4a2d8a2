// Which visual layers a scene shows, and how the fluid and grains are coloured.
#pragma once

#include <array>
#include <string>

namespace lbdem::vis {

/// Scalar the fluid layer colours by.
enum class FluidField { Speed, Pressure, Vorticity };
/// Scalar the grain layer colours by.
enum class GrainColoring { Speed, ContactForce };

/// The values a colour map spans: fitted to each frame (auto) or fixed to [min, max] in the
/// quantity's SI unit, so that colours mean the same from frame to frame.
struct ColorRange {
    bool fixed = false;
    double min = 0.0;
    double max = 1.0;
    bool operator==(const ColorRange& other) const {
        return fixed == other.fixed && min == other.min && max == other.max;
    }
    bool operator!=(const ColorRange& other) const { return !(*this == other); }
};

/// Visibility of each layer plus the colouring choices; the defaults show everything but
/// streamlines, with automatic colour ranges.
struct LayerSet {
    bool fluid = true;
    bool grains = true;
    bool chains = true;
    bool outline = true;
    bool streamlines = false;
    FluidField fluidField = FluidField::Speed;
    GrainColoring grainColoring = GrainColoring::Speed;
    /// Colour range of each fluid field, indexed by FluidField (each keeps its own range).
    std::array<ColorRange, 3> fluidRanges{};
    /// Colour range of each grain colouring, indexed by GrainColoring.
    std::array<ColorRange, 2> grainRanges{};

    /// The colour range of the fluid field shown.
    ColorRange& fluidRange() { return fluidRanges[static_cast<int>(fluidField)]; }
    /// The colour range of the fluid field shown.
    const ColorRange& fluidRange() const { return fluidRanges[static_cast<int>(fluidField)]; }
    /// The colour range of the grain colouring shown.
    ColorRange& grainRange() { return grainRanges[static_cast<int>(grainColoring)]; }
    /// The colour range of the grain colouring shown.
    const ColorRange& grainRange() const { return grainRanges[static_cast<int>(grainColoring)]; }
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
/// "speed", "pressure" or "vorticity" (the inverse of parseFluidField).
std::string fluidFieldName(FluidField field);
/// "speed" or "force" (the inverse of parseGrainColoring).
std::string grainColoringName(GrainColoring coloring);

} // namespace lbdem::vis
