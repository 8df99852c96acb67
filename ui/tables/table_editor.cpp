#include "ui/tables/table_editor.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QTableView>
#include <QVBoxLayout>
#include <algorithm>
#include <cctype>

#include "core/tables/preset_table.h"
#include "core/tables/table_file.h"
#include "core/tables/table_validation.h"
#include "core/tables/tool_table.h"
#include "ui/common/diagnostic_text.h"
#include "ui/tables/tnc_table_model.h"

namespace kerf::ui {

namespace {

std::string upperExtension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return extension;
}

// The table with the column formats of its typed view, so that numeric columns refuse text
// while it is typed. A file the typed view rejects is still opened, untyped, to be repaired.
tables::TncTable typedTable(tables::TncTable table, const std::string& extension) {
    if (extension == ".T") {
        if (auto tools = tables::ToolTable::fromTable(table)) return tools->table();
    } else if (extension == ".PR") {
        if (auto presets = tables::PresetTable::fromTable(table)) return presets->table();
    }
    return table;
}

}  // namespace

TableEditor::TableEditor(QWidget* parent) : QWidget(parent) {
    setObjectName("tableEditor");
    registerDiagnosticMetaTypes();
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* top = new QHBoxLayout();
    m_title = new QLabel(this);
    m_search = new QLineEdit(this);
    m_search->setMinimumHeight(40);
    connect(m_search, &QLineEdit::returnPressed, this, [this] { find(m_search->text()); });
    top->addWidget(m_title, 1);
    top->addWidget(m_search);
    layout->addLayout(top);
    m_view = new QTableView(this);
    m_view->setObjectName("tableView");
    m_view->verticalHeader()->setDefaultSectionSize(36);
    m_view->setSelectionBehavior(QAbstractItemView::SelectItems);
    layout->addWidget(m_view, 1);
    retranslate();
}

void TableEditor::retranslate() {
    m_search->setPlaceholderText(tr("Search"));
    if (m_model == nullptr) m_title->setText(tr("No table"));
}

void TableEditor::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) retranslate();
    QWidget::changeEvent(event);
}

TableEditor::~TableEditor() = default;

bool TableEditor::open(const std::filesystem::path& path) {
    auto table = tables::loadTable(path);
    if (!table) {
        reportDiagnostic(table.error());
        return false;
    }
    m_path = path;
    auto* model = new TncTableModel(typedTable(std::move(*table), upperExtension(path)), this);
    connect(model, &TncTableModel::refused, this, &TableEditor::reportDiagnostic);
    m_view->setModel(model);
    delete m_model;
    m_model = model;
    m_view->resizeColumnsToContents();
    m_title->setText(QString::fromStdString(path.filename().string()));
    for (const Diagnostic& d : validate())
        reportDiagnostic(d);
    return true;
}

bool TableEditor::modified() const {
    return m_model != nullptr && m_model->modified();
}

DiagnosticList TableEditor::validate() const {
    if (m_model == nullptr) return {};
    const tables::TncTable& table = m_model->table();
    const std::string extension = upperExtension(m_path);
    if (extension == ".T") {
        auto tools = tables::ToolTable::fromTable(table);
        return tools ? DiagnosticList{} : DiagnosticList{tools.error()};
    }
    if (extension == ".PR") {
        auto presets = tables::PresetTable::fromTable(table);
        return presets ? DiagnosticList{} : DiagnosticList{presets.error()};
    }
    return tables::checkNumericCells(table);
}

bool TableEditor::save() {
    if (m_model == nullptr) return false;
    const DiagnosticList problems = validate();
    if (hasErrors(problems)) {
        for (const Diagnostic& d : problems)
            reportDiagnostic(d);
        emit message(Severity::Error, tr("Not saved: correct the table first"));
        return false;
    }
    if (const MaybeError error = tables::saveTable(m_model->table(), m_path)) {
        reportDiagnostic(*error);
        return false;
    }
    m_model->setSaved();
    emit message(Severity::Note,
                 tr("Saved %1").arg(QString::fromStdString(m_path.filename().string())));
    return true;
}

bool TableEditor::insertRow() {
    if (m_model == nullptr) return false;
    const int row =
        m_view->currentIndex().isValid() ? m_view->currentIndex().row() : m_model->rowCount();
    if (!m_model->insertKeyedRow(row)) return false;
    m_view->setCurrentIndex(m_model->index(row, 0));
    return true;
}

bool TableEditor::deleteRow() {
    if (m_model == nullptr || !m_view->currentIndex().isValid()) return false;
    const int row = m_view->currentIndex().row();
    const QString key = m_model->data(m_model->index(row, 0), Qt::DisplayRole).toString();
    const QString question = tr("Delete row %1 (%2)?").arg(row + 1).arg(key);
    const bool confirmed =
        m_confirm ? m_confirm(question)
                  : QMessageBox::question(this, tr("Table"), question) == QMessageBox::Yes;
    return confirmed && m_model->removeTableRow(row);
}

void TableEditor::undo() {
    if (m_model != nullptr) m_model->undo();
}

bool TableEditor::find(const QString& text) {
    if (m_model == nullptr || text.isEmpty()) return false;
    const int from = m_view->currentIndex().isValid() ? m_view->currentIndex().row() + 1 : 0;
    const int row = m_model->findRow(text, from);
    if (row < 0) return false;
    m_view->setCurrentIndex(m_model->index(row, 0));
    return true;
}

void TableEditor::reportDiagnostic(const Diagnostic& d) {
    // Compiler style, so the operator sees the line and column of the offending cell.
    QString place = QString::fromStdString(std::filesystem::path(d.file).filename().string());
    if (d.line > 0) place += QStringLiteral(":%1:%2").arg(d.line).arg(d.column);
    emit message(d.severity, QStringLiteral("%1: %2").arg(place, translatedMessage(d)));
}

}  // namespace kerf::ui
