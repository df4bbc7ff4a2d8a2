// A case editor generated from the declared case keys, with inline validation in plain words.
#pragma once

#include "solver/scene/CaseSpec.h"

#include <QStringList>
#include <QWidget>

#include <vector>

class QLabel;

namespace lbdem::solver {
struct ParamDecl;
}

namespace lbdem::studio {

/// One group box per case section, one row per declared key (CaseSchema): a check box, a combo
/// box or a line edit; label with the unit, tooltip with the doc, range and default. Each edit is
/// checked with ParamDecl::check and the whole case with validateCase; problems appear under the
/// field they concern and isValid() turns false until they are fixed.
class CaseEditor : public QWidget {
    Q_OBJECT
public:
    explicit CaseEditor(QWidget* parent = nullptr);
    ~CaseEditor() override;

    /// Show spec in the fields (clears every error).
    void setCase(const solver::CaseSpec& spec);
    /// The case as edited; meaningful only while isValid().
    const solver::CaseSpec& currentCase() const { return m_case; }
    /// True when every field holds an allowed value and the keys agree with each other.
    bool isValid() const { return m_problems.isEmpty(); }
    /// Every problem as "section.key: reason", in field order.
    const QStringList& problems() const { return m_problems; }

    /// Type text into the field of "section.key" as a user would (for scripts and tests);
    /// false when there is no such field.
    bool setFieldText(const QString& path, const QString& text);
    /// The error shown under the field of "section.key" (empty when none).
    QString fieldError(const QString& path) const;

signals:
    /// A field changed; currentCase() and isValid() are up to date.
    void caseEdited();
    /// isValid() changed.
    void validityChanged(bool valid);

private:
    struct Field;
    void build();
    QWidget* makeEditor(Field& field);
    void revalidate();
    Field* find(const QString& path);
    const Field* find(const QString& path) const;

    std::vector<Field> m_fields;
    solver::CaseSpec m_case;
    QStringList m_problems;
    QLabel* m_summary = nullptr;
    bool m_filling = false;
};

} // namespace lbdem::studio
