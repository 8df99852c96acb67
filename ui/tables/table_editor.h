#pragma once

#include <QString>
#include <QWidget>
#include <filesystem>
#include <functional>

#include "core/base/diagnostic.h"

class QLineEdit;
class QLabel;
class QTableView;

namespace kerf::ui {

class TncTableModel;

// Editor page for the TNC tables (tool .T, preset .PR, and any other TNC table as plain cells):
// cells are checked as they are typed, rows inserted and deleted (after confirmation), edits
// undone, and the table is validated as a whole (unique tool numbers, numbers where numbers
// belong) before an atomic save.
class TableEditor : public QWidget {
    Q_OBJECT

public:
    explicit TableEditor(QWidget* parent = nullptr);
    ~TableEditor() override;

    bool open(const std::filesystem::path& path);
    bool save();
    const std::filesystem::path& path() const { return m_path; }
    bool modified() const;

    // Whole-table validation with the typed view matching the file (ToolTable for .T ...).
    DiagnosticList validate() const;

    bool insertRow();  // above the current row (or at the end)
    bool deleteRow();  // the current row, after confirmation
    void undo();
    bool find(const QString& text);

    void setConfirm(std::function<bool(const QString&)> confirm) { m_confirm = std::move(confirm); }
    TncTableModel* model() const { return m_model; }
    QTableView* view() const { return m_view; }

protected:
    void changeEvent(QEvent* event) override;

signals:
    void message(kerf::Severity severity, const QString& text);

private:
    void retranslate();
    void reportDiagnostic(const Diagnostic& d);

    std::filesystem::path m_path;
    TncTableModel* m_model = nullptr;
    QTableView* m_view = nullptr;
    QLabel* m_title = nullptr;
    QLineEdit* m_search = nullptr;
    std::function<bool(const QString&)> m_confirm;
};

}  // namespace kerf::ui
