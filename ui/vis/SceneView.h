// A renderer and its layers: what the headless PNG output and the studio's VTK widget both show.
#pragma once

#include "solver/scene/Snapshot.h"
#include "ui/vis/LayerSet.h"

#include <vtkSmartPointer.h>

#include <memory>
#include <vector>

class vtkRenderer;
class vtkScalarBarActor;
class vtkTextActor;

namespace lbdem::vis {

class FluidLayer;
class GrainLayer;
class ForceChainLayer;
class OutlineLayer;
class StreamlineLayer;
class WallLayer;

/// Owns a vtkRenderer with the fluid, grain, force-chain, outline, streamline and wall layers,
/// the colour bars and a t/tau_c label. It knows nothing of windows: put renderer() into an
/// off-screen vtkRenderWindow or a QVTKOpenGLNativeWidget's window, then call update() per frame.
/// The camera is a fixed 2D parallel projection fitted to the domain (not to the grains), so
/// successive frames line up.
class SceneView {
public:
    SceneView();
    ~SceneView();
    SceneView(const SceneView&) = delete;
    SceneView& operator=(const SceneView&) = delete;

    /// The renderer to add to a render window.
    vtkRenderer* renderer() const;
    /// Chooses visible layers, colourings and colour ranges; takes effect at the next update().
    void setLayers(const LayerSet& layers);
    /// The current layer choice.
    const LayerSet& layers() const { return m_layers; }
    /// Draws `snapshot`: refreshes every layer's data in place, places the colour bars, sets the
    /// label and fits the camera to the render window's current size.
    void update(const solver::Snapshot& snapshot);
    /// Lays out the camera, colour bars and label for a window of `width` x `height` pixels
    /// (update() does this for the window it renders into; the GUI calls it after a resize).
    void resize(int width, int height);
    /// The range the fluid colours (and colour bar) spanned at the last update.
    const ColorRange& fluidColorRange() const;
    /// The range the grain colours (and colour bar) spanned at the last update.
    const ColorRange& grainColorRange() const;
    /// The force-chain layer (threshold setting, drawn count).
    ForceChainLayer& forceChains() { return *m_chains; }
    /// The streamline layer (traced line count).
    const StreamlineLayer& streamlines() const { return *m_streamlines; }

private:
    std::vector<vtkScalarBarActor*> visibleColorBars() const;
    void placeColorBars(const std::vector<vtkScalarBarActor*>& bars, bool stacked, double bottom,
                        double rowHeight);

    LayerSet m_layers;
    bool m_unicodeLabel = false;
    double m_meanRadius = 0;
    double m_domain[4] = {0, 1, 0, 1}; // xmin, xmax, ymin, ymax of what the camera frames
    vtkSmartPointer<vtkRenderer> m_renderer;
    vtkSmartPointer<vtkTextActor> m_label;
    std::unique_ptr<FluidLayer> m_fluid;
    std::unique_ptr<GrainLayer> m_grains;
    std::unique_ptr<ForceChainLayer> m_chains;
    std::unique_ptr<OutlineLayer> m_outline;
    std::unique_ptr<StreamlineLayer> m_streamlines;
    std::unique_ptr<WallLayer> m_walls;
};

/// The label shown in a view: "t/τc = 1.25   (t = 0.050 s)" ("t/tau_c" when `unicode` is false),
/// or "t = 0.050 s" when tau_c is unknown.
std::string timeLabel(const solver::Snapshot& snapshot, bool unicode = true);

} // namespace lbdem::vis
