// A colour-range editor: "fixed" check box with min and max spin boxes (auto while unchecked).
#pragma once

#include "ui/vis/LayerSet.h"

#include <QWidget>

class QCheckBox;
class QDoubleSpinBox;

namespace lbdem::studio {

/// Edits one vis::ColorRange. While the range is automatic the spin boxes are read-only and
/// show the range the view fitted (showFittedRange); ticking "fixed" keeps those values, which
/// the user then edits. A range whose max does not exceed its min is shown in red and not
/// emitted.
class ColorRangeEdit : public QWidget {
    Q_OBJECT
public:
    /// `name` prefixes the object names of the parts ("<name>Fixed", "<name>Min", "<name>Max").
    explicit ColorRangeEdit(const QString& name, QWidget* parent = nullptr);

    /// Show `range` in the controls (emits nothing).
    void setRange(const vis::ColorRange& range);
    /// The range as the controls show it.
    vis::ColorRange range() const;
    /// While automatic, show the range the view fitted to the current frame (rounded to the
    /// digits displayed, so that fixing it keeps what is shown).
    void showFittedRange(double min, double max);

signals:
    /// The user changed the range to a valid one.
    void rangeChanged(const lbdem::vis::ColorRange& range);

private:
    void onEdited();
    void applyEnabled();

    QCheckBox* m_fixed;
    QDoubleSpinBox *m_min, *m_max;
    bool m_filling = false;
};

} // namespace lbdem::studio
