// A small QPainter line plot of one quantity against t/tau_c, cheap enough to redraw per frame.
#pragma once

#include <QColor>
#include <QPointF>
#include <QString>
#include <QVector>
#include <QWidget>

#include <functional>
#include <optional>

class QPainter;

namespace lbdem::studio {

/// One curve with automatic axes, an optional horizontal reference line (e.g. the Froude
/// number 0.4 above which a front hydroplanes), an optional shaded band drawn behind the curve
/// (an ensemble's min-max with its mean dashed) and a note shown when there is no data.
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
    /// Shade lower..upper against x behind the curve, dash mean, and name the band with label;
    /// the four vectors have one length (an empty x removes the band).
    void setBand(const QVector<double>& x, const QVector<double>& lower,
                 const QVector<double>& mean, const QVector<double>& upper, const QString& label);
    /// Remove the band.
    void clearBand();
    /// Points of the band (0 without one).
    int bandSize() const { return m_bandX.size(); }
    /// The band's label ("" without one).
    const QString& bandLabel() const { return m_bandLabel; }
    /// Fill colour of the band (opaque, so that tests can find it in a grab).
    static QColor bandColor() { return {198, 216, 240}; }
    /// Text shown while the plot is empty.
    void setEmptyNote(const QString& note);
    /// The points plotted so far.
    const QVector<QPointF>& points() const { return m_points; }

    QSize sizeHint() const override { return {320, 180}; }
    QSize minimumSizeHint() const override { return {160, 100}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    /// The band (shaded min-max, dashed mean, label under the y label) in data coordinates.
    void drawBand(QPainter& painter, const std::function<QPointF(double, double)>& map,
                  const QRectF& frame, int line) const;

    QString m_title, m_xLabel, m_yLabel, m_emptyNote;
    QVector<QPointF> m_points;
    std::optional<double> m_reference;
    QVector<double> m_bandX, m_bandLower, m_bandMean, m_bandUpper;
    QString m_bandLabel;
    QString m_referenceLabel;
};

} // namespace lbdem::studio
