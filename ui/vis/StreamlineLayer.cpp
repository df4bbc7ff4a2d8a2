// Streamlines near the front with vtkStreamTracer (Runge-Kutta 4-5) on the fluid image.
#include "ui/vis/StreamlineLayer.h"

#include "ui/vis/VtkDataSets.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkImageData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkStreamTracer.h>

#include <algorithm>

namespace lbdem::vis {

namespace {

constexpr int kSeedColumns = 4;
constexpr int kSeedRows = 10;

/// The x of the flow front and the height of the granular mass, from the outline or the grains.
std::pair<double, double> frontAndHeight(const solver::Snapshot& s) {
    double front = 0, height = 0;
    for (const auto& [x, y] : s.outline) {
        front = std::max(front, static_cast<double>(x));
        height = std::max(height, static_cast<double>(y));
    }
    if (s.outline.empty())
        for (std::size_t k = 0; k < s.grains.size(); ++k) {
            front = std::max(front, static_cast<double>(s.grains.x[k] + s.grains.radius[k]));
            height = std::max(height, static_cast<double>(s.grains.y[k] + s.grains.radius[k]));
        }
    return {front, height};
}

} // namespace

StreamlineLayer::StreamlineLayer()
    : m_image(vtkSmartPointer<vtkImageData>::New()), m_seeds(vtkSmartPointer<vtkPolyData>::New()),
      m_tracer(vtkSmartPointer<vtkStreamTracer>::New()), m_actor(vtkSmartPointer<vtkActor>::New()) {
    m_tracer->SetInputData(m_image);
    m_tracer->SetSourceData(m_seeds);
    m_tracer->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "velocity");
    m_tracer->SetIntegratorTypeToRungeKutta45();
    m_tracer->SetIntegrationDirectionToBoth();
    m_tracer->SetIntegrationStepUnit(vtkStreamTracer::CELL_LENGTH_UNIT);
    m_tracer->SetInitialIntegrationStep(0.5);
    m_tracer->SetMaximumNumberOfSteps(4000);
    m_tracer->SetComputeVorticity(false);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(m_tracer->GetOutputPort());
    mapper->ScalarVisibilityOff();
    m_actor->SetMapper(mapper);
    m_actor->GetProperty()->SetColor(1.0, 1.0, 1.0);
    m_actor->GetProperty()->SetOpacity(0.85);
    m_actor->GetProperty()->SetLineWidth(1.5f);
    m_actor->GetProperty()->LightingOff();
    m_actor->SetVisibility(false);
}

StreamlineLayer::~StreamlineLayer() = default;

void StreamlineLayer::addTo(vtkRenderer* renderer) {
    renderer->AddActor(m_actor);
}

void StreamlineLayer::setVisible(bool visible) {
    m_visible = visible;
    m_actor->SetVisibility(m_visible && m_hasData);
}

void StreamlineLayer::setDepth(double z) {
    m_actor->SetPosition(0, 0, z);
}

int StreamlineLayer::lineCount() const {
    return m_hasData ? static_cast<int>(m_tracer->GetOutput()->GetNumberOfLines()) : 0;
}

void StreamlineLayer::update(const solver::Snapshot& snapshot) {
    m_hasData = m_visible && snapshot.fluid && snapshot.fluid->nx > 1 && snapshot.fluid->ny > 1;
    m_actor->SetVisibility(m_hasData);
    if (!m_hasData) return;
    const auto& f = *snapshot.fluid;
    m_image->ShallowCopy(fluidToVtk(f));
    const auto [front, height] = frontAndHeight(snapshot);
    // Seeds in a box one mass-height wide centred on the front, from the bed to 1.5 heights.
    const double top = std::max(height, 4.0 * f.spacing_m) * 1.5;
    const double left = front - 0.5 * top, right = front + 0.5 * top;
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> vertices;
    for (int row = 0; row < kSeedRows; ++row)
        for (int col = 0; col < kSeedColumns; ++col) {
            const double x = left + (right - left) * (col + 0.5) / kSeedColumns;
            const double y = f.origin_y + (top - f.origin_y) * (row + 0.5) / kSeedRows;
            const vtkIdType id = points->InsertNextPoint(x, y, 0);
            vertices->InsertNextCell(1, &id);
        }
    vtkNew<vtkPolyData> seeds;
    seeds->SetPoints(points);
    seeds->SetVerts(vertices);
    m_seeds->ShallowCopy(seeds);
    m_tracer->SetMaximumPropagation(2.0 * top);
    m_image->Modified();
    m_seeds->Modified();
    m_tracer->Update();
}

} // namespace lbdem::vis
