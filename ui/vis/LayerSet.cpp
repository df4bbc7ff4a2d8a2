// Parsing of the --layers list and of the colouring choices shared by the CLI and the studio.
#include "ui/vis/LayerSet.h"

#include "solver/core/InputError.h"
#include "solver/core/TextDistance.h"

#include <sstream>
#include <vector>

namespace lbdem::vis {

namespace {

const std::vector<std::string> kLayerNames = {"fluid", "grains", "chains", "outline",
                                              "streamlines"};

/// The message for an unknown word, with a suggestion when one is close.
std::string unknownWord(const std::string& what, const std::string& word,
                        const std::vector<std::string>& known) {
    std::string message = "unknown " + what + " '" + word + "'";
    const std::string nearest = solver::nearestWord(word, known);
    if (!nearest.empty()) message += " (did you mean '" + nearest + "'?)";
    message += "; known: ";
    for (std::size_t k = 0; k < known.size(); ++k)
        message += (k ? ", " : "") + known[k];
    return message;
}

} // namespace

LayerSet parseLayerSet(const std::string& text) {
    LayerSet layers;
    layers.fluid = layers.grains = layers.chains = layers.outline = layers.streamlines = false;
    std::istringstream stream(text);
    std::string name;
    bool any = false;
    while (std::getline(stream, name, ',')) {
        if (name.empty()) continue;
        any = true;
        if (name == "fluid")
            layers.fluid = true;
        else if (name == "grains")
            layers.grains = true;
        else if (name == "chains")
            layers.chains = true;
        else if (name == "outline")
            layers.outline = true;
        else if (name == "streamlines")
            layers.streamlines = true;
        else
            throw solver::InputError(unknownWord("layer", name, kLayerNames));
    }
    if (!any)
        throw solver::InputError("--layers needs at least one of fluid, grains, chains, "
                                 "outline, streamlines");
    return layers;
}

std::string layerSetToString(const LayerSet& layers) {
    const bool shown[] = {layers.fluid, layers.grains, layers.chains, layers.outline,
                          layers.streamlines};
    std::string text;
    for (std::size_t k = 0; k < kLayerNames.size(); ++k)
        if (shown[k]) text += (text.empty() ? "" : ",") + kLayerNames[k];
    return text;
}

FluidField parseFluidField(const std::string& text) {
    if (text == "speed") return FluidField::Speed;
    if (text == "pressure") return FluidField::Pressure;
    if (text == "vorticity") return FluidField::Vorticity;
    throw solver::InputError(unknownWord("fluid field", text, {"speed", "pressure", "vorticity"}));
}

GrainColoring parseGrainColoring(const std::string& text) {
    if (text == "speed") return GrainColoring::Speed;
    if (text == "force") return GrainColoring::ContactForce;
    throw solver::InputError(unknownWord("grain colouring", text, {"speed", "force"}));
}

std::string fluidFieldName(FluidField field) {
    switch (field) {
    case FluidField::Pressure:
        return "pressure";
    case FluidField::Vorticity:
        return "vorticity";
    case FluidField::Speed:
        break;
    }
    return "speed";
}

std::string grainColoringName(GrainColoring coloring) {
    return coloring == GrainColoring::ContactForce ? "force" : "speed";
}

} // namespace lbdem::vis
