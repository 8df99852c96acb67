// Tool calibration on the lathe panel (docs/hmi.md, "Tool calibration"): in manual mode the
// operator touches the part and enters the diameter or face position; the panel writes the
// offset's length to fagor_tool_offsets.tab. Values by hand from where the tool stands.
#include <QApplication>
#include <QInputDialog>
#include <QTimer>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "core/interp/fagor/tables/tool_offset_table.h"
#include "core/machine/machine_loader.h"
#include "qt_test_app.h"
#include "simulated_machine.h"
#include "test_paths.h"
#include "ui/session/machine_session.h"
#include "ui/shell/main_window.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/softkey_bar.h"

namespace kerf::ui {
namespace {

using namespace std::chrono_literals;

bool processUntil(const std::function<bool()>& done, std::chrono::milliseconds limit = 10s) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
        QCoreApplication::processEvents();
        if (done()) return true;
        std::this_thread::sleep_for(2ms);
    }
    return false;
}

// Answers the three dialogs: the offset D (checking the one offered), the axis, the value.
void answerCalibration(int offeredOffset, int offset, const QString& axis, double value,
                       bool& answered) {
    QTimer::singleShot(0, [=, &answered] {
        auto* d = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
        ASSERT_NE(d, nullptr);
        EXPECT_EQ(d->objectName(), QStringLiteral("touchOffOffsetPrompt"));
        EXPECT_EQ(d->intValue(), offeredOffset);
        d->setIntValue(offset);
        QTimer::singleShot(0, [=, &answered] {
            auto* a = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
            ASSERT_NE(a, nullptr);
            EXPECT_EQ(a->objectName(), QStringLiteral("touchOffAxisPrompt"));
            a->setTextValue(axis);
            QTimer::singleShot(0, [=, &answered] {
                auto* v = qobject_cast<QInputDialog*>(QApplication::activeModalWidget());
                ASSERT_NE(v, nullptr);
                EXPECT_EQ(v->objectName(), QStringLiteral("touchOffValuePrompt"));
                // X is shown, and asked for, as a diameter; Z as a position.
                EXPECT_EQ(v->labelText().startsWith(QStringLiteral("Diameter X")), axis == "X");
                v->setDoubleValue(value);
                answered = true;
                v->accept();
            });
            a->accept();
        });
        d->accept();
    });
}

fagor::ToolOffsetTable offsets(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    auto table = fagor::ToolOffsetTable::parse(bytes.str(), "t.tab");
    EXPECT_TRUE(table.ok());
    return table.ok() ? *table : fagor::ToolOffsetTable::createDefault();
}

TEST(ToolCalibrationScreen, TouchingThePartWritesTheOffsetLengths) {
    test::testApp();
    const std::filesystem::path dir = kerf::test::uniqueTempDir("hmi_tool_calibration");
    HmiContext context;
    context.machine = *machine::loadMachine("lathe");
    context.machine.referenceRequired = false;
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    context.motion = [config = context.machine] { return test::connectSimulatedMachine(config); };
    std::ofstream(dir / "fagor_tool_offsets.tab") << "D1 X10 Z20 I0.2 F3 R0.4\n";
    std::ofstream(dir / "P000001.PIM") << "T1 D1\nG90 G00 X50 Z10\nM30\n";
    MainWindow window(std::move(context));
    window.resize(1280, 800);
    window.show();
    MachineSession* session = window.session();
    // A program leaves offset D1 active with the tip at X50 (r25) Z10.
    ASSERT_TRUE(window.openProgram(dir / "P000001.PIM"));
    ASSERT_TRUE(window.modes().requestMachineMode(task::MachineMode::FullSequence));
    ASSERT_TRUE(window.softkeys()->pressId("ncStart"));
    ASSERT_TRUE(processUntil([&] { return session->runState() == task::RunState::Finished; }));
    ASSERT_TRUE(session->activeLatheOffset());
    EXPECT_EQ(session->activeLatheOffset()->number, 1);
    // The operator touches off with the axes at rest: the run may end while the simulated drives
    // still settle the last micrometres of following error.
    auto at = [&](Axis axis, double mm) {
        return std::abs(session->status().axes[static_cast<size_t>(axisIndex(axis))].actual - mm) <
               1e-5;
    };
    ASSERT_TRUE(processUntil([&] { return at(Axis::X, 25.0) && at(Axis::Z, 10.0); }));

    ASSERT_TRUE(window.modes().requestMachineMode(task::MachineMode::Manual));
    SoftkeyBar& bar = *window.softkeys();
    // The part measures D52 where the tip shows D50: D1's X (10, wear I 0.2 kept) grows by the
    // radius difference, 10 + (26 - 25) = 11.
    bool answered = false;
    answerCalibration(1, 1, QStringLiteral("X"), 52.0, answered);
    ASSERT_TRUE(bar.pressId("toolCalibration"));
    ASSERT_TRUE(answered);
    fagor::ToolOffset d1 = offsets(dir / "fagor_tool_offsets.tab").get(1);
    EXPECT_NEAR(d1.x, 11.0, 1e-3);
    EXPECT_DOUBLE_EQ(d1.z, 20.0);
    EXPECT_DOUBLE_EQ(d1.wearX, 0.2);
    EXPECT_DOUBLE_EQ(d1.radius, 0.4);
    // D2, not the active tool, touches the face Z0 where the tip (with D1's Z 20) shows Z10:
    // the holder stands at 10 - 20 = -10, so D2's Z is 0 - (-10) = 10.
    answered = false;
    answerCalibration(1, 2, QStringLiteral("Z"), 0.0, answered);
    ASSERT_TRUE(bar.pressId("toolCalibration"));
    ASSERT_TRUE(answered);
    const fagor::ToolOffsetTable after = offsets(dir / "fagor_tool_offsets.tab");
    EXPECT_NEAR(after.get(2).z, 10.0, 1e-3);
    EXPECT_DOUBLE_EQ(after.get(2).x, 0.0);
    EXPECT_NEAR(after.get(1).x, 11.0, 1e-3);
}

TEST(ToolCalibrationScreen, TheMillHasNoToolCalibrationKey) {
    test::testApp();
    const std::filesystem::path dir = kerf::test::uniqueTempDir("hmi_tool_calibration_mill");
    HmiContext context;
    context.machine = *machine::loadMachine("mill");
    context.machine.referenceRequired = false;
    context.ncRoot = dir;
    context.recoveryFolder = dir / "recovery";
    context.motion = [config = context.machine] { return test::connectSimulatedMachine(config); };
    MainWindow window(std::move(context));
    window.show();
    ASSERT_TRUE(window.modes().requestMachineMode(task::MachineMode::Manual));
    EXPECT_FALSE(window.softkeys()->pressId("toolCalibration"));
}

}  // namespace
}  // namespace kerf::ui
