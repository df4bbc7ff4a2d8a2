// The grain layer: every disc at its true radius, coloured by speed or by contact force.
#pragma once

#include "solver/scene/Snapshot.h"
#include "ui/vis/LayerSet.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkGlyph3DMapper;
class vtkLookupTable;
class vtkRenderer;
class vtkScalarBarActor;
class vtkUnstructuredGrid;

namespace lbdem::vis {

/// Discs drawn as instanced glyphs scaled by the radius array, with a thin dark rim so touching
/// grains stay distinct; update() swaps the point data, the glyph pipeline is built once.
class GrainLayer {
public:
    GrainLayer();
    ~GrainLayer();

    /// Adds the disc, rim and colour-bar actors to `renderer`.
    void addTo(vtkRenderer* renderer);
    /// Chooses the colouring from the next update on.
    void setColoring(GrainColoring coloring);
    /// Fixes the colour range or lets update() fit it, from the next update on.
    void setRange(const ColorRange& range);
    /// Shows or hides the layer.
    void setVisible(bool visible);
    /// Takes the grains of `snapshot`; the automatic colour range is 0..max of the chosen
    /// quantity.
    void update(const solver::Snapshot& snapshot);
    /// The range the colours spanned at the last update (`fixed` as set).
    const ColorRange& shownRange() const { return m_shown; }
    /// The colour bar, for the view to place; null while hidden or empty.
    vtkScalarBarActor* colorBar() const;
    /// Draws the dark disc rims (the view turns them off when discs are only a few pixels wide).
    void setRimsVisible(bool visible);
    /// Puts the layer `z` metres above the fluid (draw order in the 2D view).
    void setDepth(double z);

private:
    void applyVisibility();

    GrainColoring m_coloring = GrainColoring::Speed;
    ColorRange m_range, m_shown;
    bool m_visible = true;
    bool m_hasData = false;
    bool m_rimsVisible = true;
    vtkSmartPointer<vtkUnstructuredGrid> m_points;
    vtkSmartPointer<vtkGlyph3DMapper> m_discMapper, m_rimMapper;
    vtkSmartPointer<vtkActor> m_discs, m_rims;
    vtkSmartPointer<vtkLookupTable> m_table;
    vtkSmartPointer<vtkScalarBarActor> m_bar;
};

} // namespace lbdem::vis
