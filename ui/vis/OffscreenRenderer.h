// Off-screen rendering of a SceneView into PNG files or images, for the CLI and the tests.
#pragma once

#include "solver/scene/Snapshot.h"
#include "ui/vis/LayerSet.h"

#include <vtkSmartPointer.h>

#include <memory>
#include <string>

class vtkImageData;
class vtkRenderWindow;

namespace lbdem::vis {

class SceneView;

/// An off-screen render window of a fixed size holding one SceneView; reuse it for a series of
/// frames (the pipelines are built once). Needs an X display: the constructor calls
/// ensureDisplay(), which starts a private Xvfb when DISPLAY is unset.
class OffscreenRenderer {
public:
    /// A `width` x `height` pixel window showing `layers`.
    OffscreenRenderer(int width, int height, const LayerSet& layers = {});
    ~OffscreenRenderer();

    /// The scene, e.g. to change layers or the chain threshold between frames.
    SceneView& view() { return *m_view; }
    /// Renders `snapshot` and returns the RGB image (origin bottom-left, as VTK stores images).
    vtkSmartPointer<vtkImageData> renderImage(const solver::Snapshot& snapshot);
    /// Renders `snapshot` and writes it as a PNG file at `path` (atomically).
    void renderPng(const solver::Snapshot& snapshot, const std::string& path);

private:
    std::unique_ptr<SceneView> m_view;
    vtkSmartPointer<vtkRenderWindow> m_window;
};

/// One-call PNG output for `lbdem run --render-every`: renders `snapshot` at `width` x `height`
/// with `layers` to `path`. Hold an OffscreenRenderer instead when rendering many frames.
void renderSnapshotPng(const solver::Snapshot& snapshot, const std::string& path, int width,
                       int height, const LayerSet& layers = {});

/// Writes an RGB(A) image to `path` as PNG through a temporary file and a rename.
void writePng(vtkImageData* image, const std::string& path);

} // namespace lbdem::vis
