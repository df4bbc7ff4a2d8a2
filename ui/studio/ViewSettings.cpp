// Reading and writing the view options under the view/ group of QSettings.
#include "ui/studio/ViewSettings.h"

#include <QSettings>
#include <QString>

#include <cmath>

namespace lbdem::studio {

namespace {

/// The settings key prefix of one quantity's range, e.g. "view/range/fluid/speed/".
QString rangeKey(const char* layer, const std::string& quantity) {
    return QString("view/range/%1/%2/").arg(layer, QString::fromStdString(quantity));
}

/// Reads a range saved under `key`; anything missing or not a valid range keeps `range`.
vis::ColorRange loadRange(const QSettings& settings, const QString& key, vis::ColorRange range) {
    bool okMin = false, okMax = false;
    const double min = settings.value(key + "min").toDouble(&okMin);
    const double max = settings.value(key + "max").toDouble(&okMax);
    if (!okMin || !okMax || !std::isfinite(min) || !std::isfinite(max) || !(max > min))
        return range;
    return {settings.value(key + "fixed", false).toBool(), min, max};
}

/// Writes `range` under `key`.
void saveRange(QSettings& settings, const QString& key, const vis::ColorRange& range) {
    settings.setValue(key + "fixed", range.fixed);
    settings.setValue(key + "min", range.min);
    settings.setValue(key + "max", range.max);
}

} // namespace

vis::LayerSet loadViewSettings(const QSettings& settings, vis::LayerSet layers) {
    // Each entry on its own, so one bad value does not discard the others.
    auto read = [&settings](const char* key, auto parse) {
        const QString text = settings.value(key).toString();
        if (text.isEmpty()) return;
        try {
            parse(text.toStdString());
        } catch (const std::exception&) {
            // A value this version does not know: keep the default.
        }
    };
    read("view/layers", [&layers](const std::string& text) {
        const vis::LayerSet shown = vis::parseLayerSet(text);
        layers.fluid = shown.fluid, layers.grains = shown.grains, layers.chains = shown.chains;
        layers.outline = shown.outline, layers.streamlines = shown.streamlines;
    });
    read("view/fluidField",
         [&layers](const std::string& text) { layers.fluidField = vis::parseFluidField(text); });
    read("view/grainColoring", [&layers](const std::string& text) {
        layers.grainColoring = vis::parseGrainColoring(text);
    });
    for (std::size_t k = 0; k < layers.fluidRanges.size(); ++k) {
        const auto field = static_cast<vis::FluidField>(k);
        layers.fluidRanges[k] = loadRange(settings, rangeKey("fluid", vis::fluidFieldName(field)),
                                          layers.fluidRanges[k]);
    }
    for (std::size_t k = 0; k < layers.grainRanges.size(); ++k) {
        const auto coloring = static_cast<vis::GrainColoring>(k);
        layers.grainRanges[k] = loadRange(
            settings, rangeKey("grains", vis::grainColoringName(coloring)), layers.grainRanges[k]);
    }
    return layers;
}

void saveViewSettings(QSettings& settings, const vis::LayerSet& layers) {
    settings.setValue("view/layers", QString::fromStdString(vis::layerSetToString(layers)));
    settings.setValue("view/fluidField",
                      QString::fromStdString(vis::fluidFieldName(layers.fluidField)));
    settings.setValue("view/grainColoring",
                      QString::fromStdString(vis::grainColoringName(layers.grainColoring)));
    for (std::size_t k = 0; k < layers.fluidRanges.size(); ++k)
        saveRange(settings, rangeKey("fluid", vis::fluidFieldName(static_cast<vis::FluidField>(k))),
                  layers.fluidRanges[k]);
    for (std::size_t k = 0; k < layers.grainRanges.size(); ++k)
        saveRange(settings,
                  rangeKey("grains", vis::grainColoringName(static_cast<vis::GrainColoring>(k))),
                  layers.grainRanges[k]);
}

} // namespace lbdem::studio
