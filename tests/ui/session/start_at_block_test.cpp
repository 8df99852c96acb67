#include <QInputDialog>
#include <QTimer>
#include <chrono>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "simulated_machine.h"
#include "test_paths.h"
#include "ui/shell/main_window.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/softkey_bar.h"

namespace kerf::ui {
namespace {

using namespace std::chrono_literals;

// Start at block asks for the block number: block 3 is on line 5 (block 1 takes two lines).
// Block 2 stops the program (M0); started at block 3 the program runs to its end, started at
// line 3 (the old meaning of the number) it would begin with block 2 and stop there.
TEST(StartAtBlock, TakesTheBlockNumberNotTheLine) {
    test::testApp();
    const std::filesystem::path dir = kerf::test::uniqueTempDir("hmi_start_at_block");
    std::ofstream(dir / "S.H") << "0 BEGIN PGM S MM\n"
                                  "1 L X+0 Y+0 Z+10 R0 ~\n"
                                  "  FMAX\n"
                                  "2 L X+10 FMAX M0\n"
                                  "3 L X+20 FMAX\n"
                                  "4 L X+30 FMAX\n"
                                  "5 END PGM S MM\n";
    HmiContext context;
    context.machine = *machine::loadMachine("mill");
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    context.motion = [config = context.machine] { return test::connectSimulatedMachine(config); };
    MainWindow window(std::move(context));
    ASSERT_TRUE(window.openProgram(dir / "S.H"));
    ASSERT_TRUE(window.modes().requestMachineMode(task::MachineMode::FullSequence));
    auto* timer = new QTimer(&window);
    QObject::connect(timer, &QTimer::timeout, timer, [&window, timer] {
        auto* dialog = window.findChild<QInputDialog*>(QStringLiteral("blockPrompt"));
        if (dialog == nullptr || !dialog->isVisible()) return;
        timer->stop();
        dialog->setIntValue(3);
        dialog->accept();
    });
    timer->start(5);
    ASSERT_TRUE(window.softkeys()->pressId("startAtBlock"));
    const auto deadline = std::chrono::steady_clock::now() + 10s;
    while (window.session()->runState() != task::RunState::Finished &&
           window.session()->runState() != task::RunState::Stopped &&
           window.session()->runState() != task::RunState::Failed &&
           std::chrono::steady_clock::now() < deadline) {
        QCoreApplication::processEvents();
        std::this_thread::sleep_for(5ms);
    }
    EXPECT_EQ(window.session()->runState(), task::RunState::Finished);
}

}  // namespace
}  // namespace kerf::ui
