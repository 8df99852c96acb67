// MainWindow's part for Program run's graphics: a playback of the program the machine runs that
// follows the machine's status, shown by the graphics panel on the machine screen, and the status
// tabs at the block the machine executes. Kept apart so the window stays a shell.
#include "ui/session/machine_session.h"
#include "ui/shell/main_window.h"
#include "ui/shell/mode_controller.h"
#include "ui/status/machine_functions.h"
#include "ui/status/position_display.h"
#include "ui/status/status_tabs.h"
#include "ui/testrun/test_run_controller.h"
#include "ui/viewport/graphics_panel.h"

namespace kerf::ui {

namespace {

MachineSample sampleOf(const task::MachineStatus& status) {
    MachineSample sample;
    sample.block = status.block;
    for (size_t i = 0; i < kAxisCount; ++i) {
        sample.actual.values[i] = status.axes[i].actual;
        sample.machine.values[i] = status.axes[i].machineActual;
    }
    sample.nominal = {status.axes[0].nominal, status.axes[1].nominal, status.axes[2].nominal};
    // Held, stopped or jogged away the block stays, but the tool is off the path.
    sample.onPath = status.state == task::MachineState::Running;
    sample.feedOverride = status.feedOverride;
    sample.rapidOverride = status.rapidOverride;
    return sample;
}

}  // namespace

void MainWindow::connectLiveRun() {
    m_liveRun = new TestRunController(m_context.machine, m_context.ncRoot, this);
    m_liveRun->setFollowsMachine(true);
    m_liveRun->setMachiningClock(m_context.machiningClock);
    // Prepared from the origin the machine's program runs from; the machine checks its moves.
    m_liveRun->setWorkAreaCheck({}, [this] { return m_session->presetInMachine(); });
    // The session reads the status from motion's snapshot every 20 ms; the playback takes what
    // it needs of it (kFollowIntervalMs).
    connect(m_session, &MachineSession::statusChanged, m_liveRun,
            [this](const task::MachineStatus& status) {
                if (!m_liveRun->following()) return m_positions->setProgrammedFeed(std::nullopt);
                m_liveRun->followMachine(sampleOf(status));
                // The feed of the move the machine executes, also in a cycle and per revolution.
                if (const auto feed = m_liveRun->followedFeed()) {
                    m_positions->setProgrammedFeed(ProgrammedFeed{feed->mm, feed->perRevolution});
                }
            });
    connect(m_session, &MachineSession::runStateChanged, m_liveRun, [this](task::RunState state) {
        if (state == task::RunState::Finished) m_liveRun->endFollowing(true);
        if (state == task::RunState::Failed || state == task::RunState::Aborted)
            m_liveRun->endFollowing(false);
    });
    connect(m_liveRun, &TestRunController::programStatusChanged, this,
            [this](const interp::ProgramStatus& status) {
                // The positions follow the block the machine executes, in its tilted plane.
                m_positions->setWorkingPlane(status.transformations.workingPlane);
                m_machineProgramStatus = status;
                showMachineProgramStatus();
            });
    // The machine screen shows the machine's run, the programming screen the test run.
    auto showPlayback = [this] {
        const bool machine = m_modes->screen() == ScreenMode::Machine;
        m_graphics->showPlayback(machine ? *m_liveRun : *m_testRun);
    };
    connect(m_modes, &ModeController::modesChanged, this, showPlayback);
    showPlayback();
}

void MainWindow::showMachineProgramStatus() {
    if (m_status == nullptr || testRunOnScreen()) return;
    if (m_session == nullptr || m_session->busy()) {
        m_status->setProgramStatus(m_machineProgramStatus);
        return;
    }
    const interp::ProgramStatus shown =
        withMachineSpindleAndCoolant(m_machineProgramStatus, m_session->status());
    // The machine's status comes every 20 ms: the tabs are filled again only when it changes.
    if (shown != m_status->programStatus()) m_status->setProgramStatus(shown);
}

}  // namespace kerf::ui
