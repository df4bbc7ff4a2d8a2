// A screenshot of a whole window including the contents of its OpenGL (VTK) views.
#pragma once

#include <QImage>

class QWidget;

namespace lbdem::studio {

/// QWidget::grab of window with every visible QOpenGLWidget inside it (the VTK views are
/// QVTKOpenGLNativeWidgets) replaced by its grabFramebuffer(), so the rendered scene shows
/// instead of an empty box. Must be called on the GUI thread.
QImage grabWindow(QWidget* window);

/// Fraction of pixels of image that differ from its most common colour by more than a few
/// levels: near zero for a blank (single colour) image.
double nonUniformFraction(const QImage& image);

} // namespace lbdem::studio
