// Composing QWidget::grab with the framebuffers of the window's OpenGL views.
#include "ui/studio/WindowGrab.h"

#include <QHash>
#include <QOpenGLWidget>
#include <QPainter>
#include <QPixmap>
#include <QWidget>

#include <algorithm>
#include <cstdlib>

namespace lbdem::studio {

QImage grabWindow(QWidget* window) {
    const QPixmap base = window->grab();
    QImage image = base.toImage().convertToFormat(QImage::Format_RGB32);
    const qreal ratio = base.devicePixelRatio();
    QPainter painter(&image);
    for (QOpenGLWidget* view : window->findChildren<QOpenGLWidget*>()) {
        if (!view->isVisible() || view->width() == 0 || view->height() == 0) continue;
        // grabFramebuffer renders the view (paintGL) into its framebuffer object and reads it
        // back; the widget backing store that grab() copies does not hold GL contents.
        const QImage frame = view->grabFramebuffer();
        const QPoint at = view->mapTo(window, QPoint(0, 0));
        painter.drawImage(QRectF(at * ratio, QSizeF(view->size()) * ratio), frame);
    }
    painter.end();
    return image;
}

double nonUniformFraction(const QImage& source) {
    const QImage image = source.convertToFormat(QImage::Format_RGB32);
    const long long total = static_cast<long long>(image.width()) * image.height();
    if (total == 0) return 0.0;
    QHash<QRgb, long long> counts;
    for (int y = 0; y < image.height(); ++y) {
        const auto* row = reinterpret_cast<const QRgb*>(image.constScanLine(y));
        for (int x = 0; x < image.width(); ++x)
            ++counts[row[x]];
    }
    const QRgb common = std::max_element(counts.begin(), counts.end()).key();
    long long different = 0;
    for (auto it = counts.begin(); it != counts.end(); ++it) {
        const QRgb c = it.key();
        const int distance = std::abs(qRed(c) - qRed(common)) +
                             std::abs(qGreen(c) - qGreen(common)) +
                             std::abs(qBlue(c) - qBlue(common));
        if (distance > 12) different += it.value();
    }
    return double(different) / double(total);
}

} // namespace lbdem::studio
