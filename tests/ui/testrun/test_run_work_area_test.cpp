#include <QSignalSpy>
#include <cmath>

#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "motion/runtime/work_area_check.h"
#include "motion/sim/simulated_clock.h"
#include "qt_test_app.h"
#include "test_paths.h"
#include "ui/testrun/test_run_controller.h"

namespace kerf::ui {
namespace {

// The built-in mill: X soft limits -400 .. +400, Z -500 .. +50 (machine coordinates), the
// workpiece origin at machine Z-400. Block 2 goes to X+450: machine X+450 from an origin at
// machine X0, beyond the limit +400; from an origin at machine X-100 it is X+350, inside.
const char* kLeavesX =
    "0 BEGIN PGM LIMIT MM\n"
    "1 L X+0 Y+0 Z+100 R0 FMAX\n"
    "2 L X+450 R0 FMAX\n"
    "3 L X+0 R0 FMAX\n"
    "4 END PGM LIMIT MM\n";

struct Fixture {
    std::filesystem::path root = kerf::test::uniqueTempDir("testrun_work_area");
    machine::MachineConfig machine = *machine::loadMachine("mill");
    TestRunController controller{machine, root};
    Pose origin;  // where Program run would put the workpiece origin now

    Fixture() {
        test::testApp();
        origin[Axis::Z] = -400.0;
        controller.setTickMs(0);
        controller.setSpeed(TestRunSpeed::Max);
        controller.setMachiningClock(motion::makeSimulatedClock);
        controller.setWorkAreaCheck(
            [config = machine](const Pose& at) { return motion::makeWorkAreaCheck(config, at); },
            [this] { return origin; });
    }
    void start(const char* text) {
        QSignalSpy ready(&controller, &TestRunController::programReady);
        controller.start(QString::fromUtf8(text), root / "LIMIT.H", program::Dialect::Klartext);
        ASSERT_TRUE(ready.wait(20000));
    }
};

TEST(TestRunWorkArea, AMoveBeyondASoftLimitEndsTheRunAtItsBlockNamingIt) {
    Fixture f;
    QSignalSpy diagnostics(&f.controller, &TestRunController::diagnostic);
    f.start(kLeavesX);
    // The run plays up to the refused block and fails there, as Program run would stop.
    EXPECT_EQ(f.controller.state(), TestRunController::State::Failed);
    const Vec3 tool = f.controller.toolPosition();
    EXPECT_DOUBLE_EQ(tool.x(), 0.0);
    EXPECT_DOUBLE_EQ(tool.z(), 100.0);
    // Only block 1 is played: 100 mm in rapid, on the simulated machine. At 2000 mm/s^2 at most
    // it cannot take less than 2 sqrt(100 / 2000) = 0.447 s (it never reaches the 500 mm/s).
    EXPECT_GT(f.controller.machiningTimeS(), 2.0 * std::sqrt(100.0 / 2000.0));
    EXPECT_LT(f.controller.machiningTimeS(), 1.0);
    bool named = false;
    for (const QList<QVariant>& d : diagnostics) {
        const QString text = d.at(1).toString();
        if (d.at(0).value<Severity>() == Severity::Error && d.at(2).toInt() == 3 &&
            text.contains(QStringLiteral("Block 2")) && text.contains(QStringLiteral("axis X")) &&
            text.contains(QStringLiteral("soft limit")))
            named = true;
    }
    EXPECT_TRUE(named) << diagnostics.count() << " diagnostics";
}

TEST(TestRunWorkArea, TheOriginOfProgramRunDecidesAndAMovedOriginIsCheckedAtTheNextStart) {
    Fixture f;
    f.origin[Axis::X] = -100.0;
    f.start(kLeavesX);
    EXPECT_EQ(f.controller.state(), TestRunController::State::Finished);
    // The operator sets the preset back to machine X0: the same text is checked again.
    f.origin[Axis::X] = 0.0;
    f.start(kLeavesX);
    EXPECT_EQ(f.controller.state(), TestRunController::State::Failed);
}

TEST(TestRunWorkArea, TheToolLengthCountsOnTheToolAxis) {
    // Z+440 without a tool: machine Z+40, inside (+50). With TOOL.T's tool 1 (L 80) machine
    // Z+120: beyond the limit, so the block after the TOOL CALL fails.
    Fixture f;
    std::filesystem::copy_file(
        std::filesystem::path(KERF_SOURCE_DIR) / "tests/graphics/programs/TOOL.T",
        f.root / "TOOL.T");
    f.start("0 BEGIN PGM LIMIT MM\n1 L Z+440 R0 FMAX\n2 END PGM LIMIT MM\n");
    EXPECT_EQ(f.controller.state(), TestRunController::State::Finished);
    QSignalSpy diagnostics(&f.controller, &TestRunController::diagnostic);
    f.start(
        "0 BEGIN PGM LIMIT MM\n1 TOOL CALL 1 Z S1000\n2 L Z+440 R0 FMAX\n"
        "3 END PGM LIMIT MM\n");
    EXPECT_EQ(f.controller.state(), TestRunController::State::Failed);
    bool block2 = false;
    for (const QList<QVariant>& d : diagnostics)
        block2 = block2 || d.at(1).toString().contains(QStringLiteral("Block 2"));
    EXPECT_TRUE(block2);
}

}  // namespace
}  // namespace kerf::ui
