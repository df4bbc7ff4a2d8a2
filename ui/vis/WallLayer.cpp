// Walls as one poly data of line segments.
#include "ui/vis/WallLayer.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

namespace lbdem::vis {

WallLayer::WallLayer()
    : m_lines(vtkSmartPointer<vtkPolyData>::New()), m_actor(vtkSmartPointer<vtkActor>::New()) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(m_lines);
    mapper->ScalarVisibilityOff();
    m_actor->SetMapper(mapper);
    m_actor->GetProperty()->SetColor(0.25, 0.25, 0.25);
    m_actor->GetProperty()->SetLineWidth(3.0f);
    m_actor->GetProperty()->LightingOff();
}

WallLayer::~WallLayer() = default;

void WallLayer::addTo(vtkRenderer* renderer) {
    renderer->AddActor(m_actor);
}

void WallLayer::setDepth(double z) {
    m_actor->SetPosition(0, 0, z);
}

void WallLayer::update(const solver::Snapshot& snapshot) {
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> lines;
    for (const auto& wall : snapshot.walls) {
        const vtkIdType ids[2] = {points->InsertNextPoint(wall.x0, wall.y0, 0),
                                  points->InsertNextPoint(wall.x1, wall.y1, 0)};
        lines->InsertNextCell(2, ids);
    }
    vtkNew<vtkPolyData> segments;
    segments->SetPoints(points);
    segments->SetLines(lines);
    m_lines->ShallowCopy(segments);
    m_lines->Modified();
    m_actor->SetVisibility(!snapshot.walls.empty());
}

} // namespace lbdem::vis
