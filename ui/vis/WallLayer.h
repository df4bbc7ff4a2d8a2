// The wall layer: domain walls, gate and fixed obstacles as dark line segments.
#pragma once

#include "solver/scene/Snapshot.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace lbdem::vis {

/// Draws Snapshot::walls; always shown, since it frames every other layer.
class WallLayer {
public:
    WallLayer();
    ~WallLayer();

    /// Adds the wall actor to `renderer`.
    void addTo(vtkRenderer* renderer);
    /// Takes the walls of `snapshot`.
    void update(const solver::Snapshot& snapshot);
    /// Puts the layer `z` metres above the fluid (draw order in the 2D view).
    void setDepth(double z);

private:
    vtkSmartPointer<vtkPolyData> m_lines;
    vtkSmartPointer<vtkActor> m_actor;
};

} // namespace lbdem::vis
