// Issue 13, part 4 for the drive chain: whatever the program or the machine file, a run through
// the CAN chain ends. A simulated-time limit ends a program that runs too long (the axes stop
// first), an axis whose drive cannot resolve its end point does not keep the chain waiting, and
// the CAN trace stops growing at its limit, whole lines only, with a warning.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "app/runner/can_machine.h"
#include "canon_builders.h"
#include "core/machine/machine_loader.h"

namespace kerf::drivers {
namespace {

using kerf::test::command;
using kerf::test::pose;

bool hasCode(const DiagnosticList& list, const std::string& code) {
    for (const Diagnostic& d : list) {
        if (d.code == code) return true;
    }
    return false;
}

TEST(ChainLimits, SimulatedTimeLimitStopsTheAxesAndEndsTheRun) {
    machine::MachineConfig mill = machine::loadMachine("mill").value();
    CanSimOptions options;
    options.maxSimulatedS = 2.0;
    auto machine = app::CanMachine::create(mill, options, pose(0, 0, 0).values);
    ASSERT_TRUE(machine.ok()) << machine.error().message();
    // 300 mm at 60 mm/min: 300 s.
    (*machine)->consume(command(canon::LinearMove{pose(300.0, 0.0, 0.0), 60.0}, 1));
    app::CanRunResult r = (*machine)->finish();
    EXPECT_TRUE(r.timeLimit);
    EXPECT_TRUE(hasCode(r.diagnostics, "drives.time-limit"));
    // 2 s at 1 mm/s, then a stop along the path that takes a few ms at that speed.
    EXPECT_GE(r.durationS, 2.0);
    EXPECT_LT(r.durationS, 2.5);
    EXPECT_NEAR(r.finalPosition[0], 2.0, 0.1);
    // Stopped: what is left is the position loop (gain 150/s) correcting less than 2 counts.
    for (size_t i = 0; i < (*machine)->drives().driveCount(); ++i)
        EXPECT_LT(std::fabs((*machine)->drives().drive(i).plant().velocity()), 300.0) << i;
    EXPECT_TRUE((*machine)->stopped());
}

// drive_scale = 0.001 counts/mm: one count is a metre, the drive cannot go 10 mm and the feedback
// never shows the axis at its end point. The chain used to wait for that for a simulated day;
// now the in-position timeout (1 s after motion ended) says so.
TEST(ChainLimits, AxisThatCannotReachItsEndPointEndsTheRunWithAnError) {
    machine::MachineConfig mill = machine::loadMachine("mill").value();
    for (machine::AxisConfig& axis : mill.axes)
        axis.driveCountsPerUnit = 0.001;
    CanSimOptions options;
    options.maxSimulatedS = 60.0;
    auto machine = app::CanMachine::create(mill, options, pose(0, 0, 0).values);
    ASSERT_TRUE(machine.ok()) << machine.error().message();
    (*machine)->consume(command(canon::RapidMove{pose(10.0, 5.0, 2.0)}, 1));
    (*machine)->consume(command(canon::LinearMove{pose(30.0, 5.0, 2.0), 1000.0}, 2));
    app::CanRunResult r = (*machine)->finish();
    EXPECT_LT(r.durationS, 5.0) << "simulated seconds";
    EXPECT_FALSE(r.timeLimit);
    EXPECT_TRUE((*machine)->stopped());
    ASSERT_TRUE(hasCode(r.diagnostics, "drives.in-position"));
    for (const Diagnostic& d : r.diagnostics) {
        if (d.code != "drives.in-position") continue;
        EXPECT_EQ(d.severity, Severity::Error);
        EXPECT_EQ(d.message(),
                  "axis X did not reach its end point: 30.0000 away 1.0 s after "
                  "motion ended")
            << d.message();
    }
}

TEST(ChainLimits, TraceStopsAtItsLimitWithAWarning) {
    machine::MachineConfig mill = machine::loadMachine("mill").value();
    const std::filesystem::path trace =
        std::filesystem::path(testing::TempDir()) / "kerf_chain_trace_limit.log";
    CanSimOptions options;
    options.tracePath = trace;
    options.traceLimitBytes = 10000;
    auto machine = app::CanMachine::create(mill, options, pose(0, 0, 0).values);
    ASSERT_TRUE(machine.ok()) << machine.error().message();
    (*machine)->consume(command(canon::RapidMove{pose(50.0, 0.0, 0.0)}, 1));
    app::CanRunResult r = (*machine)->finish();
    ASSERT_TRUE(hasCode(r.diagnostics, "drives.trace-limit"));
    for (const Diagnostic& d : r.diagnostics) {
        if (d.code == "drives.trace-limit") {
            EXPECT_EQ(d.severity, Severity::Warning);
            EXPECT_NE(d.message().find("10000 bytes"), std::string::npos) << d.message();
        }
    }
    auto size = std::filesystem::file_size(trace);
    EXPECT_LE(size, 10000u);
    EXPECT_GT(size, 10000u - 64u) << "filled up to the last whole line";
    std::ifstream in(trace, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_FALSE(text.empty());
    EXPECT_EQ(text.back(), '\n');
    std::filesystem::remove(trace);
}

}  // namespace
}  // namespace kerf::drivers
