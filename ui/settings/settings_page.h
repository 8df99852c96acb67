#pragma once

#include <QWidget>
#include <filesystem>

#include "core/base/diagnostic.h"
#include "core/machine/machine_config.h"

class QLabel;
class QLineEdit;
class QPushButton;
class QTableView;

namespace kerf::ui {

class SettingsModel;

// The machine-parameter screen: the schema's parameters by group, edited in place, checked by
// the schema (the message names the key), checked as a whole by validateMachine before an
// atomic save of the machine TOML. Kerf reads the machine when it starts, so the page says that
// saved changes apply after a restart, and for a built-in machine where the file goes and how to
// start with it. The values are shown to anyone; editing them asks for the machine's code
// number (parameter_code, 123 unless the machine file says otherwise) first, as on the TNC.
class SettingsPage : public QWidget {
    Q_OBJECT

public:
    // `file` is the machine TOML to write; `builtIn` when the machine was a built-in one
    // ("mill", "lathe") and `file` is a new file for it.
    SettingsPage(machine::MachineConfig config, std::filesystem::path file, bool builtIn,
                 QWidget* parent = nullptr);

    // Unlocks editing when `code` is the machine's code number; a wrong one is reported.
    bool unlock(const QString& code);
    bool locked() const;
    bool save();
    void undo();
    bool modified() const;
    const std::filesystem::path& file() const { return m_file; }
    SettingsModel* model() const { return m_model; }
    QTableView* view() const { return m_view; }

signals:
    void message(kerf::Severity severity, const QString& text);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    void report(const Diagnostic& d);

    std::filesystem::path m_file;
    bool m_builtIn = false;
    int m_code = 0;
    SettingsModel* m_model = nullptr;
    QTableView* m_view = nullptr;
    QLabel* m_title = nullptr;
    QLabel* m_note = nullptr;
    QWidget* m_codeRow = nullptr;
    QLabel* m_codeLabel = nullptr;
    QLineEdit* m_codeEdit = nullptr;
    QPushButton* m_unlockButton = nullptr;
};

}  // namespace kerf::ui
