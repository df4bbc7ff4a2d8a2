// The colour-range editor and its spin box for values of any magnitude.
#include "ui/studio/ColorRangeEdit.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QRegularExpression>

namespace lbdem::studio {

namespace {

// Significant digits shown; fitted ranges are rounded to them.
constexpr int kDigits = 4;

/// A QDoubleSpinBox that reads and writes numbers in %g form ("0.0512", "1.5e-05", "2400"),
/// since speeds, pressures, vorticities and contact forces span many decades.
class ValueSpinBox : public QDoubleSpinBox {
public:
    ValueSpinBox() {
        setDecimals(15);
        setRange(-1e15, 1e15);
        setStepType(QAbstractSpinBox::AdaptiveDecimalStepType);
        setKeyboardTracking(false);
        setMinimumWidth(80);
    }

    QString textFromValue(double value) const override {
        return QString::number(value, 'g', kDigits + 2);
    }

    double valueFromText(const QString& text) const override { return text.trimmed().toDouble(); }

    QValidator::State validate(QString& text, int&) const override {
        const QString t = text.trimmed();
        bool ok = false;
        t.toDouble(&ok);
        if (ok) return QValidator::Acceptable;
        static const QRegularExpression partial(R"(^[+-]?(\d*\.?\d*)([eE][+-]?\d*)?$)");
        return partial.match(t).hasMatch() ? QValidator::Intermediate : QValidator::Invalid;
    }
};

/// `value` rounded to the digits a spin box shows.
double displayed(double value) {
    return QString::number(value, 'g', kDigits).toDouble();
}

} // namespace

ColorRangeEdit::ColorRangeEdit(const QString& name, QWidget* parent) : QWidget(parent) {
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    m_fixed = new QCheckBox(tr("fixed"));
    m_fixed->setObjectName(name + "Fixed");
    m_fixed->setToolTip(tr("Fixed: the colours span min to max on every frame, so frames can be "
                           "compared. Unchecked: the range is fitted to each frame."));
    m_min = new ValueSpinBox;
    m_max = new ValueSpinBox;
    m_min->setObjectName(name + "Min");
    m_max->setObjectName(name + "Max");
    m_min->setToolTip(tr("Value at the low end of the colour map (SI unit of the colour bar)"));
    m_max->setToolTip(tr("Value at the high end of the colour map (SI unit of the colour bar)"));
    m_max->setValue(1.0);
    row->addWidget(m_fixed);
    row->addWidget(m_min);
    row->addWidget(new QLabel(tr("to")));
    row->addWidget(m_max);
    connect(m_fixed, &QCheckBox::toggled, this, &ColorRangeEdit::onEdited);
    for (QDoubleSpinBox* box : {m_min, m_max})
        connect(box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
                &ColorRangeEdit::onEdited);
    applyEnabled();
}

void ColorRangeEdit::setRange(const vis::ColorRange& range) {
    m_filling = true;
    m_fixed->setChecked(range.fixed);
    m_min->setValue(range.min);
    m_max->setValue(range.max);
    m_filling = false;
    applyEnabled();
}

vis::ColorRange ColorRangeEdit::range() const {
    return {m_fixed->isChecked(), m_min->value(), m_max->value()};
}

void ColorRangeEdit::showFittedRange(double min, double max) {
    if (m_fixed->isChecked()) return;
    m_filling = true;
    m_min->setValue(displayed(min));
    m_max->setValue(displayed(max));
    m_filling = false;
    applyEnabled();
}

void ColorRangeEdit::onEdited() {
    applyEnabled();
    if (m_filling) return;
    const vis::ColorRange edited = range();
    if (!edited.fixed || edited.max > edited.min) emit rangeChanged(edited);
}

void ColorRangeEdit::applyEnabled() {
    const bool fixed = m_fixed->isChecked();
    const bool valid = !fixed || m_max->value() > m_min->value();
    const QString style = valid ? QString() : QStringLiteral("color: #c00000");
    for (QDoubleSpinBox* box : {m_min, m_max}) {
        box->setEnabled(fixed);
        if (box->styleSheet() != style) box->setStyleSheet(style);
    }
    m_max->setToolTip(
        valid ? tr("Value at the high end of the colour map (SI unit of the colour bar)")
              : tr("max must exceed min; the last valid range stays in effect"));
}

} // namespace lbdem::studio
