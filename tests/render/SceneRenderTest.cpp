// Render regression: 300x300 images of a synthetic snapshot against baselines (docs/style.md,
// Style §7).
#include "tests/render/ImageBaseline.h"
#include "tests/support/SyntheticSnapshot.h"
#include "ui/vis/ForceChainLayer.h"
#include "ui/vis/LayerSet.h"
#include "ui/vis/LineChart.h"
#include "ui/vis/OffscreenRenderer.h"
#include "ui/vis/SceneView.h"
#include "ui/vis/StreamlineLayer.h"

#include <vtkActorCollection.h>
#include <vtkImageData.h>
#include <vtkRenderer.h>

#include <QtTest>

#include <cmath>
#include <cstring>

using namespace lbdem;

Q_DECLARE_METATYPE(vis::LayerSet)

namespace {
constexpr int kSize = 300;
// vtkImageDifference's thresholded error; VTK's own regression tests use 10 by default.
constexpr double kTolerance = 10.0;
} // namespace

class SceneRenderTest : public QObject {
    Q_OBJECT
private slots:
    void matchesBaseline_data();
    void matchesBaseline();
    void updateReusesPipelines();
    void chainThresholdSelectsStrongContacts();
    void streamlinesAreTracedNearFront();
    void chartMatchesBaseline();
    void sweepChartHasMarkers();
    void badChartInputIsRejected();
};

void SceneRenderTest::matchesBaseline_data() {
    QTest::addColumn<vis::LayerSet>("layers");
    QTest::addColumn<bool>("wet");
    vis::LayerSet all;
    all.streamlines = true;
    QTest::newRow("scene_all_layers") << all << true;
    vis::LayerSet pressure;
    pressure.fluidField = vis::FluidField::Pressure;
    pressure.grainColoring = vis::GrainColoring::ContactForce;
    QTest::newRow("scene_pressure_force") << pressure << true;
    vis::LayerSet vorticity = vis::parseLayerSet("fluid,outline");
    vorticity.fluidField = vis::FluidField::Vorticity;
    QTest::newRow("scene_vorticity_outline") << vorticity << true;
    QTest::newRow("scene_dry") << vis::LayerSet{} << false;
}

void SceneRenderTest::matchesBaseline() {
    QFETCH(vis::LayerSet, layers);
    QFETCH(bool, wet);
    vis::OffscreenRenderer renderer(kSize, kSize, layers);
    const auto image = renderer.renderImage(support::syntheticSnapshot(2, wet));
    QVERIFY(support::distinctColours(image) > 50);
    const auto result = support::compareWithBaseline(image, QTest::currentDataTag(), kTolerance);
    QVERIFY2(result.passed, result.message.c_str());
}

void SceneRenderTest::updateReusesPipelines() {
    vis::OffscreenRenderer renderer(kSize, kSize);
    vtkRenderer* scene = renderer.view().renderer();
    const auto first = renderer.renderImage(support::syntheticSnapshot(0));
    const int actors = scene->GetActors()->GetNumberOfItems();
    const int props = scene->GetViewProps()->GetNumberOfItems();
    vtkActor* firstActor = vtkActor::SafeDownCast(scene->GetActors()->GetItemAsObject(0));
    const auto later = renderer.renderImage(support::syntheticSnapshot(3));
    QCOMPARE(scene->GetActors()->GetNumberOfItems(), actors);
    QCOMPARE(scene->GetViewProps()->GetNumberOfItems(), props);
    QCOMPARE(vtkActor::SafeDownCast(scene->GetActors()->GetItemAsObject(0)), firstActor);
    // The later frame must actually look different (the column has spread).
    const auto bytes = static_cast<std::size_t>(kSize) * kSize * 3;
    QVERIFY(std::memcmp(first->GetScalarPointer(), later->GetScalarPointer(), bytes) != 0);
}

void SceneRenderTest::chainThresholdSelectsStrongContacts() {
    const solver::Snapshot snapshot = support::syntheticSnapshot(1);
    vis::SceneView view;
    view.update(snapshot);
    const int aboveMean = view.forceChains().drawnCount();
    QVERIFY(aboveMean > 0);
    QVERIFY(aboveMean < static_cast<int>(snapshot.contacts.size()));
    view.forceChains().setThreshold(0.0);
    view.update(snapshot);
    QCOMPARE(view.forceChains().drawnCount(), static_cast<int>(snapshot.contacts.size()));
}

void SceneRenderTest::streamlinesAreTracedNearFront() {
    vis::SceneView view;
    view.setLayers(vis::parseLayerSet("fluid,streamlines"));
    view.update(support::syntheticSnapshot(1));
    QVERIFY(view.streamlines().lineCount() >= 20);
    view.update(support::syntheticSnapshot(1, false));
    QCOMPARE(view.streamlines().lineCount(), 0);
}

void SceneRenderTest::chartMatchesBaseline() {
    vis::ChartSeries run{"synthetic", {}, {}};
    for (int k = 0; k <= 60; ++k) {
        const double t = 0.1 * k;
        run.x.push_back(t);
        run.y.push_back(0.9 * t * std::exp(-0.5 * t)); // rises past 0.4, then decays
    }
    const std::string path =
        std::string(LBDEM_BINARY_DIR) + "/Testing/Temporary/chart_froude.render.png";
    QDir().mkpath(QString::fromStdString(std::string(LBDEM_BINARY_DIR) + "/Testing/Temporary"));
    vis::renderLineChart(vis::froudeChart({run}), path, kSize, kSize);
    const auto image = support::readPng(path);
    QVERIFY(image);
    QVERIFY(support::distinctColours(image) > 20);
    const auto result = support::compareWithBaseline(image, "chart_froude", kTolerance);
    QVERIFY2(result.passed, result.message.c_str());
}

void SceneRenderTest::sweepChartHasMarkers() {
    vis::ChartSeries dry{"dry", {0, 5, 10, 15, 20}, {0.10, 0.12, 0.15, 0.19, 0.25}};
    vis::ChartSeries wet{"wet dense", {0, 5, 10, 15, 20}, {0.07, 0.08, 0.10, 0.13, 0.17}};
    const vis::ChartSpec spec = vis::runoutVsSlopeChart({dry, wet});
    QVERIFY(spec.series[0].markers && spec.series[1].markers);
    const std::string path =
        std::string(LBDEM_BINARY_DIR) + "/Testing/Temporary/chart_runout_slope.render.png";
    vis::renderLineChart(spec, path, kSize, kSize);
    const auto result =
        support::compareWithBaseline(support::readPng(path), "chart_runout_slope", kTolerance);
    QVERIFY2(result.passed, result.message.c_str());
}

void SceneRenderTest::badChartInputIsRejected() {
    vis::ChartSpec spec;
    spec.series.push_back({"bad", {0, 1}, {0}});
    QVERIFY_EXCEPTION_THROWN(vis::renderLineChart(spec, "unused.png", kSize, kSize),
                             std::invalid_argument);
    QVERIFY_EXCEPTION_THROWN(vis::renderLineChart(vis::ChartSpec{}, "unused.png", kSize, kSize),
                             std::invalid_argument);
}

QTEST_GUILESS_MAIN(SceneRenderTest)
#include "SceneRenderTest.moc"
