#include "ui/shell/executing_block_follower.h"

#include <QTextBlock>

#include "core/task/program_loader.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_panel.h"
#include "ui/session/machine_session.h"

namespace kerf::ui {

namespace {

// Marks our extra selection among the editor's own.
constexpr int kExecutingProperty = QTextFormat::UserProperty + 0x4b45;

}  // namespace

ExecutingBlockFollower::ExecutingBlockFollower(MachineSession& session, ProgramPanel& program,
                                               QObject* parent)
    : QObject(parent), m_session(session), m_program(program) {
    connect(&session, &MachineSession::statusChanged, this, [this] { follow(); });
}

void ExecutingBlockFollower::follow() {
    ProgramEditor& editor = *m_program.editor();
    const bool shown = !m_program.path().empty() &&
                       task::programName(m_program.path()) == m_session.runningProgramName();
    const std::optional<int> line = shown ? m_session.executingLine() : std::nullopt;
    if (line) {
        if (!m_following) {
            m_following = true;
            m_wasReadOnly = editor.isReadOnly();
            // Edits would move the lines under the running blocks.
            editor.setReadOnly(true);
        }
        if (line != m_line) {
            mark(line);
            editor.goToLine(*line);
        }
        return;
    }
    // In a called program the last block of this one stays marked until the run ends.
    if (!m_following || (shown && m_session.busy())) return;
    m_following = false;
    editor.setReadOnly(m_wasReadOnly);
    mark(std::nullopt);
}

void ExecutingBlockFollower::mark(std::optional<int> line) {
    m_line = line;
    ProgramEditor& editor = *m_program.editor();
    QList<QTextEdit::ExtraSelection> selections;
    for (const QTextEdit::ExtraSelection& s : editor.extraSelections())
        if (!s.format.hasProperty(kExecutingProperty)) selections.append(s);
    if (line) {
        QTextEdit::ExtraSelection executing;
        executing.cursor = QTextCursor(editor.document()->findBlockByNumber(*line - 1));
        executing.format.setBackground(QColor(0xff, 0xd8, 0x66));
        executing.format.setProperty(QTextFormat::FullWidthSelection, true);
        executing.format.setProperty(kExecutingProperty, true);
        selections.append(executing);
    }
    editor.setExtraSelections(selections);
}

}  // namespace kerf::ui
