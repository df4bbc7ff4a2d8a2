// The row of controls above the live view: layer toggles, colouring and the camera reset.
#pragma once

#include "ui/vis/LayerSet.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;

namespace lbdem::studio {

/// Edits a vis::LayerSet; every change is emitted at once.
class ViewControls : public QWidget {
    Q_OBJECT
public:
    explicit ViewControls(QWidget* parent = nullptr);

    /// Show layers in the controls (emits nothing).
    void setLayers(const vis::LayerSet& layers);
    /// The layers as the controls show them.
    vis::LayerSet layers() const;

signals:
    /// The user changed a toggle or a colouring.
    void layersChanged(const lbdem::vis::LayerSet& layers);
    /// Force chains are drawn above factor x the mean normal force (0: all).
    void chainThresholdChanged(double factor);
    /// The user asked to fit the whole domain into the view.
    void resetCameraRequested();

private:
    void emitChange();

    QCheckBox *m_fluid, *m_grains, *m_chains, *m_outline, *m_streamlines;
    QComboBox *m_fluidField, *m_grainColoring;
    QDoubleSpinBox* m_chainThreshold;
    bool m_filling = false;
};

} // namespace lbdem::studio
