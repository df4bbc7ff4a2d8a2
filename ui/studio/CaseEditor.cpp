// Building the case editor's fields from CaseSchema and validating them as the user types.
#include "ui/studio/CaseEditor.h"

#include "solver/scene/CaseSchema.h"
#include "solver/scene/CaseValidation.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QScrollArea>
#include <QVBoxLayout>

#include <algorithm>
#include <optional>

namespace lbdem::studio {

using solver::ParamDecl;
using solver::ParamType;
using solver::ParamValue;

struct CaseEditor::Field {
    const ParamDecl* decl = nullptr;
    QWidget* editor = nullptr;
    QLabel* error = nullptr;
    QString path;
};

namespace {

QString valueText(const ParamValue& value) {
    if (const auto* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
    if (const auto* i = std::get_if<long long>(&value)) return QString::number(*i);
    if (const auto* d = std::get_if<double>(&value)) return QString::number(*d, 'g', 10);
    return QString::fromStdString(std::get<std::string>(value));
}

QString sectionTitle(const std::string& section) {
    if (section.empty()) return QObject::tr("Case");
    QString title = QString::fromStdString(section);
    title[0] = title[0].toUpper();
    return title;
}

QString tooltipOf(const ParamDecl& decl) {
    QString tip = QString::fromStdString(decl.doc);
    const std::string range = decl.describeRange();
    if (!range.empty()) tip += "\n" + QObject::tr("Allowed: %1").arg(QString::fromStdString(range));
    if (!decl.unit.empty() && decl.unit != "-")
        tip += "\n" + QObject::tr("Unit: %1").arg(QString::fromStdString(decl.unit));
    tip += "\n" + QObject::tr("Default: %1").arg(valueText(decl.defaultValue()));
    return tip;
}

// Text typed into a number field, read as the case file would: whole numbers stay whole so
// that ParamDecl::check can tell "expected a whole number" from a range error.
std::optional<ParamValue> parseNumber(const QString& text) {
    const QString trimmed = text.trimmed();
    bool ok = false;
    const qlonglong whole = trimmed.toLongLong(&ok);
    if (ok) return ParamValue{static_cast<long long>(whole)};
    const double real = QLocale::c().toDouble(trimmed, &ok);
    if (ok) return ParamValue{real};
    return std::nullopt;
}

} // namespace

CaseEditor::CaseEditor(QWidget* parent) : QWidget(parent) {
    build();
    setCase(solver::defaultCase());
}

CaseEditor::~CaseEditor() = default;

void CaseEditor::build() {
    auto* content = new QWidget;
    auto* column = new QVBoxLayout(content);
    const auto& schema = solver::CaseSchema::instance();
    m_fields.reserve(schema.params().size());
    for (const std::string& section : schema.sections()) {
        auto* box = new QGroupBox(sectionTitle(section));
        auto* form = new QFormLayout(box);
        form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
        for (const ParamDecl& decl : schema.params()) {
            if (decl.section != section) continue;
            Field& field = m_fields.emplace_back();
            field.decl = &decl;
            field.path = QString::fromStdString(decl.path());
            QString label = QString::fromStdString(decl.key);
            if (!decl.unit.empty() && decl.unit != "-")
                label += QString(" [%1]").arg(QString::fromStdString(decl.unit));
            auto* cell = new QWidget;
            auto* stack = new QVBoxLayout(cell);
            stack->setContentsMargins(0, 0, 0, 0);
            stack->setSpacing(1);
            stack->addWidget(makeEditor(field));
            field.error = new QLabel;
            field.error->setObjectName("fieldError");
            field.error->setStyleSheet("color: #b00020;");
            field.error->setWordWrap(true);
            field.error->hide();
            stack->addWidget(field.error);
            auto* labelWidget = new QLabel(label);
            labelWidget->setToolTip(tooltipOf(decl));
            form->addRow(labelWidget, cell);
        }
        column->addWidget(box);
    }
    column->addStretch(1);

    auto* scroll = new QScrollArea;
    scroll->setWidget(content);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_summary = new QLabel;
    m_summary->setWordWrap(true);
    m_summary->setStyleSheet("color: #b00020;");
    auto* outer = new QVBoxLayout(this);
    outer->setContentsMargins(0, 0, 0, 0);
    outer->addWidget(scroll, 1);
    outer->addWidget(m_summary);
}

QWidget* CaseEditor::makeEditor(Field& field) {
    const ParamDecl& decl = *field.decl;
    const QString tip = tooltipOf(decl);
    if (decl.type == ParamType::Bool) {
        auto* box = new QCheckBox;
        connect(box, &QCheckBox::toggled, this, &CaseEditor::revalidate);
        field.editor = box;
    } else if (decl.type == ParamType::Choice) {
        auto* combo = new QComboBox;
        for (const auto& choice : decl.choices)
            combo->addItem(QString::fromStdString(choice));
        connect(combo, &QComboBox::currentTextChanged, this, &CaseEditor::revalidate);
        field.editor = combo;
    } else {
        auto* line = new QLineEdit;
        if (decl.type != ParamType::Text)
            line->setPlaceholderText(QString::fromStdString(decl.describeRange()));
        connect(line, &QLineEdit::textChanged, this, &CaseEditor::revalidate);
        field.editor = line;
    }
    field.editor->setObjectName(field.path);
    field.editor->setToolTip(tip);
    return field.editor;
}

void CaseEditor::setCase(const solver::CaseSpec& spec) {
    m_filling = true;
    for (Field& field : m_fields) {
        const ParamValue value = field.decl->get(spec);
        if (auto* box = qobject_cast<QCheckBox*>(field.editor))
            box->setChecked(std::get<bool>(value));
        else if (auto* combo = qobject_cast<QComboBox*>(field.editor))
            combo->setCurrentText(valueText(value));
        else if (auto* line = qobject_cast<QLineEdit*>(field.editor))
            line->setText(valueText(value));
    }
    m_filling = false;
    revalidate();
}

bool CaseEditor::setFieldText(const QString& path, const QString& text) {
    Field* field = find(path);
    if (!field) return false;
    if (auto* box = qobject_cast<QCheckBox*>(field->editor))
        box->setChecked(text == "true");
    else if (auto* combo = qobject_cast<QComboBox*>(field->editor))
        combo->setCurrentText(text);
    else if (auto* line = qobject_cast<QLineEdit*>(field->editor))
        line->setText(text);
    return true;
}

QString CaseEditor::fieldError(const QString& path) const {
    const Field* field = find(path);
    return field && !field->error->isHidden() ? field->error->text() : QString();
}

void CaseEditor::revalidate() {
    if (m_filling) return;
    const bool wasValid = isValid();
    solver::CaseSpec spec = solver::defaultCase();
    QStringList problems;
    std::vector<QString> errors(m_fields.size());
    for (std::size_t k = 0; k < m_fields.size(); ++k) {
        const Field& field = m_fields[k];
        std::optional<ParamValue> value;
        if (auto* box = qobject_cast<QCheckBox*>(field.editor))
            value = box->isChecked();
        else if (auto* combo = qobject_cast<QComboBox*>(field.editor))
            value = combo->currentText().toStdString();
        else if (auto* line = qobject_cast<QLineEdit*>(field.editor))
            value = field.decl->type == ParamType::Text
                        ? std::optional<ParamValue>(line->text().toStdString())
                        : parseNumber(line->text());
        std::string reason =
            value ? field.decl->check(*value)
                  : "expected " + std::string(solver::describeType(field.decl->type));
        if (reason.empty())
            field.decl->set(spec, *value);
        else
            errors[k] = QString::fromStdString(reason);
    }
    // Cross-key rules only make sense once every key is within its own range.
    if (std::all_of(errors.begin(), errors.end(), [](const QString& e) { return e.isEmpty(); })) {
        for (const auto& problem : solver::validateCase(spec)) {
            const QString path = QString::fromStdString(problem.path);
            const QString message = QString::fromStdString(problem.message);
            bool placed = false;
            for (std::size_t k = 0; k < m_fields.size(); ++k)
                if (m_fields[k].path == path) {
                    errors[k] += (errors[k].isEmpty() ? "" : "; ") + message;
                    placed = true;
                }
            if (!placed) problems << path + ": " + message;
        }
    }
    QStringList fieldProblems;
    for (std::size_t k = 0; k < m_fields.size(); ++k) {
        m_fields[k].error->setText(errors[k]);
        m_fields[k].error->setVisible(!errors[k].isEmpty());
        if (!errors[k].isEmpty()) fieldProblems << m_fields[k].path + ": " + errors[k];
    }
    problems = fieldProblems + problems;
    m_case = spec;
    m_problems = problems;
    m_summary->setText(
        problems.isEmpty()
            ? QString()
            : tr("Run is disabled until this is fixed: %1").arg(problems.join("; ")));
    m_summary->setVisible(!problems.isEmpty());
    emit caseEdited();
    if (wasValid != isValid()) emit validityChanged(isValid());
}

CaseEditor::Field* CaseEditor::find(const QString& path) {
    for (Field& field : m_fields)
        if (field.path == path) return &field;
    return nullptr;
}

const CaseEditor::Field* CaseEditor::find(const QString& path) const {
    for (const Field& field : m_fields)
        if (field.path == path) return &field;
    return nullptr;
}

} // namespace lbdem::studio
