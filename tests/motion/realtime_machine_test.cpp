#include "motion/runtime/realtime_machine.h"

#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "tests/motion/motion_test_run.h"

namespace kerf::motion::test {
namespace {

canon::Command line(double x, double y) {
    canon::Command c;
    Pose p;
    p[Axis::X] = x;
    p[Axis::Y] = y;
    c.body = canon::LinearMove{p, 6000.0};
    return c;
}

// Runs in real time (a few hundred milliseconds); asserts the outcome, not deadlines: this
// machine has no real-time kernel (shared/anchors/FIGURES.md).
TEST(RealtimeMachine, RunsAProgramInItsOwnThread) {
    RealtimeMachine machine(millConfig(), {});
    ASSERT_TRUE(machine.start());
    RealtimeReport report = machine.report();
    EXPECT_TRUE(report.running);
    if (!report.realtimePriority) std::printf("note: %s\n", report.note.c_str());
    for (canon::Command c : {line(10, 0), line(10, 5), line(0, 5), line(0, 0)}) {
        ASSERT_TRUE(machine.submit(c));
    }
    machine.flush();
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (!machine.drained() && std::chrono::steady_clock::now() < deadline) {
        machine.pump();
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ASSERT_TRUE(machine.drained());
    std::this_thread::sleep_for(std::chrono::milliseconds(100));  // filter and drives settle
    MotionStatus status = machine.status();
    EXPECT_NEAR(status.commandedPosition[0], 0.0, 1e-9);
    EXPECT_NEAR(status.commandedPosition[1], 0.0, 1e-9);
    EXPECT_GT(status.cycle, 100u);
    std::printf("cycles %llu late %llu worst cycle %.1f us\n",
                static_cast<unsigned long long>(status.cycle),
                static_cast<unsigned long long>(status.lateCycles), status.maxCycleCpuS * 1e6);
    machine.stop();
}

}  // namespace
}  // namespace kerf::motion::test
