#include "ui/tables/table_editor.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>

#include "core/base/atomic_file.h"
#include "core/interp/fagor/tables/table_text.h"
#include "core/program/nc_root.h"
#include "core/tables/table_file.h"
#include "ui/common/diagnostic_text.h"
#include "ui/tables/fagor_table_model.h"
#include "ui/tables/table_kinds.h"
#include "ui/tables/tnc_table_model.h"
#include "ui/touch/touch_size.h"

namespace kerf::ui {

TableEditor::TableEditor(std::filesystem::path ncRoot, QWidget* parent)
    : QWidget(parent), m_ncRoot(std::move(ncRoot)) {
    setObjectName("tableEditor");
    registerDiagnosticMetaTypes();
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* top = new QHBoxLayout();
    m_title = new QLabel(this);
    m_search = new QLineEdit(this);
    m_search->setMinimumHeight(kTouchHeight);
    connect(m_search, &QLineEdit::returnPressed, this, [this] { find(m_search->text()); });
    top->addWidget(m_title, 1);
    top->addWidget(m_search);
    layout->addLayout(top);
    m_view = new QTableView(this);
    m_view->setObjectName("tableView");
    makeTouchSizedRows(*m_view);
    m_view->setSelectionBehavior(QAbstractItemView::SelectItems);
    layout->addWidget(m_view, 1);
    m_diskCheck = new QTimer(this);
    m_diskCheck->setInterval(1000);
    connect(m_diskCheck, &QTimer::timeout, this, [this] {
        if (isVisible()) checkFileOnDisk();
    });
    m_diskCheck->start();
    retranslate();
}

std::optional<TableEditor::FileStamp> TableEditor::stampOnDisk() const {
    std::error_code error;
    const auto time = std::filesystem::last_write_time(m_path, error);
    if (error) return std::nullopt;
    const auto size = std::filesystem::file_size(m_path, error);
    if (error) return std::nullopt;
    return FileStamp{time, size};
}

void TableEditor::checkFileOnDisk() {
    if (m_model == nullptr || m_path.empty()) return;
    const auto now = stampOnDisk();
    if (!now || now == m_stamp) return;
    if (!modified()) {
        const std::filesystem::path path = m_path;
        if (open(path)) {
            emit message(Severity::Note,
                         tr("%1 was changed on disk (e.g. by a tool measurement): reloaded")
                             .arg(QString::fromStdString(path.filename().string())));
        }
        return;
    }
    if (m_warnedChanged) return;
    m_warnedChanged = true;
    emit message(Severity::Warning,
                 tr("%1 was changed on disk while you edit it: saving would overwrite those "
                    "changes")
                     .arg(QString::fromStdString(m_path.filename().string())));
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

EditableTableModel* TableEditor::loadModel(const std::filesystem::path& path) {
    const TableKind kind = tableKindOf(path);
    if (isFagorTable(kind)) {
        auto bytes = readWholeFile(path);
        if (!bytes) {
            reportDiagnostic(bytes.error());
            return nullptr;
        }
        auto text = fagor::TableText::parse(*bytes, path.string());
        if (!text) {
            reportDiagnostic(text.error());
            return nullptr;
        }
        return new FagorTableModel(std::move(*text), fagorTableSpec(kind, m_axisLetters), this);
    }
    auto table = tables::loadTable(path);
    if (!table) {
        reportDiagnostic(table.error());
        return nullptr;
    }
    return new TncTableModel(
        typedTncTable(std::move(*table), kind), this,
        [kind](const tables::TncTable& t) { return validateTncTable(t, kind); });
}

bool TableEditor::open(const std::filesystem::path& path) {
    EditableTableModel* model = loadModel(path);
    if (model == nullptr) return false;
    m_path = path;
    connect(model, &EditableTableModel::refused, this, &TableEditor::reportDiagnostic);
    m_view->setModel(model);
    delete m_model;
    m_model = model;
    m_view->resizeColumnsToContents();
    m_title->setText(QString::fromStdString(path.filename().string()));
    m_stamp = stampOnDisk();
    m_warnedChanged = false;
    for (const Diagnostic& d : validate())
        reportDiagnostic(d);
    return true;
}

bool TableEditor::modified() const {
    return m_model != nullptr && m_model->modified();
}

DiagnosticList TableEditor::validate() const {
    return m_model == nullptr ? DiagnosticList{} : m_model->validate();
}

TncTableModel* TableEditor::model() const {
    return qobject_cast<TncTableModel*>(m_model);
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
    if (const auto now = stampOnDisk(); now && m_stamp && now != m_stamp) {
        const QString question =
            tr("%1 was changed on disk since it was opened here (e.g. by a tool measurement). "
               "Overwrite it with the table shown?")
                .arg(QString::fromStdString(m_path.filename().string()));
        const bool confirmed =
            m_confirm ? m_confirm(question) : confirmTouch(this, tr("Table"), question);
        if (!confirmed) {
            emit message(Severity::Warning, tr("Not saved: the file on disk is kept"));
            return false;
        }
    }
    // Through the NC root: never outside it, never through a link (docs/files.md).
    if (const MaybeError error = program::NcRoot(m_ncRoot).replace(m_path, m_model->content())) {
        reportDiagnostic(*error);
        return false;
    }
    m_model->setSaved();
    m_stamp = stampOnDisk();
    m_warnedChanged = false;
    emit message(Severity::Note,
                 tr("Saved %1").arg(QString::fromStdString(m_path.filename().string())));
    return true;
}

bool TableEditor::insertRow() {
    if (m_model == nullptr) return false;
    const int row =
        m_view->currentIndex().isValid() ? m_view->currentIndex().row() : m_model->rowCount();
    const int inserted = m_model->insertKeyedRow(row);
    if (inserted < 0) return false;
    m_view->setCurrentIndex(m_model->index(inserted, 0));
    return true;
}

bool TableEditor::deleteRow() {
    if (m_model == nullptr || !m_view->currentIndex().isValid()) return false;
    const int row = m_view->currentIndex().row();
    const QString key = m_model->data(m_model->index(row, 0), Qt::DisplayRole).toString();
    const QString question = tr("Delete row %1 (%2)?").arg(row + 1).arg(key);
    const bool confirmed =
        m_confirm ? m_confirm(question) : confirmTouch(this, tr("Table"), question);
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
