#pragma once

#include <QString>
#include <QWidget>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "core/base/diagnostic.h"

class QLineEdit;
class QLabel;
class QTableView;
class QTimer;

namespace kerf::ui {

class EditableTableModel;
class TncTableModel;

// Editor page for the tables (docs/hmi.md, "Tables"): the TNC tool, preset, datum, point and
// touch-probe tables (other TNC tables as plain cells) and the FAGOR tool offsets, zero offsets
// and tools. Cells are checked as they are typed, rows inserted and deleted (after
// confirmation), edits undone, and the table is validated as a whole (unique keys, numbers where
// numbers belong, allowed words) before an atomic save.
class TableEditor : public QWidget {
    Q_OBJECT

public:
    // Saves go through the file-access layer of `ncRoot` (docs/files.md).
    explicit TableEditor(std::filesystem::path ncRoot, QWidget* parent = nullptr);
    ~TableEditor() override;

    bool open(const std::filesystem::path& path);
    // Refuses (unless confirmed) to overwrite a file that changed on disk since it was opened or
    // saved here: a program run may have written measured tools into TOOL.T meanwhile.
    bool save();
    // The file changed on disk: reloaded when nothing is edited, else a warning (once). Called
    // every second while the editor is shown; tests call it directly.
    void checkFileOnDisk();
    const std::filesystem::path& path() const { return m_path; }
    bool modified() const;

    // Whole-table validation with the typed view matching the file (ToolTable for .T ...).
    DiagnosticList validate() const;
    // Columns of the FAGOR zero offsets: the machine's axes ("XZ" unless told).
    void setAxisLetters(std::string letters) { m_axisLetters = std::move(letters); }

    bool insertRow();  // above the current row (or at the end)
    bool deleteRow();  // the current row, after confirmation
    void undo();
    bool find(const QString& text);

    void setConfirm(std::function<bool(const QString&)> confirm) { m_confirm = std::move(confirm); }
    EditableTableModel* tableModel() const { return m_model; }
    // The model of a TNC table; nullptr for the FAGOR tables.
    TncTableModel* model() const;
    QTableView* view() const { return m_view; }

protected:
    void changeEvent(QEvent* event) override;

signals:
    void message(kerf::Severity severity, const QString& text);

private:
    void retranslate();
    void reportDiagnostic(const Diagnostic& d);
    EditableTableModel* loadModel(const std::filesystem::path& path);
    // What identifies the file's version on disk: its modification time and size.
    struct FileStamp {
        std::filesystem::file_time_type time;
        std::uintmax_t size = 0;
        bool operator==(const FileStamp&) const = default;
    };
    std::optional<FileStamp> stampOnDisk() const;

    std::filesystem::path m_ncRoot;
    std::filesystem::path m_path;
    EditableTableModel* m_model = nullptr;
    std::string m_axisLetters = "XZ";
    QTableView* m_view = nullptr;
    QLabel* m_title = nullptr;
    QLineEdit* m_search = nullptr;
    std::function<bool(const QString&)> m_confirm;
    std::optional<FileStamp> m_stamp;  // the file as opened or saved here
    bool m_warnedChanged = false;
    QTimer* m_diskCheck = nullptr;
};

}  // namespace kerf::ui
