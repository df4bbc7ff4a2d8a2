// Fixed colour ranges: the lookup table, the colour bar and the picture follow a fixed
// range instead of the frame's own; auto comes back bit for bit; each quantity keeps its range.
#include "tests/support/SyntheticSnapshot.h"
#include "ui/vis/LayerSet.h"
#include "ui/vis/OffscreenRenderer.h"
#include "ui/vis/SceneView.h"

#include <vtkImageData.h>
#include <vtkPropCollection.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkScalarsToColors.h>

#include <QtTest>

#include <cstring>
#include <vector>

using namespace lbdem;

Q_DECLARE_METATYPE(vis::LayerSet)

namespace {

constexpr int kSize = 300;

/// The colour bars shown in `view` (hidden ones left out).
std::vector<vtkScalarBarActor*> visibleBars(vis::SceneView& view) {
    std::vector<vtkScalarBarActor*> bars;
    vtkPropCollection* props = view.renderer()->GetViewProps();
    for (int k = 0; k < props->GetNumberOfItems(); ++k)
        if (auto* bar = vtkScalarBarActor::SafeDownCast(props->GetItemAsObject(k)))
            if (bar->GetVisibility()) bars.push_back(bar);
    return bars;
}

/// Fraction of pixels of two equally sized RGB images that differ in any channel.
double differingFraction(vtkImageData* a, vtkImageData* b) {
    const auto* p = static_cast<const unsigned char*>(a->GetScalarPointer());
    const auto* q = static_cast<const unsigned char*>(b->GetScalarPointer());
    const std::size_t pixels = static_cast<std::size_t>(kSize) * kSize;
    std::size_t differing = 0;
    for (std::size_t k = 0; k < pixels; ++k)
        differing += std::memcmp(p + 3 * k, q + 3 * k, 3) != 0;
    return double(differing) / double(pixels);
}

/// The range in effect for the fluid (`fluid` true) or the grain layer.
const vis::ColorRange& shown(const vis::SceneView& view, bool fluid) {
    return fluid ? view.fluidColorRange() : view.grainColorRange();
}

} // namespace

class ColorRangeTest : public QObject {
    Q_OBJECT
private slots:
    void fixedRangeIsUsed_data();
    void fixedRangeIsUsed();
    void eachQuantityKeepsItsRange();
};

void ColorRangeTest::fixedRangeIsUsed_data() {
    QTest::addColumn<vis::LayerSet>("layers");
    QTest::addColumn<bool>("fluid");
    for (vis::FluidField field :
         {vis::FluidField::Speed, vis::FluidField::Pressure, vis::FluidField::Vorticity}) {
        vis::LayerSet layers = vis::parseLayerSet("fluid");
        layers.fluidField = field;
        QTest::newRow(("fluid " + vis::fluidFieldName(field)).c_str()) << layers << true;
    }
    for (vis::GrainColoring coloring :
         {vis::GrainColoring::Speed, vis::GrainColoring::ContactForce}) {
        vis::LayerSet layers = vis::parseLayerSet("grains");
        layers.grainColoring = coloring;
        QTest::newRow(("grains " + vis::grainColoringName(coloring)).c_str()) << layers << false;
    }
}

void ColorRangeTest::fixedRangeIsUsed() {
    QFETCH(vis::LayerSet, layers);
    QFETCH(bool, fluid);
    const solver::Snapshot snapshot = support::syntheticSnapshot(2);
    vis::OffscreenRenderer renderer(kSize, kSize, layers);
    const auto automatic = renderer.renderImage(snapshot);
    const vis::ColorRange fitted = shown(renderer.view(), fluid);
    QVERIFY(!fitted.fixed);
    QVERIFY(fitted.max > fitted.min);

    // A narrower, shifted range: most of the picture saturates at one end or the other.
    const double span = fitted.max - fitted.min;
    const vis::ColorRange fixed{true, fitted.min + 0.1 * span, fitted.min + 0.35 * span};
    vis::LayerSet fixedLayers = layers;
    (fluid ? fixedLayers.fluidRange() : fixedLayers.grainRange()) = fixed;
    renderer.view().setLayers(fixedLayers);
    const auto pinned = renderer.renderImage(snapshot);
    QCOMPARE(shown(renderer.view(), fluid), fixed);
    const auto bars = visibleBars(renderer.view());
    QCOMPARE(bars.size(), std::size_t(1));
    const double* barRange = bars[0]->GetLookupTable()->GetRange();
    QCOMPARE(barRange[0], fixed.min);
    QCOMPARE(barRange[1], fixed.max);
    const double differing = differingFraction(automatic, pinned);
    qInfo("%s: auto range [%g, %g], fixed [%g, %g]: %.3f of the pixels change",
          QTest::currentDataTag(), fitted.min, fitted.max, fixed.min, fixed.max, differing);
    QVERIFY2(differing > 0.02, "the fixed range did not change the picture");

    // The range stays fixed on later frames, whose own values differ.
    renderer.renderImage(support::syntheticSnapshot(3));
    QCOMPARE(shown(renderer.view(), fluid), fixed);

    // Back to auto: the first picture again, pixel for pixel.
    renderer.view().setLayers(layers);
    const auto again = renderer.renderImage(snapshot);
    QCOMPARE(differingFraction(automatic, again), 0.0);
}

void ColorRangeTest::eachQuantityKeepsItsRange() {
    vis::LayerSet layers;
    layers.fluidRanges[static_cast<int>(vis::FluidField::Speed)] = {true, 0.0, 0.5};
    layers.grainRanges[static_cast<int>(vis::GrainColoring::ContactForce)] = {true, 1.0, 2.0};
    vis::SceneView view;
    const solver::Snapshot snapshot = support::syntheticSnapshot(1);
    view.setLayers(layers);
    view.update(snapshot);
    QCOMPARE(view.fluidColorRange(), (vis::ColorRange{true, 0.0, 0.5}));
    QVERIFY(!view.grainColorRange().fixed); // grains by speed: still automatic
    layers.fluidField = vis::FluidField::Pressure;
    layers.grainColoring = vis::GrainColoring::ContactForce;
    view.setLayers(layers);
    view.update(snapshot);
    QVERIFY(!view.fluidColorRange().fixed); // pressure: still automatic
    QCOMPARE(view.grainColorRange(), (vis::ColorRange{true, 1.0, 2.0}));
}

QTEST_GUILESS_MAIN(ColorRangeTest)
#include "ColorRangeTest.moc"
