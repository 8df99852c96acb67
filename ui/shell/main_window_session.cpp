// MainWindow's part for the machine: the session, the position display and the machine-mode
// softkeys. Kept apart from main_window.cpp so the window stays a shell.
#include <QCoreApplication>

#include "ui/editor/program_editor.h"
#include "ui/editor/program_panel.h"
#include "ui/session/machine_session.h"
#include "ui/shell/machine_rows.h"
#include "ui/shell/main_window.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/workspace.h"
#include "ui/status/override_controls.h"
#include "ui/status/position_display.h"
#include "ui/status/status_tabs.h"

namespace kerf::ui {

void MainWindow::connectSession() {
    if (m_context.programmingStation || !m_context.motion) return;
    m_session = new MachineSession(m_context.machine, m_context.motion(), m_context.ncRoot, this);
    m_modes->setMovingQuery([this] { return m_session->busy(); });
    connect(m_session, &MachineSession::statusChanged, m_positions, &PositionDisplay::setStatus);
    connect(m_session, &MachineSession::runStateChanged, this, [this](task::RunState state) {
        m_positions->setRunState(QCoreApplication::translate("kerf", task::runStateName(state)));
    });
    connect(m_session, &MachineSession::message, m_messages,
            [this](Severity severity, const QString& text, int line) {
                m_messages->addMessage(severity, text, line);
            });
    connect(m_session, &MachineSession::programStatusChanged, m_status,
            &StatusTabs::setProgramStatus);
    OverrideControls* overrides = m_positions->overrides();
    connect(overrides, &OverrideControls::feedOverrideChanged, m_session,
            &MachineSession::setFeedOverride);
    connect(overrides, &OverrideControls::rapidOverrideChanged, m_session,
            &MachineSession::setRapidOverride);
    connect(overrides, &OverrideControls::spindleOverrideChanged, m_session,
            &MachineSession::setSpindleOverride);
    connect(m_modes, &ModeController::modesChanged, this, [this] {
        if (m_modes->screen() != ScreenMode::Machine) {
            // Programming needs the program, not the machine's positions.
            if (m_workspace->layoutKind() == WorkspaceLayout::PositionsStatus)
                m_workspace->setLayoutKind(WorkspaceLayout::Program);
            return;
        }
        const task::MachineMode mode = m_modes->machineMode();
        // Program run, single block stops after every block; full sequence runs through.
        if (mode == task::MachineMode::SingleBlock) m_session->setSingleBlock(true);
        if (mode == task::MachineMode::FullSequence) m_session->setSingleBlock(false);
        // The machine modes need the positions and the override controls on the screen.
        if (m_workspace->layoutKind() == WorkspaceLayout::Program)
            m_workspace->setLayoutKind(WorkspaceLayout::PositionsStatus);
        refreshSoftkeys();
    });
}

std::vector<SoftkeyRow> MainWindow::machineRows() {
    MachineRowContext context;
    context.session = m_session;
    context.dialogParent = this;
    context.startProgram = [this](std::optional<uint32_t> line) { startEditorProgram(line); };
    context.refresh = [this] { refreshSoftkeys(); };
    return machineModeRows(m_modes->machineMode(), context);
}

void MainWindow::startEditorProgram(std::optional<uint32_t> startLine) {
    if (m_session == nullptr) return;
    if (m_program->path().empty()) {
        m_messages->addMessage(Severity::Error, tr("No program is open: open one in Files"));
        return;
    }
    m_session->startProgram(m_program->editor()->toPlainText(), m_program->path(), startLine);
}

}  // namespace kerf::ui
