// A small QPainter line plot of one quantity against t/tau_c, cheap enough to redraw per frame.
#pragma once

#include <QPointF>
#include <QString>
#include <QVector>
#include <QWidget>

#include <optional>

namespace lbdem::studio {

/// One curve with automatic axes, an optional horizontal reference line (e.g. the Froude
/// number 0.4 above which a front hydroplanes) and a note shown when there is no data.
class PlotWidget : public QWidget {
    Q_OBJECT
public:
    /// A plot titled title with the given axis labels.
    PlotWidget(const QString& title, const QString& xLabel, const QString& yLabel,
               QWidget* parent = nullptr);

    /// Append a point (x should not decrease); repaints.
    void addPoint(double x, double y);
    /// Forget every point.
    void clear();
    /// Draw a dashed horizontal line at y with a label.
    void setReferenceLine(double y, const QString& label);
    /// Text shown while the plot is empty.
    void setEmptyNote(const QString& note);
    /// The points plotted so far.
    const QVector<QPointF>& points() const { return m_points; }

    QSize sizeHint() const override { return {320, 180}; }
    QSize minimumSizeHint() const override { return {160, 100}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QString m_title, m_xLabel, m_yLabel, m_emptyNote;
    QVector<QPointF> m_points;
    std::optional<double> m_reference;
    QString m_referenceLabel;
};

} // namespace lbdem::studio
