// The fluid layer: a colour map of speed, pressure or vorticity with contour lines.
#pragma once

#include "solver/scene/Snapshot.h"
#include "ui/vis/LayerSet.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkContourFilter;
class vtkImageActor;
class vtkImageData;
class vtkImageMapToColors;
class vtkLookupTable;
class vtkPolyDataMapper;
class vtkRenderer;
class vtkScalarBarActor;

namespace lbdem::vis {

/// Draws the fluid grid coloured by one field (with a colour bar in SI units) and eight contour
/// lines of the same field; update() refills the image in place, the pipeline is built once.
/// The colours go through vtkImageMapToColors into a texture (vtkImageActor): a 1000 x 500 grid
/// as polygons would take seconds per frame under software OpenGL.
class FluidLayer {
public:
    FluidLayer();
    ~FluidLayer();

    /// Adds the actors (field, contours, colour bar) to `renderer`.
    void addTo(vtkRenderer* renderer);
    /// Chooses the field shown from the next update on.
    void setField(FluidField field);
    /// Fixes the colour range (and the contour levels) or lets update() fit it, from the next
    /// update on.
    void setRange(const ColorRange& range);
    /// Shows or hides the layer; a snapshot without fluid hides it regardless.
    void setVisible(bool visible);
    /// Takes the fluid fields of `snapshot` (automatic colour range: 0..max for speed,
    /// symmetric about zero otherwise).
    void update(const solver::Snapshot& snapshot);
    /// The range the colours spanned at the last update (`fixed` as set).
    const ColorRange& shownRange() const { return m_shown; }
    /// The colour bar, for the view to place; null while the layer is hidden.
    vtkScalarBarActor* colorBar() const;

private:
    void applyVisibility();

    FluidField m_field = FluidField::Speed;
    ColorRange m_range, m_shown;
    bool m_visible = true;
    bool m_hasData = false;
    vtkSmartPointer<vtkImageData> m_image;
    vtkSmartPointer<vtkImageMapToColors> m_colors;
    vtkSmartPointer<vtkImageActor> m_actor;
    vtkSmartPointer<vtkContourFilter> m_contours;
    vtkSmartPointer<vtkPolyDataMapper> m_contourMapper;
    vtkSmartPointer<vtkActor> m_contourActor;
    vtkSmartPointer<vtkLookupTable> m_sequential, m_diverging;
    vtkSmartPointer<vtkScalarBarActor> m_bar;
};

} // namespace lbdem::vis
