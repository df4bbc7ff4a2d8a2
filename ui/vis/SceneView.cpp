// SceneView: layer ownership, colour-bar layout, time label and the fixed 2D camera.
#include "ui/vis/SceneView.h"

#include "ui/vis/ColorMaps.h"
#include "ui/vis/FluidLayer.h"
#include "ui/vis/ForceChainLayer.h"
#include "ui/vis/GrainLayer.h"
#include "ui/vis/OutlineLayer.h"
#include "ui/vis/StreamlineLayer.h"
#include "ui/vis/WallLayer.h"

#include <vtkCamera.h>
#include <vtkCoordinate.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <vector>

namespace lbdem::vis {

namespace {

// Layout in pixels: a label strip on top, the scene, then the colour bars; the group is centred
// vertically. Bars sit side by side when each gets kBarMinWidth pixels, else one per row.
constexpr double kLabelPixels = 28, kGapPixels = 6, kSideMargin = 0.03;
constexpr double kBarRowPixels = 46, kBarMinWidth = 170;
// Grain rims are dropped below this radius in pixels, where they would darken whole discs.
constexpr double kRimMinPixels = 4;
// Layer heights above the fluid plane, in units of the domain size, give the draw order.
constexpr double kDepthStreamlines = 1e-3, kDepthGrains = 2e-3, kDepthChains = 3e-3,
                 kDepthOutline = 4e-3, kDepthWalls = 5e-3;

/// Extent of the scene: the declared domain, or what the data covers when none is declared.
void sceneBounds(const solver::Snapshot& s, double bounds[4]) {
    if (s.domain_width_m > 0 && s.domain_height_m > 0) {
        bounds[0] = 0, bounds[1] = s.domain_width_m, bounds[2] = 0, bounds[3] = s.domain_height_m;
        return;
    }
    bounds[0] = bounds[2] = INFINITY;
    bounds[1] = bounds[3] = -INFINITY;
    auto grow = [bounds](double x, double y, double r) {
        bounds[0] = std::min(bounds[0], x - r), bounds[1] = std::max(bounds[1], x + r);
        bounds[2] = std::min(bounds[2], y - r), bounds[3] = std::max(bounds[3], y + r);
    };
    for (std::size_t k = 0; k < s.grains.size(); ++k)
        grow(s.grains.x[k], s.grains.y[k], s.grains.radius[k]);
    if (s.fluid) {
        const auto& f = *s.fluid;
        grow(f.origin_x, f.origin_y, 0);
        grow(f.origin_x + (f.nx - 1) * f.spacing_m, f.origin_y + (f.ny - 1) * f.spacing_m, 0);
    }
    if (!(bounds[1] > bounds[0]) || !(bounds[3] > bounds[2]))
        bounds[0] = 0, bounds[1] = 1, bounds[2] = 0, bounds[3] = 1;
}

} // namespace

std::string timeLabel(const solver::Snapshot& s, bool unicode) {
    char text[96];
    if (s.tc_s > 0)
        std::snprintf(text, sizeof text, "%s = %.2f   (t = %.3f s)",
                      timeOverTcSymbol(unicode).c_str(), s.timeOverTc(), s.time_s);
    else
        std::snprintf(text, sizeof text, "t = %.3f s", s.time_s);
    return text;
}

SceneView::SceneView()
    : m_renderer(vtkSmartPointer<vtkRenderer>::New()),
      m_label(vtkSmartPointer<vtkTextActor>::New()), m_fluid(std::make_unique<FluidLayer>()),
      m_grains(std::make_unique<GrainLayer>()), m_chains(std::make_unique<ForceChainLayer>()),
      m_outline(std::make_unique<OutlineLayer>()),
      m_streamlines(std::make_unique<StreamlineLayer>()), m_walls(std::make_unique<WallLayer>()) {
    m_renderer->SetBackground(1.0, 1.0, 1.0);
    m_fluid->addTo(m_renderer);
    m_streamlines->addTo(m_renderer);
    m_grains->addTo(m_renderer);
    m_chains->addTo(m_renderer);
    m_outline->addTo(m_renderer);
    m_walls->addTo(m_renderer);
    m_label->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
    m_label->GetTextProperty()->SetFontSize(13);
    m_unicodeLabel = useUnicodeFont(m_label->GetTextProperty());
    m_label->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
    m_renderer->AddViewProp(m_label);
    m_renderer->GetActiveCamera()->ParallelProjectionOn();
    setLayers(m_layers);
}

SceneView::~SceneView() = default;

vtkRenderer* SceneView::renderer() const {
    return m_renderer;
}

void SceneView::setLayers(const LayerSet& layers) {
    m_layers = layers;
    m_fluid->setField(layers.fluidField);
    m_fluid->setRange(layers.fluidRange());
    m_fluid->setVisible(layers.fluid);
    m_grains->setColoring(layers.grainColoring);
    m_grains->setRange(layers.grainRange());
    m_grains->setVisible(layers.grains);
    m_chains->setVisible(layers.chains);
    m_outline->setVisible(layers.outline);
    m_streamlines->setVisible(layers.streamlines);
}

const ColorRange& SceneView::fluidColorRange() const {
    return m_fluid->shownRange();
}

const ColorRange& SceneView::grainColorRange() const {
    return m_grains->shownRange();
}

void SceneView::update(const solver::Snapshot& snapshot) {
    sceneBounds(snapshot, m_domain);
    const auto& radius = snapshot.grains.radius;
    m_meanRadius =
        radius.empty() ? 0.0 : std::accumulate(radius.begin(), radius.end(), 0.0) / radius.size();
    const double size = std::max(m_domain[1] - m_domain[0], m_domain[3] - m_domain[2]);
    m_streamlines->setDepth(kDepthStreamlines * size);
    m_grains->setDepth(kDepthGrains * size);
    m_chains->setDepth(kDepthChains * size);
    m_outline->setDepth(kDepthOutline * size);
    m_walls->setDepth(kDepthWalls * size);
    m_fluid->update(snapshot);
    m_streamlines->update(snapshot);
    m_grains->update(snapshot);
    m_chains->update(snapshot);
    m_outline->update(snapshot);
    m_walls->update(snapshot);
    m_label->SetInput(timeLabel(snapshot, m_unicodeLabel).c_str());
    if (vtkRenderWindow* window = m_renderer->GetRenderWindow()) {
        const int* pixels = window->GetSize();
        resize(pixels[0], pixels[1]);
    }
}

void SceneView::resize(int width, int height) {
    if (width <= 0 || height <= 0) return;
    const double w = m_domain[1] - m_domain[0], h = m_domain[3] - m_domain[2];
    const std::vector<vtkScalarBarActor*> bars = visibleColorBars();
    const bool stacked =
        bars.size() > 1 && (1 - 2 * kSideMargin) * width / bars.size() < kBarMinWidth;
    const double barRows = bars.empty() ? 0.0 : stacked ? static_cast<double>(bars.size()) : 1.0;
    const double barPixels = barRows * kBarRowPixels;
    const double sceneWidth = (1 - 2 * kSideMargin) * width;
    const double sceneHeight = std::max(1.0, height - kLabelPixels - barPixels - 2 * kGapPixels);
    // World units per pixel so that the domain fits the scene band in both directions.
    const double perPixel = std::max(w / sceneWidth, h / sceneHeight);
    const double scenePixels = h / perPixel;
    const double top = 0.5 * (height - (kLabelPixels + scenePixels + barPixels + 2 * kGapPixels));
    const double sceneTop = height - top - kLabelPixels - kGapPixels;
    const double sceneBottom = sceneTop - scenePixels;
    m_label->SetPosition(kSideMargin * width, height - top - kLabelPixels + 8);
    placeColorBars(bars, stacked, (sceneBottom - kGapPixels - barPixels) / height,
                   kBarRowPixels / height);
    m_grains->setRimsVisible(m_meanRadius / perPixel >= kRimMinPixels);
    const double centreX = 0.5 * (m_domain[0] + m_domain[1]);
    const double centreY = 0.5 * (m_domain[2] + m_domain[3]) -
                           (0.5 * (sceneTop + sceneBottom) - 0.5 * height) * perPixel;
    const double distance = 10 * std::max(w, h);
    vtkCamera* camera = m_renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetFocalPoint(centreX, centreY, 0);
    camera->SetPosition(centreX, centreY, distance);
    camera->SetViewUp(0, 1, 0);
    camera->SetParallelScale(0.5 * height * perPixel);
    camera->SetClippingRange(0.5 * distance, 2 * distance);
}

std::vector<vtkScalarBarActor*> SceneView::visibleColorBars() const {
    std::vector<vtkScalarBarActor*> bars;
    for (vtkScalarBarActor* bar : {m_fluid->colorBar(), m_grains->colorBar(), m_chains->colorBar()})
        if (bar) bars.push_back(bar);
    return bars;
}

void SceneView::placeColorBars(const std::vector<vtkScalarBarActor*>& bars, bool stacked,
                               double bottom, double rowHeight) {
    const double slot =
        (1.0 - 2 * kSideMargin) / (stacked ? 1 : std::max<std::size_t>(bars.size(), 1));
    for (std::size_t k = 0; k < bars.size(); ++k) {
        const std::size_t row = stacked ? bars.size() - 1 - k : 0, column = stacked ? 0 : k;
        bars[k]->SetPosition(kSideMargin + column * slot + 0.02, bottom + row * rowHeight);
        bars[k]->SetWidth(slot - 0.04);
        bars[k]->SetHeight(rowHeight);
    }
}

} // namespace lbdem::vis
