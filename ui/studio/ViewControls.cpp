// Building the view controls and translating them to a LayerSet.
#include "ui/studio/ViewControls.h"

#include "ui/studio/ColorRangeEdit.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>
#include <QVBoxLayout>

namespace lbdem::studio {

ViewControls::ViewControls(QWidget* parent) : QWidget(parent) {
    auto* rows = new QVBoxLayout(this);
    rows->setContentsMargins(4, 2, 4, 2);
    rows->setSpacing(2);
    auto* row = new QHBoxLayout;
    rows->addLayout(row);
    auto check = [&](const QString& text, const QString& name, const QString& tip) {
        auto* box = new QCheckBox(text);
        box->setObjectName(name);
        box->setToolTip(tip);
        connect(box, &QCheckBox::toggled, this, &ViewControls::onToggled);
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

    // Second row: what the fluid and the grains are coloured by, and over which range.
    auto* colours = new QHBoxLayout;
    rows->addLayout(colours);
    colours->addWidget(new QLabel(tr("Fluid by")));
    m_fluidField = new QComboBox;
    m_fluidField->setObjectName("fluidField");
    m_fluidField->addItems({tr("speed"), tr("pressure"), tr("vorticity")});
    m_fluidField->setToolTip(tr("Fluid colour map: speed [m/s], excess pore pressure [Pa] or "
                                "vorticity [1/s]"));
    colours->addWidget(m_fluidField);
    m_fluidRange = new ColorRangeEdit("fluidRange");
    colours->addWidget(m_fluidRange);
    colours->addSpacing(16);
    colours->addWidget(new QLabel(tr("Grains by")));
    m_grainColoring = new QComboBox;
    m_grainColoring->setObjectName("grainColoring");
    m_grainColoring->addItems({tr("speed"), tr("force")});
    m_grainColoring->setToolTip(tr("Grain colours: speed [m/s] or summed contact force [N/m]"));
    colours->addWidget(m_grainColoring);
    m_grainRange = new ColorRangeEdit("grainRange");
    colours->addWidget(m_grainRange);
    colours->addStretch(1);
    for (QComboBox* combo : {m_fluidField, m_grainColoring})
        connect(combo, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
                &ViewControls::onColoringChosen);
    connect(m_fluidRange, &ColorRangeEdit::rangeChanged, this,
            [this](const vis::ColorRange& range) {
                m_layers.fluidRange() = range;
                emitChange();
            });
    connect(m_grainRange, &ColorRangeEdit::rangeChanged, this,
            [this](const vis::ColorRange& range) {
                m_layers.grainRange() = range;
                emitChange();
            });
    setLayers(vis::LayerSet{});
}

void ViewControls::setLayers(const vis::LayerSet& layers) {
    m_filling = true;
    m_layers = layers;
    m_fluid->setChecked(layers.fluid);
    m_grains->setChecked(layers.grains);
    m_chains->setChecked(layers.chains);
    m_outline->setChecked(layers.outline);
    m_streamlines->setChecked(layers.streamlines);
    m_fluidField->setCurrentIndex(static_cast<int>(layers.fluidField));
    m_grainColoring->setCurrentIndex(static_cast<int>(layers.grainColoring));
    m_fluidRange->setRange(layers.fluidRange());
    m_grainRange->setRange(layers.grainRange());
    m_filling = false;
}

void ViewControls::showColorRanges(const vis::ColorRange& fluid, const vis::ColorRange& grain) {
    m_fluidRange->showFittedRange(fluid.min, fluid.max);
    m_grainRange->showFittedRange(grain.min, grain.max);
}

void ViewControls::onToggled() {
    if (m_filling) return;
    m_layers.fluid = m_fluid->isChecked();
    m_layers.grains = m_grains->isChecked();
    m_layers.chains = m_chains->isChecked();
    m_layers.outline = m_outline->isChecked();
    m_layers.streamlines = m_streamlines->isChecked();
    emitChange();
}

void ViewControls::onColoringChosen() {
    if (m_filling) return;
    m_layers.fluidField = static_cast<vis::FluidField>(m_fluidField->currentIndex());
    m_layers.grainColoring = static_cast<vis::GrainColoring>(m_grainColoring->currentIndex());
    // The newly chosen quantity brings its own range (setRange emits nothing).
    m_fluidRange->setRange(m_layers.fluidRange());
    m_grainRange->setRange(m_layers.grainRange());
    emitChange();
}

void ViewControls::emitChange() {
    if (!m_filling) emit layersChanged(m_layers);
}

} // namespace lbdem::studio
