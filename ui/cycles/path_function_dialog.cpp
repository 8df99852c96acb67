#include "ui/cycles/path_function_dialog.h"

namespace kerf::ui {

namespace {

std::vector<WordRow> rowsOf(const std::vector<PathField>& fields) {
    std::vector<WordRow> rows;
    for (const PathField& field : fields)
        rows.push_back({field.word, field.choices});
    return rows;
}

}  // namespace

PathFunctionDialog::PathFunctionDialog(PathFunction function, QWidget* parent)
    : WordFieldsDialog(parent, "pathFunctionDialog"),
      m_function(function),
      m_fields(pathFields(function)) {
    build(pathFunctionKeyword(function), rowsOf(m_fields), "pathMessage", 140);
}

QString PathFunctionDialog::block() const {
    return writePathFunction(m_function, values());
}

std::optional<QString> PathFunctionDialog::checkRow(int field, const QString& text) const {
    return checkPathField(m_fields.at(static_cast<size_t>(field)), text);
}

std::optional<QString> PathFunctionDialog::checkBlock(const QStringList& values) const {
    return checkPathFunction(m_function, values);
}

QString PathFunctionDialog::rowDescription(int field) const {
    return pathFieldDescription(m_fields.at(static_cast<size_t>(field)));
}

QString PathFunctionDialog::dialogTitle() const {
    return tr("Path function");
}

}  // namespace kerf::ui
