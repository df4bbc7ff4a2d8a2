// Hosting vis::SceneView in a QVTKOpenGLNativeWidget; the only studio file that sees VTK.
#include "ui/studio/LiveView.h"

#include "ui/studio/SnapshotProbe.h"
#include "ui/vis/ForceChainLayer.h"
#include "ui/vis/SceneView.h"

#include <QEvent>
#include <QMouseEvent>
#include <QResizeEvent>
#include <QSurfaceFormat>
#include <QVBoxLayout>
#include <QVTKOpenGLNativeWidget.h>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkInteractorStyleImage.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

namespace lbdem::studio {

namespace {

// A 2D view has nothing to rotate: the left button pans (the image style's middle button) and
// the wheel zooms, so a mouse or a touchpad suffices.
class PanZoomStyle : public vtkInteractorStyleImage {
public:
    static PanZoomStyle* New();
    vtkTypeMacro(PanZoomStyle, vtkInteractorStyleImage) void OnLeftButtonDown() override {
        vtkInteractorStyleImage::OnMiddleButtonDown();
    }
    void OnLeftButtonUp() override { vtkInteractorStyleImage::OnMiddleButtonUp(); }
};
vtkStandardNewMacro(PanZoomStyle)

} // namespace

void configureOpenGlFormat() {
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
}

struct LiveView::Impl {
    vis::SceneView scene;
    QVTKOpenGLNativeWidget* widget = nullptr;
    vtkNew<vtkGenericOpenGLRenderWindow> window;
    vtkNew<PanZoomStyle> style;
    vtkNew<vtkCamera> userCamera; ///< the user's pan and zoom, kept across updates
    bool cameraMoved = false;
};

LiveView::LiveView(QWidget* parent) : QWidget(parent), m_impl(std::make_unique<Impl>()) {
    m_impl->widget = new QVTKOpenGLNativeWidget;
    m_impl->widget->setObjectName("liveViewGl");
    // Multisampling costs a factor of several under software OpenGL; the discs and chains
    // carry their own dark rims, so edges stay readable without it.
    m_impl->window->SetMultiSamples(0);
    m_impl->widget->setRenderWindow(m_impl->window);
    m_impl->window->AddRenderer(m_impl->scene.renderer());
    m_impl->widget->interactor()->SetInteractorStyle(m_impl->style);
    m_impl->widget->setMouseTracking(true);
    m_impl->widget->installEventFilter(this);
    m_impl->widget->setMinimumSize(320, 200);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_impl->widget);
}

LiveView::~LiveView() = default;

void LiveView::showSnapshot(const solver::SnapshotPtr& snapshot) {
    m_snapshot = snapshot;
    redraw();
}

const vis::LayerSet& LiveView::layers() const {
    return m_impl->scene.layers();
}

const vis::ColorRange& LiveView::fluidColorRange() const {
    return m_impl->scene.fluidColorRange();
}

const vis::ColorRange& LiveView::grainColorRange() const {
    return m_impl->scene.grainColorRange();
}

void LiveView::setLayers(const vis::LayerSet& layers) {
    m_impl->scene.setLayers(layers);
    redraw();
}

void LiveView::setChainThreshold(double factor) {
    m_impl->scene.forceChains().setThreshold(factor);
    redraw();
}

void LiveView::resetCamera() {
    m_impl->cameraMoved = false;
    const qreal ratio = m_impl->widget->devicePixelRatioF();
    m_impl->scene.resize(int(m_impl->widget->width() * ratio),
                         int(m_impl->widget->height() * ratio));
    m_impl->widget->renderWindow()->Render();
}

void LiveView::redraw() {
    if (!m_snapshot) return;
    vtkCamera* camera = m_impl->scene.renderer()->GetActiveCamera();
    // SceneView::update refits the camera to the domain; keep the user's view instead.
    if (m_impl->cameraMoved) m_impl->userCamera->DeepCopy(camera);
    m_impl->scene.update(*m_snapshot);
    if (m_impl->cameraMoved) camera->DeepCopy(m_impl->userCamera);
    m_impl->widget->renderWindow()->Render();
    emit colorRangesShown(m_impl->scene.fluidColorRange(), m_impl->scene.grainColorRange());
}

QImage LiveView::grabImage() {
    return m_impl->widget->grabFramebuffer();
}

QWidget* LiveView::renderWidget() const {
    return m_impl->widget;
}

std::pair<double, double> LiveView::worldAt(int x, int y) const {
    const qreal ratio = m_impl->widget->devicePixelRatioF();
    const int height = int(m_impl->widget->height() * ratio);
    vtkRenderer* renderer = m_impl->scene.renderer();
    renderer->SetDisplayPoint(x * ratio, height - 1 - y * ratio, 0.0);
    renderer->DisplayToWorld();
    const double* world = renderer->GetWorldPoint();
    const double w = world[3] != 0.0 ? world[3] : 1.0;
    return {world[0] / w, world[1] / w};
}

bool LiveView::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_impl->widget) {
        switch (event->type()) {
        case QEvent::MouseButtonPress:
        case QEvent::Wheel:
            m_impl->cameraMoved = true;
            break;
        case QEvent::MouseMove:
            if (m_snapshot) {
                const QPoint at = static_cast<QMouseEvent*>(event)->pos();
                const auto [x, y] = worldAt(at.x(), at.y());
                emit probed(describeProbe(probeSnapshot(*m_snapshot, x, y)));
            }
            break;
        case QEvent::Resize:
            if (m_snapshot) {
                // Colour bars and label follow the new size; a user's pan and zoom stay.
                vtkCamera* camera = m_impl->scene.renderer()->GetActiveCamera();
                if (m_impl->cameraMoved) m_impl->userCamera->DeepCopy(camera);
                const qreal ratio = m_impl->widget->devicePixelRatioF();
                const QSize size = static_cast<QResizeEvent*>(event)->size() * ratio;
                m_impl->scene.resize(size.width(), size.height());
                if (m_impl->cameraMoved) camera->DeepCopy(m_impl->userCamera);
            }
            break;
        default:
            break;
        }
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace lbdem::studio
