// The live view's options kept in QSettings: layers, colourings and colour ranges.
#pragma once

#include "ui/vis/LayerSet.h"

class QSettings;

namespace lbdem::studio {

/// Reads the view options written by saveViewSettings over `defaults`; a missing or unreadable
/// entry (say, from another version) keeps its default.
vis::LayerSet loadViewSettings(const QSettings& settings, vis::LayerSet defaults);

/// Writes `layers` under view/: the visible layers, the fluid field and grain colouring, and
/// the colour range of every field and colouring (view/range/fluid/speed/fixed, .../min, ...).
void saveViewSettings(QSettings& settings, const vis::LayerSet& layers);

} // namespace lbdem::studio
