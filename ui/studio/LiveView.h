// The live view: the vis SceneView hosted in a QVTKOpenGLNativeWidget, with pan, zoom and probe.
#pragma once

#include "solver/scene/Snapshot.h"
#include "ui/vis/LayerSet.h"

#include <QImage>
#include <QWidget>

#include <memory>

namespace lbdem::studio {

/// Set the default OpenGL surface format VTK needs; call before the QApplication is made.
void configureOpenGlFormat();

/// Draws snapshots with vis::SceneView (the same layers the headless PNG output draws). Left
/// drag pans, the wheel zooms; once the user moved the camera it stays put until resetCamera().
/// Moving the mouse emits probed() with the fluid and grain values under the cursor. All VTK
/// objects live here, on the GUI thread.
class LiveView : public QWidget {
    Q_OBJECT
public:
    explicit LiveView(QWidget* parent = nullptr);
    ~LiveView() override;

    /// Draw snapshot now (and keep it for the probe).
    void showSnapshot(const solver::SnapshotPtr& snapshot);
    /// The snapshot on screen, or null.
    const solver::SnapshotPtr& snapshot() const { return m_snapshot; }
    /// The layer choice in effect.
    const vis::LayerSet& layers() const;
    /// The range the fluid colours spanned in the last frame drawn (fitted or fixed).
    const vis::ColorRange& fluidColorRange() const;
    /// The range the grain colours spanned in the last frame drawn (fitted or fixed).
    const vis::ColorRange& grainColorRange() const;
    /// The rendered scene as an image (renders first).
    QImage grabImage();
    /// The OpenGL widget the scene is drawn in.
    QWidget* renderWidget() const;
    /// The world point [m] under widget pixel (x, y) of the render widget.
    std::pair<double, double> worldAt(int x, int y) const;

public slots:
    /// Choose the visible layers, colourings and colour ranges; redraws the current snapshot.
    void setLayers(const lbdem::vis::LayerSet& layers);
    /// Draw only force chains above factor x the mean normal force (0: all).
    void setChainThreshold(double factor);
    /// Fit the whole domain into the view and forget the user's pan and zoom.
    void resetCamera();

signals:
    /// One line describing what lies under the cursor.
    void probed(const QString& text);
    /// A frame was drawn with these fluid and grain colour ranges (fitted or fixed).
    void colorRangesShown(const lbdem::vis::ColorRange& fluid, const lbdem::vis::ColorRange& grain);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void redraw();

    struct Impl;
    std::unique_ptr<Impl> m_impl;
    solver::SnapshotPtr m_snapshot;
};

} // namespace lbdem::studio
