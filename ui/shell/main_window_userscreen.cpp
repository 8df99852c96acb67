// The FAGOR user screen: the customisation program of the mode on screen (spec part 2 §6.8) runs
// on its own page; its softkeys are the bar's F1-F7, and in Programming the blocks its WBUF
// writes go into the program in the editor after the cursor.
#include <QPlainTextEdit>
#include <QTextBlock>

#include "ui/common/diagnostic_text.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_panel.h"
#include "ui/shell/main_window.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/workspace.h"
#include "ui/userscreen/user_screen_run.h"
#include "ui/userscreen/user_screen_view.h"

namespace kerf::ui {

namespace {

// The machine parameter that names each mode's program, used as its file name in the NC root.
struct UserProgram {
    fagor::UserMode mode;
    const char* file;
};

UserProgram userProgramOf(ScreenMode screen, task::MachineMode machine) {
    if (screen == ScreenMode::Programming) return {fagor::UserMode::Edit, "USEREDIT.PIM"};
    if (machine == task::MachineMode::Manual || machine == task::MachineMode::Handwheel) {
        return {fagor::UserMode::Manual, "USERMAN.PIM"};
    }
    return {fagor::UserMode::Execution, "USERDPLY.PIM"};
}

// One block on a new line after the cursor's line, in one undo step; the cursor follows it so
// that the next block goes after it.
void insertAfterCursor(QPlainTextEdit& editor, const QString& block) {
    QTextCursor cursor = editor.textCursor();
    cursor.beginEditBlock();
    if (cursor.block().text().trimmed().isEmpty()) {
        cursor.select(QTextCursor::LineUnderCursor);
        cursor.insertText(block);
    } else {
        cursor.movePosition(QTextCursor::EndOfBlock);
        cursor.insertText(QStringLiteral("\n") + block);
    }
    cursor.endEditBlock();
    editor.setTextCursor(cursor);
}

}  // namespace

bool MainWindow::openUserScreen() {
    const UserProgram user = userProgramOf(m_modes->screen(), m_modes->machineMode());
    const std::filesystem::path program = m_context.ncRoot / user.file;
    std::error_code error;
    if (!std::filesystem::is_regular_file(program, error)) {
        m_messages->addMessage(
            Severity::Error,
            tr("No user customisation program: %1 is not in the NC root").arg(user.file));
        return false;
    }
    if (m_userScreenRun == nullptr) {
        m_userScreenRun = new UserScreenRun(m_context.machine, this);
        m_userScreenView = new UserScreenView(*m_userScreenRun, this);
        m_userScreenView->hide();
        connect(m_userScreenRun, &UserScreenRun::changed, this, [this] { userScreenChanged(); });
        connect(m_userScreenRun, &UserScreenRun::ended, this,
                [this](bool failed) { userScreenEnded(failed); });
        connect(m_userScreenView, &UserScreenView::message, this,
                [this](const QString& text) { m_messages->addMessage(Severity::Error, text); });
    }
    if (!m_userScreenRun->start(program, m_context.ncRoot, user.mode)) {
        for (const Diagnostic& d : m_userScreenRun->diagnostics())
            m_messages->addMessage(d.severity, translatedMessage(d));
        return false;
    }
    m_page = Page::UserScreen;
    m_workspace->showPage(m_userScreenView);
    m_userScreenView->refresh();
    refreshSoftkeys();
    return true;
}

SoftkeyRow MainWindow::userScreenOpenRow() {
    return {{"userScreen", tr("User"), [this] { openUserScreen(); }}};
}

std::vector<SoftkeyRow> MainWindow::userScreenRows() {
    SoftkeyRow row;
    const fagor::UserScreen* screen = m_userScreenRun->screen();
    for (int i = 0; i < fagor::UserScreen::kSoftkeys; ++i) {
        const std::string& text = screen->softkeys()[static_cast<size_t>(i)];
        const auto [upper, lower] = fagor::softkeyLines(text);
        QString label = QString::fromStdString(upper).trimmed();
        if (!lower.empty()) label += "\n" + QString::fromStdString(lower).trimmed();
        row.push_back({QStringLiteral("userF%1").arg(i + 1), label, [this, i] {
                           m_userScreenRun->pressKey(fagor::UserScreen::kSoftkeyF1 + i);
                       }});
    }
    row.push_back({"userLeave", tr("Leave\nuser screen"), [this] {
                       m_userScreenRun->stop();
                       showPanels();
                   }});
    return {row};
}

void MainWindow::userScreenChanged() {
    fagor::UserScreen* screen = m_userScreenRun->screen();
    for (const std::string& block : screen->takeInsertedBlocks()) {
        ProgramEditor* editor = m_program->editor();
        if (editor->isReadOnly()) {
            m_messages->addMessage(Severity::Error,
                                   tr("The program in the editor is protected: the block %1 "
                                      "of the user screen was not inserted")
                                       .arg(QString::fromStdString(block)));
            continue;
        }
        insertAfterCursor(*editor, QString::fromStdString(block));
    }
    if (m_page == Page::UserScreen) refreshSoftkeys();
}

void MainWindow::userScreenEnded(bool failed) {
    userScreenChanged();
    for (const Diagnostic& d : m_userScreenRun->diagnostics()) {
        if (d.severity != Severity::Note) m_messages->addMessage(d.severity, translatedMessage(d));
    }
    // SYSTEM returns to the standard menu of the mode.
    if (!failed && m_userScreenRun->screen()->left() && m_page == Page::UserScreen) showPanels();
}

}  // namespace kerf::ui
