// Fluid colour map and contour lines over the fluid grid.
#include "ui/vis/FluidLayer.h"

#include "ui/vis/ColorMaps.h"
#include "ui/vis/VtkDataSets.h"

#include <vtkActor.h>
#include <vtkContourFilter.h>
#include <vtkImageActor.h>
#include <vtkImageData.h>
#include <vtkImageMapToColors.h>
#include <vtkImageMapper3D.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>

#include <algorithm>
#include <cmath>

namespace lbdem::vis {

namespace {

constexpr int kContourCount = 8;

const char* barTitle(FluidField field) {
    switch (field) {
    case FluidField::Pressure:
        return "excess pressure [Pa]";
    case FluidField::Vorticity:
        return "vorticity [1/s]";
    case FluidField::Speed:
        break;
    }
    return "fluid speed [m/s]";
}

} // namespace

FluidLayer::FluidLayer()
    : m_image(vtkSmartPointer<vtkImageData>::New()),
      m_colors(vtkSmartPointer<vtkImageMapToColors>::New()),
      m_actor(vtkSmartPointer<vtkImageActor>::New()),
      m_contours(vtkSmartPointer<vtkContourFilter>::New()),
      m_contourMapper(vtkSmartPointer<vtkPolyDataMapper>::New()),
      m_contourActor(vtkSmartPointer<vtkActor>::New()), m_sequential(makeSequentialLookupTable()),
      m_diverging(makeDivergingLookupTable()) {
    m_colors->SetInputData(m_image);
    m_colors->SetLookupTable(m_sequential);
    m_colors->SetOutputFormatToRGB();
    m_actor->GetMapper()->SetInputConnection(m_colors->GetOutputPort());
    m_actor->InterpolateOn();
    m_contours->SetInputData(m_image);
    m_contours->ComputeScalarsOff();
    m_contourMapper->SetInputConnection(m_contours->GetOutputPort());
    m_contourMapper->ScalarVisibilityOff();
    m_contourActor->SetMapper(m_contourMapper);
    m_contourActor->GetProperty()->SetColor(0.05, 0.05, 0.05);
    m_contourActor->GetProperty()->SetOpacity(0.45);
    m_contourActor->GetProperty()->SetLineWidth(1.0);
    m_contourActor->GetProperty()->LightingOff();
    m_bar = makeColorBar(m_sequential, barTitle(m_field));
    applyVisibility();
}

FluidLayer::~FluidLayer() = default;

void FluidLayer::addTo(vtkRenderer* renderer) {
    renderer->AddActor(m_actor);
    renderer->AddActor(m_contourActor);
    renderer->AddViewProp(m_bar);
}

void FluidLayer::setField(FluidField field) {
    m_field = field;
}

void FluidLayer::setRange(const ColorRange& range) {
    m_range = range;
}

void FluidLayer::setVisible(bool visible) {
    m_visible = visible;
    applyVisibility();
}

vtkScalarBarActor* FluidLayer::colorBar() const {
    return m_visible && m_hasData ? m_bar.Get() : nullptr;
}

void FluidLayer::applyVisibility() {
    const bool shown = m_visible && m_hasData;
    m_actor->SetVisibility(shown);
    m_contourActor->SetVisibility(shown);
    m_bar->SetVisibility(shown);
}

void FluidLayer::update(const solver::Snapshot& snapshot) {
    m_hasData = snapshot.fluid && snapshot.fluid->nx > 1 && snapshot.fluid->ny > 1;
    applyVisibility();
    if (!m_hasData) return;
    m_image->ShallowCopy(fluidToVtk(*snapshot.fluid));
    // The field's name is also its array name in the VTK image and its colour-bar title.
    const std::string fieldName = fluidFieldName(m_field);
    const char* name = fieldName.c_str();
    const bool signedField = m_field != FluidField::Speed;
    double low = m_range.min, high = m_range.max;
    if (!m_range.fixed) {
        double range[2] = {0.0, 0.0};
        m_image->GetPointData()->GetArray(name)->GetRange(range);
        low = signedField ? -std::max(std::abs(range[0]), std::abs(range[1])) : 0.0;
        high = signedField ? -low : range[1];
    }
    if (!(high - low > 0)) high = low + 1e-12; // a flat field still needs a valid range
    m_shown = {m_range.fixed, low, high};
    vtkLookupTable* table = signedField ? m_diverging.Get() : m_sequential.Get();
    table->SetTableRange(low, high);
    m_image->GetPointData()->SetActiveScalars(name); // vtkImageMapToColors maps the active scalars
    m_colors->SetLookupTable(table);
    m_contours->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name);
    // Levels strictly inside the range: the end values would only trace the extrema points.
    const double step = (high - low) / (kContourCount + 1);
    m_contours->GenerateValues(kContourCount, low + step, high - step);
    m_bar->SetLookupTable(table);
    m_bar->SetTitle(barTitle(m_field));
    m_image->Modified();
}

} // namespace lbdem::vis
