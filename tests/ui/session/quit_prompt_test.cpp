#include <QStringList>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "session_service.h"
#include "simulated_machine.h"
#include "test_paths.h"
#include "ui/shell/main_window.h"

namespace kerf::ui {
namespace {

// Quitting with the spindle turning asks first; "no" keeps the window and the spindle, "yes"
// stops the machine and quits.
TEST(QuitPrompt, QuittingWithTheSpindleTurningAsksFirst) {
    test::testApp();
    const std::filesystem::path dir = kerf::test::uniqueTempDir("hmi_quit_spindle");
    HmiContext context;
    context.machine = *machine::loadMachine("mill");
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    context.motion = [config = context.machine] { return test::connectSimulatedMachine(config); };
    MainWindow window(std::move(context));
    QStringList asked;
    bool answer = false;
    MainWindow::Prompts prompts;
    prompts.confirm = [&](const QString& question) {
        asked << question;
        return answer;
    };
    window.setPrompts(prompts);
    window.show();
    MachineSession& session = *window.session();
    ASSERT_TRUE(session.spindle(true));
    ASSERT_TRUE(test::serviceUntil(
        session, [&] { return session.status().actualSpindleRpm > 500; },
        std::chrono::seconds(10)));
    EXPECT_FALSE(window.close());
    ASSERT_EQ(asked.size(), 1);
    EXPECT_TRUE(asked.front().contains(QStringLiteral("spindle")));
    EXPECT_TRUE(window.isVisible());
    EXPECT_GT(session.status().programmedSpindleRpm, 500.0);
    answer = true;
    EXPECT_TRUE(window.close());
    EXPECT_EQ(asked.size(), 2);
}

TEST(QuitPrompt, QuittingAnIdleMachineAsksNothing) {
    test::testApp();
    const std::filesystem::path dir = kerf::test::uniqueTempDir("hmi_quit_idle");
    HmiContext context;
    context.machine = *machine::loadMachine("mill");
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    context.motion = [config = context.machine] { return test::connectSimulatedMachine(config); };
    MainWindow window(std::move(context));
    int asked = 0;
    MainWindow::Prompts prompts;
    prompts.confirm = [&](const QString&) {
        ++asked;
        return false;
    };
    window.setPrompts(prompts);
    window.show();
    EXPECT_TRUE(window.close());
    EXPECT_EQ(asked, 0);
}

}  // namespace
}  // namespace kerf::ui
