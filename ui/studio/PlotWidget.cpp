// Painting of PlotWidget: frame, nice tick values, the curve and the reference line.
#include "ui/studio/PlotWidget.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>
#include <functional>

namespace lbdem::studio {

namespace {

// A tick step of 1, 2 or 5 times a power of ten giving about `target` intervals over span.
double niceStep(double span, int target) {
    const double raw = span / std::max(target, 1);
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    for (double factor : {1.0, 2.0, 5.0, 10.0})
        if (raw <= factor * magnitude) return factor * magnitude;
    return 10.0 * magnitude;
}

/// The data's extent: x0..x1 and y0..y1 over the points, the band and the reference line.
struct Extent {
    double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    bool empty = true;
    void add(double x, double y) {
        if (!std::isfinite(x) || !std::isfinite(y)) return;
        if (empty) {
            x0 = x1 = x, y0 = y1 = y, empty = false;
            return;
        }
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
};

} // namespace

PlotWidget::PlotWidget(const QString& title, const QString& xLabel, const QString& yLabel,
                       QWidget* parent)
    : QWidget(parent), m_title(title), m_xLabel(xLabel), m_yLabel(yLabel) {
    setAutoFillBackground(true);
    QPalette palette = this->palette();
    palette.setColor(QPalette::Window, Qt::white);
    setPalette(palette);
}

void PlotWidget::addPoint(double x, double y) {
    if (!std::isfinite(x) || !std::isfinite(y)) return;
    m_points.append({x, y});
    update();
}

void PlotWidget::clear() {
    m_points.clear();
    update();
}

void PlotWidget::setReferenceLine(double y, const QString& label) {
    m_reference = y;
    m_referenceLabel = label;
    update();
}

void PlotWidget::setBand(const QVector<double>& x, const QVector<double>& lower,
                         const QVector<double>& mean, const QVector<double>& upper,
                         const QString& label) {
    const bool consistent =
        lower.size() == x.size() && mean.size() == x.size() && upper.size() == x.size();
    if (!consistent || x.isEmpty()) {
        clearBand();
        return;
    }
    m_bandX = x, m_bandLower = lower, m_bandMean = mean, m_bandUpper = upper;
    m_bandLabel = label;
    update();
}

void PlotWidget::clearBand() {
    m_bandX.clear(), m_bandLower.clear(), m_bandMean.clear(), m_bandUpper.clear();
    m_bandLabel.clear();
    update();
}

void PlotWidget::setEmptyNote(const QString& note) {
    m_emptyNote = note;
    update();
}

void PlotWidget::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const QFontMetrics metrics(font());
    const int line = metrics.height();
    const QRectF frame(QPointF(6 + 5 * metrics.averageCharWidth(), line + 6),
                       QPointF(width() - 10, height() - 2 * line - 6));
    painter.drawText(QRectF(0, 2, width(), line), Qt::AlignHCenter, m_title);
    painter.drawText(QRectF(frame.left(), height() - line - 2, frame.width(), line),
                     Qt::AlignHCenter, m_xLabel);
    painter.setPen(QColor(120, 120, 120));
    painter.drawRect(frame);
    Extent extent;
    for (const QPointF& p : m_points)
        extent.add(p.x(), p.y());
    for (int k = 0; k < m_bandX.size(); ++k)
        extent.add(m_bandX[k], m_bandLower[k]), extent.add(m_bandX[k], m_bandUpper[k]);
    if (extent.empty || frame.width() < 20 || frame.height() < 20) {
        painter.drawText(frame, Qt::AlignCenter | Qt::TextWordWrap,
                         m_emptyNote.isEmpty() ? tr("no data yet") : m_emptyNote);
        return;
    }
    double x0 = extent.x0, x1 = extent.x1, y0 = extent.y0, y1 = extent.y1;
    if (m_reference) y0 = std::min(y0, *m_reference), y1 = std::max(y1, *m_reference);
    if (x1 - x0 < 1e-12) x1 = x0 + 1;
    if (y1 - y0 < 1e-12) y0 -= 0.5, y1 += 0.5;
    const double margin = 0.05 * (y1 - y0);
    y0 -= margin, y1 += margin;
    auto map = [&](double x, double y) {
        return QPointF(frame.left() + (x - x0) / (x1 - x0) * frame.width(),
                       frame.bottom() - (y - y0) / (y1 - y0) * frame.height());
    };
    const double step = niceStep(y1 - y0, 4);
    for (double y = std::ceil(y0 / step) * step; y <= y1; y += step) {
        const QPointF at = map(x0, y);
        painter.setPen(QColor(225, 225, 225));
        painter.drawLine(at, map(x1, y));
        painter.setPen(Qt::black);
        painter.drawText(QRectF(0, at.y() - line / 2.0, frame.left() - 3, line),
                         Qt::AlignRight | Qt::AlignVCenter, QString::number(y, 'g', 3));
    }
    if (!m_bandX.isEmpty()) drawBand(painter, map, frame, line);
    painter.setPen(Qt::black);
    painter.drawText(QRectF(frame.left() + 3, frame.top() + 2, frame.width(), line), Qt::AlignLeft,
                     m_yLabel);
    painter.drawText(QRectF(frame.left(), frame.bottom() + 1, frame.width(), line), Qt::AlignRight,
                     QString::number(x1, 'g', 3));
    if (m_reference) {
        painter.setPen(QPen(QColor(200, 60, 60), 1, Qt::DashLine));
        painter.drawLine(map(x0, *m_reference), map(x1, *m_reference));
        const QPointF end = map(x1, *m_reference);
        const double labelTop = end.y() - line - 1 < frame.top() ? end.y() + 1 : end.y() - line - 1;
        painter.drawText(QRectF(frame.left(), labelTop, frame.width() - 4, line), Qt::AlignRight,
                         m_referenceLabel);
    }
    if (m_points.isEmpty()) return;
    QPainterPath path(map(m_points.front().x(), m_points.front().y()));
    for (const QPointF& p : m_points)
        path.lineTo(map(p.x(), p.y()));
    painter.setPen(QPen(QColor(30, 90, 180), 1.6));
    painter.drawPath(path);
}

void PlotWidget::drawBand(QPainter& painter, const std::function<QPointF(double, double)>& map,
                          const QRectF& frame, int line) const {
    QPolygonF area;
    for (int k = 0; k < m_bandX.size(); ++k)
        area << map(m_bandX[k], m_bandUpper[k]);
    for (int k = m_bandX.size() - 1; k >= 0; --k)
        area << map(m_bandX[k], m_bandLower[k]);
    painter.setPen(Qt::NoPen);
    painter.setBrush(bandColor());
    painter.drawPolygon(area);
    painter.setBrush(Qt::NoBrush);
    QPainterPath mean(map(m_bandX.front(), m_bandMean.front()));
    for (int k = 1; k < m_bandX.size(); ++k)
        mean.lineTo(map(m_bandX[k], m_bandMean[k]));
    painter.setPen(QPen(QColor(90, 120, 170), 1, Qt::DashLine));
    painter.drawPath(mean);
    painter.setPen(QColor(70, 90, 130));
    painter.drawText(QRectF(frame.left() + 3, frame.top() + line + 2, frame.width() - 6, line),
                     Qt::AlignLeft, m_bandLabel);
}

} // namespace lbdem::studio
