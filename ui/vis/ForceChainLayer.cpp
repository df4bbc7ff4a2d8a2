// Force chains as quads built directly: VTK line width is per actor, so varying width needs
// geometry.
#include "ui/vis/ForceChainLayer.h"

#include "ui/vis/ColorMaps.h"
#include "ui/vis/VtkDataSets.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkLookupTable.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace lbdem::vis {

ForceChainLayer::ForceChainLayer()
    : m_strips(vtkSmartPointer<vtkPolyData>::New()),
      m_mapper(vtkSmartPointer<vtkPolyDataMapper>::New()),
      m_actor(vtkSmartPointer<vtkActor>::New()), m_table(makeForceLookupTable()) {
    m_mapper->SetInputData(m_strips);
    m_mapper->SetLookupTable(m_table);
    m_mapper->SetScalarModeToUseCellData();
    m_mapper->ScalarVisibilityOn();
    m_actor->SetMapper(m_mapper);
    m_actor->GetProperty()->LightingOff();
    m_bar = makeColorBar(m_table, "normal force [N/m]");
    applyVisibility();
}

ForceChainLayer::~ForceChainLayer() = default;

void ForceChainLayer::addTo(vtkRenderer* renderer) {
    renderer->AddActor(m_actor);
    renderer->AddViewProp(m_bar);
}

void ForceChainLayer::setVisible(bool visible) {
    m_visible = visible;
    applyVisibility();
}

void ForceChainLayer::setDepth(double z) {
    m_actor->SetPosition(0, 0, z);
}

vtkScalarBarActor* ForceChainLayer::colorBar() const {
    return m_visible && m_drawn > 0 ? m_bar.Get() : nullptr;
}

void ForceChainLayer::applyVisibility() {
    m_actor->SetVisibility(m_visible && m_drawn > 0);
    m_bar->SetVisibility(m_visible && m_drawn > 0);
}

void ForceChainLayer::update(const solver::Snapshot& snapshot) {
    const auto& c = snapshot.contacts;
    const auto& g = snapshot.grains;
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> quads;
    vtkNew<vtkFloatArray> force;
    force->SetName("normal_force");
    m_drawn = 0;
    if (c.size() > 0 && g.size() > 0) {
        const double mean =
            std::accumulate(c.normal_force.begin(), c.normal_force.end(), 0.0) / c.size();
        const double peak = *std::max_element(c.normal_force.begin(), c.normal_force.end());
        const double radius = std::accumulate(g.radius.begin(), g.radius.end(), 0.0) / g.size();
        const double cut = m_threshold * mean;
        std::size_t wallOrdinal = 0;
        for (std::size_t k = 0; k < c.size(); ++k) {
            const bool wall = c.j[k] < 0;
            const auto wallPoint =
                wall ? wallContactPoint(c, k, wallOrdinal++) : std::pair<float, float>{};
            if (c.normal_force[k] <= cut || peak <= 0) continue;
            const auto a = static_cast<std::size_t>(c.i[k]);
            const double ax = g.x[a], ay = g.y[a];
            const double bx = wall ? wallPoint.first : g.x[static_cast<std::size_t>(c.j[k])];
            const double by = wall ? wallPoint.second : g.y[static_cast<std::size_t>(c.j[k])];
            const double length = std::hypot(bx - ax, by - ay);
            if (!(length > 0)) continue;
            const double half = 0.5 * m_maxWidthOverRadius * radius * c.normal_force[k] / peak;
            const double nx = -(by - ay) / length * half, ny = (bx - ax) / length * half;
            const vtkIdType ids[4] = {points->InsertNextPoint(ax + nx, ay + ny, 0),
                                      points->InsertNextPoint(bx + nx, by + ny, 0),
                                      points->InsertNextPoint(bx - nx, by - ny, 0),
                                      points->InsertNextPoint(ax - nx, ay - ny, 0)};
            quads->InsertNextCell(4, ids);
            force->InsertNextValue(c.normal_force[k]);
            ++m_drawn;
        }
        m_table->SetTableRange(cut, std::max(peak, cut + 1e-12));
        m_mapper->SetScalarRange(cut, std::max(peak, cut + 1e-12));
    }
    vtkNew<vtkPolyData> strips;
    strips->SetPoints(points);
    strips->SetPolys(quads);
    strips->GetCellData()->SetScalars(force);
    m_strips->ShallowCopy(strips);
    m_strips->Modified();
    applyVisibility();
}

} // namespace lbdem::vis
