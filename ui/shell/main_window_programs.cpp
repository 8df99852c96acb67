// MainWindow's part for programs as files: opening one (after asking about unsaved edits), a new
// program, and the questions before quitting. Kept apart from main_window.cpp so the window
// stays a shell.
#include <QCloseEvent>
#include <QTextBlock>
#include <QTextCursor>
#include <cmath>

#include "ui/common/diagnostic_text.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_panel.h"
#include "ui/files/file_manager.h"
#include "ui/files/nc_file_operations.h"
#include "ui/files/new_program_dialog.h"
#include "ui/shell/main_window.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/mode_controller.h"
#include "ui/tables/table_editor.h"
#include "ui/touch/touch_size.h"

namespace kerf::ui {

void MainWindow::setPrompts(Prompts prompts) {
    m_prompts = std::move(prompts);
}

bool MainWindow::settleUnsavedEdits() {
    if (!m_program->modified()) return true;
    const QString name = m_program->path().empty()
                             ? tr("The program")
                             : QString::fromStdString(m_program->path().filename().string());
    return settle(
        name, [this] { return m_program->save(); }, [this] { m_program->abandonEdits(); });
}

bool MainWindow::settleUnsavedTableEdits() {
    if (!m_tables->modified()) return true;
    // Discarding needs nothing: the next table, or quitting, replaces the edited one.
    return settle(
        QString::fromStdString(m_tables->path().filename().string()),
        [this] { return m_tables->save(); }, [] {});
}

bool MainWindow::settle(const QString& name, const std::function<bool()>& save,
                        const std::function<void()>& discard) {
    UnsavedChoice choice = UnsavedChoice::Cancel;
    if (m_prompts.unsavedEdits) {
        choice = m_prompts.unsavedEdits(name);
    } else {
        const auto answer = askTouch(
            this, tr("Unsaved changes"), tr("%1 has unsaved changes. Save them?").arg(name),
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
        choice = answer == QMessageBox::Save      ? UnsavedChoice::Save
                 : answer == QMessageBox::Discard ? UnsavedChoice::Discard
                                                  : UnsavedChoice::Cancel;
    }
    switch (choice) {
        case UnsavedChoice::Save:
            return save();
        case UnsavedChoice::Discard:
            discard();
            return true;
        case UnsavedChoice::Cancel:
            break;
    }
    return false;
}

bool MainWindow::openProgram(const std::filesystem::path& path) {
    if (!settleUnsavedEdits()) return false;
    return showProgram(path);
}

bool MainWindow::showProgram(const std::filesystem::path& path) {
    if (!m_program->open(path)) return false;
    if (m_program->recoveryAvailable()) {
        m_messages->addMessage(
            Severity::Warning,
            tr("%1 has unsaved changes from an earlier session: press \"Restore autosave\" to "
               "get them back")
                .arg(QString::fromStdString(path.filename().string())));
    }
    m_files->addRecent(path);
    showPanels();
    return true;
}
bool MainWindow::newProgram() {
    if (!settleUnsavedEdits()) return false;
    std::optional<NewProgramSpec> spec;
    if (m_prompts.newProgram) {
        spec = m_prompts.newProgram();
    } else {
        NewProgramDialog dialog(m_context.machine, this);
        if (dialog.exec() == QDialog::Accepted) spec = dialog.spec();
    }
    if (!spec) return false;
    // Through the NC root: a new file inside it, never over an existing one or through a link.
    const NcFileOperations files(m_context.ncRoot);
    auto made = files.createFile(m_files->currentFolder(),
                                 newProgramFileName(m_context.machine, spec->name),
                                 newProgramText(m_context.machine, *spec));
    if (!made) {
        m_messages->addMessage(Severity::Error, translatedMessage(made.error()));
        return false;
    }
    if (!showProgram(*made)) return false;
    m_modes->requestProgrammingMode(task::ProgrammingMode::Programming);
    // The next block goes before END PGM (FAGOR: M30), as on the control: the cursor at the end
    // of the block above it (it stood before BEGIN PGM, where typing wrote into the header).
    ProgramEditor* editor = m_program->editor();
    QTextBlock last = editor->document()->lastBlock();
    while (last.isValid() && last.text().trimmed().isEmpty())
        last = last.previous();
    if (last.isValid() && last.previous().isValid()) {
        QTextCursor cursor(last.previous());
        cursor.movePosition(QTextCursor::EndOfBlock);
        editor->setTextCursor(cursor);
    }
    return true;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    // Quitting stops the machine: ask first while a program runs or the spindle turns.
    if (m_session != nullptr) {
        const task::MachineStatus& status = m_session->status();
        const bool spindle =
            std::abs(status.actualSpindleRpm) > 0.5 || std::abs(status.programmedSpindleRpm) > 0.5;
        if (m_session->busy() || spindle) {
            const QString question = m_session->busy()
                                         ? tr("A program is running. Stop it and quit?")
                                         : tr("The spindle turns. Stop it and quit?");
            const bool quit = m_prompts.confirm ? m_prompts.confirm(question)
                                                : confirmTouch(this, tr("Quit"), question);
            if (!quit) return event->ignore();
            m_session->stop();
        }
    }
    if (!settleUnsavedEdits() || !settleUnsavedTableEdits()) return event->ignore();
    // What is still unsaved (a save that failed) is kept in the recovery folder.
    if (m_program->modified()) m_program->autosave();
    QMainWindow::closeEvent(event);
}

}  // namespace kerf::ui
