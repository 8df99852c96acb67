// MainWindow's part for the machine: the session, the position display and the machine-mode
// softkeys. Kept apart from main_window.cpp so the window stays a shell.
#include <QCoreApplication>
#include <QShortcut>

#include "core/interp/fagor/operator_inputs.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_panel.h"
#include "ui/session/machine_session.h"
#include "ui/shell/block_prompt.h"
#include "ui/shell/executing_block_follower.h"
#include "ui/shell/machine_keys.h"
#include "ui/shell/machine_rows.h"
#include "ui/shell/main_window.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/operator_input_dialog.h"
#include "ui/shell/workspace.h"
#include "ui/status/override_controls.h"
#include "ui/status/position_display.h"
#include "ui/status/status_tabs.h"
#include "ui/testrun/test_run_controller.h"
#include "ui/userscreen/user_screen_run.h"

namespace kerf::ui {

namespace {

// A program run shows the program, the positions and the status; manual operation and MDI the
// positions with the override controls beside the status.
WorkspaceLayout machineModeLayout(task::MachineMode mode) {
    const bool programRun =
        mode == task::MachineMode::SingleBlock || mode == task::MachineMode::FullSequence;
    return programRun ? WorkspaceLayout::ProgramStatus : WorkspaceLayout::PositionsStatus;
}

}  // namespace

void MainWindow::connectSession() {
    if (m_context.programmingStation || !m_context.motion) return;
    m_session = new MachineSession(m_context.machine, m_context.motion(), m_context.ncRoot, this);
    m_modes->setMovingQuery([this] { return m_session->busy(); });
    connect(m_session, &MachineSession::statusChanged, m_positions, &PositionDisplay::setStatus);
    connect(m_session, &MachineSession::basicRotationChanged, m_positions,
            &PositionDisplay::setBasicRotation);
    m_positions->setBasicRotation(m_session->basicRotationDeg());
    // The machine's state from the start, not only after the first service (a screenshot may come
    // first).
    m_positions->setStatus(m_session->status());
    connect(m_session, &MachineSession::runStateChanged, this, [this](task::RunState state) {
        m_positions->setRunState(QCoreApplication::translate("kerf", task::runStateName(state)));
    });
    connect(m_session, &MachineSession::message, m_messages,
            [this](Severity severity, const QString& text, int line, MessageCause cause) {
                m_messages->addMessage(severity, text, line, cause);
            });
    // A message whose cause is gone (the axes referenced, the machine switched on ...) leaves
    // the message line.
    connect(m_session, &MachineSession::statusChanged, m_messages, [this] {
        m_messages->resolve([this](MessageCause cause) { return m_session->causeHolds(cause); });
    });
    connect(m_session, &MachineSession::programStatusChanged, m_status,
            [this](const interp::ProgramStatus& status) {
                // A program's status comes from the block the machine executes (connectLiveRun);
                // the interpreter's own is read ahead. An MDI block is the one executed.
                if (!m_session->runningProgramName().empty()) return;
                m_positions->setWorkingPlane(status.transformations.workingPlane);
                m_machineProgramStatus = status;
                showMachineProgramStatus();
            });
    // The spindle and coolant keys (and a Stop) change the machine's M functions; while a program
    // moves the machine its blocks do (and set the tabs themselves).
    connect(m_session, &MachineSession::statusChanged, this, [this] {
        if (!m_session->busy()) showMachineProgramStatus();
    });
    connect(m_session, &MachineSession::manualProbingChanged, m_status, [this] {
        m_status->setManualProbing(m_session->manualProbingFunction(),
                                   m_session->manualTouchesDone(),
                                   m_session->manualProbingResult());
    });
    connect(m_session, &MachineSession::toolLengthTouchedOff, m_status,
            &StatusTabs::setToolTouchOff);
    connectLiveRun();
    OverrideControls* overrides = m_positions->overrides();
    connect(overrides, &OverrideControls::feedOverrideChanged, m_session,
            &MachineSession::setFeedOverride);
    connect(overrides, &OverrideControls::rapidOverrideChanged, m_session,
            &MachineSession::setRapidOverride);
    connect(overrides, &OverrideControls::spindleOverrideChanged, m_session,
            &MachineSession::setSpindleOverride);
    new ExecutingBlockFollower(*m_session, *m_program, this);
    connect(m_machineKeys, &MachineKeys::emergencyStopPressed, m_session,
            &MachineSession::emergencyStop);
    connect(m_machineKeys, &MachineKeys::emergencyStopReleased, m_session,
            &MachineSession::releaseEmergencyStop);
    connect(m_session, &MachineSession::statusChanged, m_machineKeys,
            [this] { m_machineKeys->setEmergencyStopPressed(m_session->emergencyStopPressed()); });
    connect(m_machineKeys, &MachineKeys::machineOnPressed, m_session, &MachineSession::machineOn);
    // The keyboard's Pause key is an emergency stop too, whatever has the focus.
    auto* emergencyKey = new QShortcut(QKeySequence(Qt::Key_Pause), this);
    emergencyKey->setContext(Qt::ApplicationShortcut);
    connect(emergencyKey, &QShortcut::activated, m_session, &MachineSession::emergencyStop);
    // The layout follows a change of mode; the operator's choice stands until the next one.
    connect(m_modes, &ModeController::modesChanged, this,
            [this, shown = std::optional<task::MachineMode>()]() mutable {
                if (m_modes->screen() != ScreenMode::Machine) {
                    shown.reset();
                    // Programming needs the program alone, not the machine's positions.
                    const WorkspaceLayout layout = m_workspace->layoutKind();
                    if (layout == WorkspaceLayout::PositionsStatus ||
                        layout == WorkspaceLayout::ProgramStatus)
                        m_workspace->setLayoutKind(WorkspaceLayout::Program);
                    return;
                }
                const task::MachineMode mode = m_modes->machineMode();
                // Program run, single block stops after every block; full sequence runs through.
                if (mode == task::MachineMode::SingleBlock) m_session->setSingleBlock(true);
                if (mode == task::MachineMode::FullSequence) m_session->setSingleBlock(false);
                if (shown != mode) {
                    const auto chosen = m_machineModeLayouts.find(mode);
                    m_workspace->setLayoutKind(chosen != m_machineModeLayouts.end()
                                                   ? chosen->second
                                                   : machineModeLayout(mode));
                }
                shown = mode;
                refreshSoftkeys();
            });
}

std::vector<SoftkeyRow> MainWindow::machineRows() {
    MachineRowContext context;
    context.session = m_session;
    context.dialogParent = this;
    context.startProgram = [this](std::optional<uint32_t> line) { startEditorProgram(line); };
    context.askStartBlock = [this] {
        return askForBlockLine(this, tr("Start at block"), *m_program->editor(), *m_messages);
    };
    // New labels, same row: the operator stays where the key was pressed.
    context.refresh = [this] {
        const int row = m_softkeys->currentRow();
        refreshSoftkeys();
        if (row < m_softkeys->rowCount()) m_softkeys->showRow(row);
    };
    return machineModeRows(m_modes->machineMode(), context);
}

void MainWindow::startEditorProgram(std::optional<uint32_t> startLine) {
    if (m_session == nullptr) return;
    if (m_program->path().empty()) {
        m_messages->addMessage(Severity::Error, tr("No program is open: open one in Files"));
        return;
    }
    ProgramEditor* editor = m_program->editor();
    std::vector<std::pair<int, double>> inputs;
    if (editor->dialect() == program::Dialect::Fagor && !askOperatorInputs(inputs)) return;
    if (!m_session->startProgram(editor->toPlainText(), m_program->path(), startLine, inputs))
        return;
    m_liveRun->follow(editor->toPlainText(), m_program->path(), editor->dialect(),
                      m_session->programStart());
    // The tabs follow the machine's block once the program is prepared (seconds for a long
    // one); until then they must not show the program run before.
    if (m_liveRun->state() == TestRunController::State::Interpreting && !testRunOnScreen())
        m_status->setPreparing(QString::fromStdString(m_program->path().filename().string()));
}

bool MainWindow::askOperatorInputs(std::vector<std::pair<int, double>>& inputs) {
    // The IBn a program reads are the operator's: asked before the run, filled with the values
    // the user screen's last inputs left (docs/fagor.md, "Operator inputs").
    const std::vector<int> read =
        fagor::operatorInputsRead(m_program->editor()->toPlainText().toStdString());
    if (read.empty()) return true;
    std::vector<std::pair<int, double>> current;
    const fagor::UserScreen* screen = m_userScreenRun ? m_userScreenRun->screen() : nullptr;
    for (int n : read)
        current.emplace_back(n, screen ? screen->input(n) : 0.0);
    OperatorInputDialog dialog(current, this);
    if (dialog.exec() != QDialog::Accepted) return false;
    inputs = dialog.values();
    return true;
}

}  // namespace kerf::ui
