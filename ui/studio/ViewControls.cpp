// Building the view controls and translating them to a LayerSet.
#include "ui/studio/ViewControls.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>

namespace lbdem::studio {

ViewControls::ViewControls(QWidget* parent) : QWidget(parent) {
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(4, 2, 4, 2);
    auto check = [&](const QString& text, const QString& name, const QString& tip) {
        auto* box = new QCheckBox(text);
        box->setObjectName(name);
        box->setToolTip(tip);
        connect(box, &QCheckBox::toggled, this, &ViewControls::emitChange);
        row->addWidget(box);
        return box;
    };
    m_fluid = check(tr("&Fluid"), "layerFluid", tr("Colour map and contour lines of the fluid"));
    m_grains = check(tr("&Grains"), "layerGrains", tr("Discs at their contact radius"));
    m_chains = check(tr("&Chains"), "layerChains",
                     tr("Lines between touching grains, width and colour by normal force"));
    m_outline = check(tr("&Outline"), "layerOutline", tr("The flow-front outline of the mass"));
    m_streamlines = check(tr("Stream&lines"), "layerStreamlines", tr("Streamlines near the front"));
    row->addSpacing(8);
    row->addWidget(new QLabel(tr("Fluid by")));
    m_fluidField = new QComboBox;
    m_fluidField->setObjectName("fluidField");
    m_fluidField->addItems({tr("speed"), tr("pressure"), tr("vorticity")});
    m_fluidField->setToolTip(tr("Fluid colour map: speed [m/s], excess pore pressure [Pa] or "
                                "vorticity [1/s]"));
    row->addWidget(m_fluidField);
    row->addWidget(new QLabel(tr("Grains by")));
    m_grainColoring = new QComboBox;
    m_grainColoring->setObjectName("grainColoring");
    m_grainColoring->addItems({tr("speed"), tr("force")});
    m_grainColoring->setToolTip(tr("Grain colours: speed [m/s] or summed contact force [N/m]"));
    row->addWidget(m_grainColoring);
    for (QComboBox* combo : {m_fluidField, m_grainColoring})
        connect(combo, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
                &ViewControls::emitChange);
    row->addWidget(new QLabel(tr("Chains >")));
    m_chainThreshold = new QDoubleSpinBox;
    m_chainThreshold->setObjectName("chainThreshold");
    m_chainThreshold->setRange(0.0, 5.0);
    m_chainThreshold->setSingleStep(0.25);
    m_chainThreshold->setValue(1.0);
    m_chainThreshold->setSuffix(tr(" x mean"));
    m_chainThreshold->setToolTip(tr("Draw force chains whose normal force exceeds this multiple "
                                    "of the mean (0 draws every contact)"));
    connect(m_chainThreshold, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
            &ViewControls::chainThresholdChanged);
    row->addWidget(m_chainThreshold);
    row->addStretch(1);
    auto* fit = new QToolButton;
    fit->setText(tr("Fit"));
    fit->setToolTip(tr("Show the whole domain (drag to pan, wheel to zoom)"));
    connect(fit, &QToolButton::clicked, this, &ViewControls::resetCameraRequested);
    row->addWidget(fit);
    setLayers(vis::LayerSet{});
}

void ViewControls::setLayers(const vis::LayerSet& layers) {
    m_filling = true;
    m_fluid->setChecked(layers.fluid);
    m_grains->setChecked(layers.grains);
    m_chains->setChecked(layers.chains);
    m_outline->setChecked(layers.outline);
    m_streamlines->setChecked(layers.streamlines);
    m_fluidField->setCurrentIndex(static_cast<int>(layers.fluidField));
    m_grainColoring->setCurrentIndex(static_cast<int>(layers.grainColoring));
    m_filling = false;
}

vis::LayerSet ViewControls::layers() const {
    vis::LayerSet layers;
    layers.fluid = m_fluid->isChecked();
    layers.grains = m_grains->isChecked();
    layers.chains = m_chains->isChecked();
    layers.outline = m_outline->isChecked();
    layers.streamlines = m_streamlines->isChecked();
    layers.fluidField = static_cast<vis::FluidField>(m_fluidField->currentIndex());
    layers.grainColoring = static_cast<vis::GrainColoring>(m_grainColoring->currentIndex());
    return layers;
}

void ViewControls::emitChange() {
    if (!m_filling) emit layersChanged(layers());
}

} // namespace lbdem::studio
