// The flow-front outline layer: the free-surface polyline of the granular mass.
#pragma once

#include "solver/scene/Snapshot.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace lbdem::vis {

/// Draws Snapshot::outline as a thick polyline (white over a dark halo so it reads on any
/// colour); update() refills the polyline in place.
class OutlineLayer {
public:
    OutlineLayer();
    ~OutlineLayer();

    /// Adds the halo and line actors to `renderer`.
    void addTo(vtkRenderer* renderer);
    /// Shows or hides the layer.
    void setVisible(bool visible);
    /// Takes the outline of `snapshot`.
    void update(const solver::Snapshot& snapshot);
    /// Puts the layer `z` metres above the fluid (draw order in the 2D view).
    void setDepth(double z);

private:
    void applyVisibility();

    bool m_visible = true;
    bool m_hasData = false;
    vtkSmartPointer<vtkPolyData> m_line;
    vtkSmartPointer<vtkActor> m_halo, m_actor;
};

} // namespace lbdem::vis
