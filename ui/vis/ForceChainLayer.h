// The force-chain layer: strips between contacting centres, width and colour by normal force.
#pragma once

#include "solver/scene/Snapshot.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkLookupTable;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkRenderer;
class vtkScalarBarActor;

namespace lbdem::vis {

/// Contacts whose normal force exceeds `threshold` times the mean are drawn as flat strips from
/// centre to centre (or to the wall point); the strip width grows linearly with the force up to
/// `maxWidthOverRadius` mean radii at the strongest contact, the colour follows the force.
class ForceChainLayer {
public:
    ForceChainLayer();
    ~ForceChainLayer();

    /// Adds the strip and colour-bar actors to `renderer`.
    void addTo(vtkRenderer* renderer);
    /// Shows or hides the layer.
    void setVisible(bool visible);
    /// Draws only contacts with normal force above `factor` x mean (1 by default; 0 draws all).
    void setThreshold(double factor) { m_threshold = factor; }
    /// Rebuilds the strips for the contacts of `snapshot`.
    void update(const solver::Snapshot& snapshot);
    /// The colour bar, for the view to place; null while hidden or empty.
    vtkScalarBarActor* colorBar() const;
    /// Puts the layer `z` metres above the fluid (draw order in the 2D view).
    void setDepth(double z);
    /// Number of strips drawn by the last update.
    int drawnCount() const { return m_drawn; }

private:
    void applyVisibility();

    double m_threshold = 1.0;
    double m_maxWidthOverRadius = 0.5;
    bool m_visible = true;
    int m_drawn = 0;
    vtkSmartPointer<vtkPolyData> m_strips;
    vtkSmartPointer<vtkPolyDataMapper> m_mapper;
    vtkSmartPointer<vtkActor> m_actor;
    vtkSmartPointer<vtkLookupTable> m_table;
    vtkSmartPointer<vtkScalarBarActor> m_bar;
};

} // namespace lbdem::vis
