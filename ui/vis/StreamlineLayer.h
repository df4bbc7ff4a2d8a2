// The streamline layer: fluid streamlines seeded around the flow front (the paper's Figure 19).
#pragma once

#include "solver/scene/Snapshot.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkImageData;
class vtkPolyData;
class vtkRenderer;
class vtkStreamTracer;

namespace lbdem::vis {

/// Streamlines of the fluid velocity traced both ways from a grid of seeds in a box around the
/// front (the rightmost point of the outline, or of the grains when there is no outline).
class StreamlineLayer {
public:
    StreamlineLayer();
    ~StreamlineLayer();

    /// Adds the streamline actor to `renderer`.
    void addTo(vtkRenderer* renderer);
    /// Shows or hides the layer; hidden layers skip the tracing in update().
    void setVisible(bool visible);
    /// Re-seeds and re-traces for `snapshot` (nothing drawn without fluid).
    void update(const solver::Snapshot& snapshot);
    /// Puts the layer `z` metres above the fluid (draw order in the 2D view).
    void setDepth(double z);
    /// Number of streamline cells traced by the last update.
    int lineCount() const;

private:
    bool m_visible = false;
    bool m_hasData = false;
    vtkSmartPointer<vtkImageData> m_image;
    vtkSmartPointer<vtkPolyData> m_seeds;
    vtkSmartPointer<vtkStreamTracer> m_tracer;
    vtkSmartPointer<vtkActor> m_actor;
};

} // namespace lbdem::vis
