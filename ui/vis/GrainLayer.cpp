// Grains as instanced disc glyphs scaled by radius.
#include "ui/vis/GrainLayer.h"

#include "ui/vis/ColorMaps.h"
#include "ui/vis/VtkDataSets.h"

#include <vtkActor.h>
#include <vtkGlyph3DMapper.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkRegularPolygonSource.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkUnstructuredGrid.h>

namespace lbdem::vis {

namespace {

// 32 sides keep the polygon within 0.5 % of the true radius.
constexpr int kDiscSides = 32;

/// A glyph mapper drawing `source` at every point, scaled by the radius array.
vtkSmartPointer<vtkGlyph3DMapper> discMapper(vtkUnstructuredGrid* points, bool filled) {
    vtkNew<vtkRegularPolygonSource> source;
    source->SetNumberOfSides(kDiscSides);
    source->SetRadius(1.0);
    source->SetGeneratePolygon(filled);
    source->SetGeneratePolyline(!filled);
    auto mapper = vtkSmartPointer<vtkGlyph3DMapper>::New();
    mapper->SetInputData(points);
    mapper->SetSourceConnection(source->GetOutputPort());
    mapper->SetScaleArray("radius");
    mapper->SetScaleModeToScaleByMagnitude();
    mapper->SetScaleFactor(1.0);
    mapper->ScalingOn();
    mapper->OrientOff();
    return mapper;
}

} // namespace

GrainLayer::GrainLayer()
    : m_points(vtkSmartPointer<vtkUnstructuredGrid>::New()),
      m_discs(vtkSmartPointer<vtkActor>::New()), m_rims(vtkSmartPointer<vtkActor>::New()),
      m_table(makeGrainLookupTable()) {
    m_discMapper = discMapper(m_points, true);
    m_discMapper->SetScalarModeToUsePointFieldData();
    m_discMapper->SetLookupTable(m_table);
    m_discMapper->ScalarVisibilityOn();
    m_discMapper->SetColorModeToMapScalars();
    m_discs->SetMapper(m_discMapper);
    m_discs->GetProperty()->LightingOff();
    m_rimMapper = discMapper(m_points, false);
    m_rimMapper->ScalarVisibilityOff();
    m_rims->SetMapper(m_rimMapper);
    m_rims->GetProperty()->SetColor(0.1, 0.1, 0.1);
    m_rims->GetProperty()->SetOpacity(0.5);
    m_rims->GetProperty()->LightingOff();
    m_bar = makeColorBar(m_table, "grain speed [m/s]");
    applyVisibility();
}

GrainLayer::~GrainLayer() = default;

void GrainLayer::addTo(vtkRenderer* renderer) {
    renderer->AddActor(m_discs);
    renderer->AddActor(m_rims);
    renderer->AddViewProp(m_bar);
}

void GrainLayer::setColoring(GrainColoring coloring) {
    m_coloring = coloring;
}

void GrainLayer::setRange(const ColorRange& range) {
    m_range = range;
}

void GrainLayer::setVisible(bool visible) {
    m_visible = visible;
    applyVisibility();
}

void GrainLayer::setRimsVisible(bool visible) {
    m_rimsVisible = visible;
    applyVisibility();
}

void GrainLayer::setDepth(double z) {
    m_discs->SetPosition(0, 0, z);
    m_rims->SetPosition(0, 0, z);
}

vtkScalarBarActor* GrainLayer::colorBar() const {
    return m_visible && m_hasData ? m_bar.Get() : nullptr;
}

void GrainLayer::applyVisibility() {
    const bool shown = m_visible && m_hasData;
    m_discs->SetVisibility(shown);
    m_rims->SetVisibility(shown && m_rimsVisible);
    m_bar->SetVisibility(shown);
}

void GrainLayer::update(const solver::Snapshot& snapshot) {
    m_hasData = snapshot.grains.size() > 0;
    applyVisibility();
    if (!m_hasData) return;
    m_points->ShallowCopy(particlesToVtk(snapshot));
    const bool byForce = m_coloring == GrainColoring::ContactForce;
    const char* name = byForce ? "contact_force" : "speed";
    double low = m_range.min, high = m_range.max;
    if (!m_range.fixed) {
        double range[2];
        m_points->GetPointData()->GetArray(name)->GetRange(range);
        low = 0.0;
        high = range[1];
    }
    if (!(high - low > 0)) high = low + 1e-12; // all at rest still needs a range
    m_shown = {m_range.fixed, low, high};
    m_table->SetTableRange(low, high);
    m_discMapper->SelectColorArray(name);
    m_discMapper->SetScalarRange(low, high);
    m_bar->SetTitle(byForce ? "contact force [N/m]" : "grain speed [m/s]");
    m_points->Modified();
}

} // namespace lbdem::vis
