// MainWindow's part for the test run: the graphics panel, its wiring to the editor and the
// message list, and the Test run softkeys. Kept apart from main_window.cpp so the window stays
// a shell.
#include <QCoreApplication>
#include <QEventLoop>
#include <QTimer>

#include "graphics/stock/progressive_stock.h"
#include "ui/editor/program_editor.h"
#include "ui/editor/program_panel.h"
#include "ui/session/program_origin.h"
#include "ui/shell/main_window.h"
#include "ui/shell/message_panel.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/test_run_screen.h"
#include "ui/shell/workspace.h"
#include "ui/status/status_tabs.h"
#include "ui/testrun/test_run_controller.h"
#include "ui/viewport/graphics_panel.h"
#include "ui/viewport/viewport_widget.h"

namespace kerf::ui {

namespace {

constexpr std::array<graphics::View, 4> kMillViews{graphics::View::Iso, graphics::View::Top,
                                                   graphics::View::Front, graphics::View::Side};

TestRunSpeed nextSpeed(TestRunSpeed speed) {
    switch (speed) {
        case TestRunSpeed::Real:
            return TestRunSpeed::Times10;
        case TestRunSpeed::Times10:
            return TestRunSpeed::Times100;
        case TestRunSpeed::Times100:
            return TestRunSpeed::Max;
        case TestRunSpeed::Max:
            break;
    }
    return TestRunSpeed::Real;
}

}  // namespace

bool MainWindow::testRunOnScreen() const {
    return m_modes->screen() == ScreenMode::Programming &&
           m_modes->programmingMode() == task::ProgrammingMode::TestRun;
}

void MainWindow::createGraphics(QWidget* parent) {
    m_testRun = new TestRunController(m_context.machine, m_context.ncRoot, this);
    m_testRun->setMachiningClock(m_context.machiningClock);
    // The work area and the origin of Program run: with a machine the session's, without one
    // the machine file's preset and PRESET.PR.
    auto origin = [this] {
        if (m_session != nullptr) return m_session->nextProgramOrigin();
        return programOrigin(m_context.machine, task::PresetStore(m_context.ncRoot));
    };
    m_testRun->setWorkAreaCheck(m_context.checkMoves, origin);
    // "Check program" judges the moves as Program run would, as `kerf check` does.
    m_program->setWorkAreaCheck(m_context.checkMoves, origin);
    m_graphics = new GraphicsPanel(*m_testRun, m_context.machine, parent);
    connect(m_testRun, &TestRunController::diagnostic, m_messages,
            [this](Severity severity, const QString& text, int line) {
                m_messages->addMessage(severity, text, line);
            });
    connect(m_testRun, &TestRunController::speedChanged, this, [this] {
        if (testRunOnScreen() && m_page == Page::Panels) refreshSoftkeys();
    });
    connect(m_testRun, &TestRunController::programStatusChanged, this,
            [this](const interp::ProgramStatus& status) {
                // The status tabs follow the test run while it is on the screen.
                m_testRunProgramStatus = status;
                if (m_status != nullptr && testRunOnScreen()) m_status->setProgramStatus(status);
            });
    connect(m_graphics, &GraphicsPanel::blockPicked, this,
            [this](int line) { m_program->editor()->goToLine(line); });
    ProgramEditor* editor = m_program->editor();
    connect(editor, &ProgramEditor::cursorPositionChanged, m_graphics, [this, editor] {
        if (m_graphics->isVisible()) m_graphics->highlightLine(editor->currentLine());
    });
    connect(m_modes, &ModeController::modesChanged, this, [this] {
        // The tabs show the run of the screen on view: a test run's last cycle, M functions and
        // parameters are not the machine's (nor the other way round).
        const bool testRunShown = testRunOnScreen();
        if (m_status != nullptr && m_showsTestRunStatus != testRunShown) {
            if (testRunShown)
                m_status->setProgramStatus(m_testRunProgramStatus);
            else
                showMachineProgramStatus();
        }
        m_showsTestRunStatus = testRunShown;
        if (!testRunShown) return;
        // Test run shows the program beside its graphics, also when a machine mode's positions
        // were on the screen before (whichever handler of this signal runs first).
        if (m_workspace->layoutKind() != WorkspaceLayout::ProgramGraphics)
            m_workspace->setLayoutKind(WorkspaceLayout::ProgramGraphics);
        if (m_testRun->state() == TestRunController::State::Empty) prepareTestRun();
    });
    connect(m_program, &ProgramPanel::fileChanged, this, [this] {
        // The test run's toolpath, messages and picked lines belong to the program shown.
        if (testRunOnScreen()) {
            prepareTestRun();
        } else {
            m_testRun->clear();
        }
    });
}

void MainWindow::prepareTestRun() {
    ProgramEditor* editor = m_program->editor();
    if (m_program->path().empty() && editor->document()->isEmpty()) return;
    m_testRun->prepare(editor->toPlainText(), m_program->path(), editor->dialect());
}

void MainWindow::startTestRun() {
    ProgramEditor* editor = m_program->editor();
    if (m_program->path().empty() && editor->document()->isEmpty()) {
        m_messages->addMessage(Severity::Error, tr("No program is open: open one in Files"));
        return;
    }
    m_testRun->start(editor->toPlainText(), m_program->path(), editor->dialect());
}

std::vector<SoftkeyRow> MainWindow::testRunRows() {
    TestRunController* run = m_testRun;
    GraphicsPanel* graphics = m_graphics;
    const bool lathe = m_context.machine.kind == machine::MachineKind::Lathe;
    return {{
        {"testStart", tr("Start"), [this] { startTestRun(); }},
        {"testStop", tr("Stop"), [run] { run->stop(); }},
        {"testReset", tr("Reset"), [run] { run->reset(); }},
        {"testSpeed", tr("Speed\n%1").arg(speedText(run->speed())),
         [run] { run->setSpeed(nextSpeed(run->speed())); }},
        {"testView", tr("View"),
         [graphics, lathe] {
             ViewportWidget* viewport = graphics->viewport();
             if (viewport == nullptr) return;
             if (lathe) return viewport->setView(graphics::View::LatheSection);
             const graphics::View current = graphics->scene().view();
             size_t next = 0;
             for (size_t i = 0; i < kMillViews.size(); ++i) {
                 if (kMillViews[i] == current) next = (i + 1) % kMillViews.size();
             }
             viewport->setView(kMillViews[next]);
         }},
        {"testZoomIn", tr("Zoom\n+"),
         [graphics] {
             if (graphics->viewport() != nullptr) graphics->viewport()->zoomBy(1.25);
         }},
        {"testZoomOut", tr("Zoom\n-"),
         [graphics] {
             if (graphics->viewport() != nullptr) graphics->viewport()->zoomBy(0.8);
         }},
        {"testCheck", tr("Check\nprogram"), [this] { m_program->checkProgram(); }},
    }};
}

bool finishTestRunForPicture(MainWindow& window, int timeoutMs) {
    TestRunController* run = window.testRun();
    GraphicsPanel* graphics = window.graphics();
    // Done when the run has ended, the final stock is in the scene and the view is fitted to it:
    // checked again whenever one of them may have changed, never after a guessed delay.
    auto pictureReady = [run, graphics] {
        using State = TestRunController::State;
        if (run->state() == State::Failed) return true;
        if (run->state() != State::Finished) return false;
        if (graphics->fitPending()) return false;
        if (run->stock() == nullptr || graphics->viewport() == nullptr) return true;
        // The finished stock itself, not the blank or a mesh of halfway still in the scene.
        const auto latest = run->stock()->latest();
        return latest->finished && graphics->viewport()->shownStockSequence() == latest->sequence;
    };
    QEventLoop loop;
    const auto check = [&] {
        if (pictureReady()) loop.quit();
    };
    QObject::connect(run, &TestRunController::stateChanged, &loop, check);
    QObject::connect(graphics, &GraphicsPanel::viewFitted, &loop, check);
    if (graphics->viewport() != nullptr)
        QObject::connect(graphics->viewport(), &ViewportWidget::stockShown, &loop, check);
    QTimer timeout;
    timeout.setSingleShot(true);
    QObject::connect(&timeout, &QTimer::timeout, &loop, [&loop] { loop.exit(1); });
    run->setSpeed(TestRunSpeed::Max);
    window.startTestRun();
    if (pictureReady()) return true;
    timeout.start(timeoutMs);
    return loop.exec() == 0;
}

}  // namespace kerf::ui
