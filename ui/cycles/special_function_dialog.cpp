#include "ui/cycles/special_function_dialog.h"

namespace kerf::ui {

namespace {

std::vector<WordRow> rowsOf(const std::vector<SpecialField>& fields) {
    std::vector<WordRow> rows;
    for (const SpecialField& field : fields) {
        const bool choice = field.kind == SpecialFieldKind::Choice;
        rows.push_back({field.word, choice ? field.choices : QStringList()});
    }
    return rows;
}

}  // namespace

SpecialFunctionDialog::SpecialFunctionDialog(SpecialFunction function, QWidget* parent)
    : WordFieldsDialog(parent, "specialFunctionDialog"),
      m_function(function),
      m_fields(specialFields(function)) {
    build(specialFunctionTitle(function), rowsOf(m_fields), "specialMessage", 160);
}

std::optional<QString> SpecialFunctionDialog::checkRow(int field, const QString& text) const {
    return checkSpecialField(m_fields.at(static_cast<size_t>(field)), text);
}

std::optional<QString> SpecialFunctionDialog::checkBlock(const QStringList& values) const {
    return checkSpecialFunction(m_function, values);
}

QString SpecialFunctionDialog::rowDescription(int field) const {
    return specialFieldDescription(m_fields.at(static_cast<size_t>(field)));
}

QString SpecialFunctionDialog::dialogTitle() const {
    return tr("Special function");
}

}  // namespace kerf::ui
