// Outline polyline drawn twice (wide dark halo, narrower white line) for contrast.
#include "ui/vis/OutlineLayer.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <vector>

namespace lbdem::vis {

namespace {

/// An unlit line actor of `width` pixels and colour `grey` showing `line`.
vtkSmartPointer<vtkActor> lineActor(vtkPolyData* line, double width, double grey) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(line);
    mapper->ScalarVisibilityOff();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetLineWidth(static_cast<float>(width));
    actor->GetProperty()->SetColor(grey, grey, grey);
    actor->GetProperty()->LightingOff();
    return actor;
}

} // namespace

OutlineLayer::OutlineLayer() : m_line(vtkSmartPointer<vtkPolyData>::New()) {
    m_halo = lineActor(m_line, 4.0, 0.0);
    m_actor = lineActor(m_line, 2.0, 1.0);
    applyVisibility();
}

OutlineLayer::~OutlineLayer() = default;

void OutlineLayer::addTo(vtkRenderer* renderer) {
    renderer->AddActor(m_halo);
    renderer->AddActor(m_actor);
}

void OutlineLayer::setVisible(bool visible) {
    m_visible = visible;
    applyVisibility();
}

void OutlineLayer::setDepth(double z) {
    m_halo->SetPosition(0, 0, z);
    m_actor->SetPosition(0, 0, z * 1.01); // the white line above its own halo
}

void OutlineLayer::applyVisibility() {
    m_halo->SetVisibility(m_visible && m_hasData);
    m_actor->SetVisibility(m_visible && m_hasData);
}

void OutlineLayer::update(const solver::Snapshot& snapshot) {
    vtkNew<vtkPoints> points;
    std::vector<vtkIdType> ids;
    for (const auto& [x, y] : snapshot.outline)
        ids.push_back(points->InsertNextPoint(x, y, 0));
    vtkNew<vtkCellArray> lines;
    if (ids.size() >= 2) lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    vtkNew<vtkPolyData> line;
    line->SetPoints(points);
    line->SetLines(lines);
    m_line->ShallowCopy(line);
    m_line->Modified();
    m_hasData = ids.size() >= 2;
    applyVisibility();
}

} // namespace lbdem::vis
