// The rows of controls above the live view: layer toggles, colourings, colour ranges and the
// camera reset.
#pragma once

#include "ui/vis/LayerSet.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;

namespace lbdem::studio {

class ColorRangeEdit;

/// Edits a vis::LayerSet; every change is emitted at once. Each fluid field and grain colouring
/// keeps its own colour range: switching the field shows (and applies) that field's range.
class ViewControls : public QWidget {
    Q_OBJECT
public:
    explicit ViewControls(QWidget* parent = nullptr);

    /// Show layers in the controls (emits nothing).
    void setLayers(const vis::LayerSet& layers);
    /// The layers as the controls show them.
    vis::LayerSet layers() const { return m_layers; }

public slots:
    /// Show the ranges the view drew with in the range controls that are automatic.
    void showColorRanges(const lbdem::vis::ColorRange& fluid, const lbdem::vis::ColorRange& grain);

signals:
    /// The user changed a toggle, a colouring or a colour range.
    void layersChanged(const lbdem::vis::LayerSet& layers);
    /// Force chains are drawn above factor x the mean normal force (0: all).
    void chainThresholdChanged(double factor);
    /// The user asked to fit the whole domain into the view.
    void resetCameraRequested();

private:
    void onToggled();
    void onColoringChosen();
    void emitChange();

    vis::LayerSet m_layers;
    QCheckBox *m_fluid, *m_grains, *m_chains, *m_outline, *m_streamlines;
    QComboBox *m_fluidField, *m_grainColoring;
    ColorRangeEdit *m_fluidRange, *m_grainRange;
    QDoubleSpinBox* m_chainThreshold;
    bool m_filling = false;
};

} // namespace lbdem::studio
