#include "ui/cycles/special_function_dialog.h"

#include <QEvent>
#include <QLineEdit>
#include <QPushButton>

#include "ui/cycles/program_file_dialog.h"

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

SpecialFunctionDialog::SpecialFunctionDialog(SpecialFunction function, ProgramPlace place,
                                             QWidget* parent)
    : WordFieldsDialog(parent, "specialFunctionDialog"),
      m_function(function),
      m_fields(specialFields(function)),
      m_place(std::move(place)) {
    build(specialFunctionTitle(function), rowsOf(m_fields), "specialMessage", 160);
    for (size_t i = 0; i < m_fields.size(); ++i)
        if (m_fields[i].kind == SpecialFieldKind::ProgramName) m_programField = static_cast<int>(i);
    if (m_programField < 0 || m_place.ncRoot.empty()) return;
    m_selectFile = new QPushButton(tr("Select file"), this);
    m_selectFile->setObjectName("selectFile");
    m_selectFile->setAutoDefault(false);
    connect(m_selectFile, &QPushButton::clicked, this, [this] { selectFile(); });
    addToRow(m_programField, m_selectFile);
}

bool SpecialFunctionDialog::selectFile() {
    if (m_programField < 0 || m_place.ncRoot.empty()) return false;
    ProgramFileDialog files(m_place.ncRoot, m_place.folder, this);
    if (files.exec() != QDialog::Accepted) return false;
    const std::optional<std::filesystem::path> chosen = files.selectedPath();
    if (!chosen) return false;
    const ProgramReference reference = programReference(*chosen, m_place);
    if (!reference.refusal.isEmpty()) {
        setMessage(reference.refusal);
        return false;
    }
    // A name the block cannot hold (a blank, a quote) is refused as if it had been typed.
    if (const auto error = checkRow(m_programField, reference.name)) {
        setMessage(*error);
        return false;
    }
    auto* field = static_cast<QLineEdit*>(input(m_programField));
    field->setText(reference.name);
    field->setFocus();
    setMessage({});
    return true;
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

void SpecialFunctionDialog::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange && m_selectFile != nullptr)
        m_selectFile->setText(tr("Select file"));
    WordFieldsDialog::changeEvent(event);
}

}  // namespace kerf::ui
