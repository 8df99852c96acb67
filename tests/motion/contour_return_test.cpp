#include <cmath>

#include <gtest/gtest.h>

#include "tests/motion/motion_test_run.h"

// Return to the contour: feed hold on a line, jog away, cycle start returns to the interruption
// point one axis at a time (the tool axis Z first when it goes up, last when it goes down) and
// the line goes on from there.
namespace kerf::motion::test {
namespace {

constexpr double kOn = 1e-9;

Pose at(double x, double y, double z) {
    Pose p;
    p[Axis::X] = x;
    p[Axis::Y] = y;
    p[Axis::Z] = z;
    return p;
}

// X0 -> X100 at F600 (10 mm/s): 10 s of path, the hold at X 30 is far from both ends.
std::vector<canon::Command> lineAlongX() {
    canon::Command c;
    c.location.line = 1;
    c.body = canon::LinearMove{at(100, 0, 0), 600.0};
    return {c};
}

// The operator's sequence, one step per phase, driven from the samples.
struct Interruption {
    enum class Phase { Run, Hold, JogY, JogZ, Start, Returning, Done };
    Phase phase = Phase::Run;
    int restCycles = 0;
    AxisVector held{};  // tool tip where the program stopped
    AxisVector awayAt{};
    bool sawReturning = false;
    bool jogEndedInIdle = false;
    double jogY = 5.0;
    double jogZ = 10.0;
    bool quickStopOnReturn = false;
    bool xMovedOffThePoint = false;  // X left the hold point before Y and Z were back
    bool bothMoved = false;          // Y and Z between away and back at the same time
    int firstBack = -1;              // the axis that left its away position first
    double stopY = 0.0;

    void step(SimulatedMachine& sim, const Sample& sample, const MotionStatus& s) {
        const AxisVector& tip = sample.tip;
        if (phase >= Phase::Start) {
            bool yBack = std::fabs(tip[1] - held[1]) <= kOn;
            bool zBack = std::fabs(tip[2] - held[2]) <= kOn;
            bool yAway = std::fabs(tip[1] - awayAt[1]) <= kOn;
            bool zAway = std::fabs(tip[2] - awayAt[2]) <= kOn;
            if (std::fabs(tip[0] - held[0]) > kOn && (!yBack || !zBack)) xMovedOffThePoint = true;
            if (!yBack && !yAway && !zBack && !zAway) bothMoved = true;
            if (firstBack < 0 && !yAway) firstBack = 1;
            if (firstBack < 0 && !zAway) firstBack = 2;
        }
        if (s.mode == MotionMode::Returning) sawReturning = true;
        if ((phase == Phase::JogY || phase == Phase::JogZ) && s.mode == MotionMode::Idle)
            jogEndedInIdle = true;
        // The setpoints settle through the filter: wait a while at rest before the next step.
        restCycles = s.mode == MotionMode::Hold ? restCycles + 1 : 0;
        switch (phase) {
            case Phase::Run:
                if (s.pathPosition >= 30.0) {
                    sim.command({OperatorCommandKind::FeedHold});
                    phase = Phase::Hold;
                }
                break;
            case Phase::Hold:
                if (restCycles < 300) break;
                held = tip;
                sim.command({OperatorCommandKind::JogIncrement, 1, jogY});
                phase = Phase::JogY;
                restCycles = 0;
                break;
            case Phase::JogY:
                if (restCycles < 300) break;
                EXPECT_NEAR(tip[1], held[1] + jogY, kOn);
                sim.command({OperatorCommandKind::JogIncrement, 2, jogZ});
                phase = Phase::JogZ;
                restCycles = 0;
                break;
            case Phase::JogZ:
                if (restCycles < 300) break;
                awayAt = tip;
                EXPECT_NEAR(tip[2], held[2] + jogZ, kOn);
                sim.command({OperatorCommandKind::CycleStart});
                phase = Phase::Start;
                break;
            case Phase::Start:
                if (s.mode == MotionMode::Returning) phase = Phase::Returning;
                break;
            case Phase::Returning:
                if (quickStopOnReturn && tip[1] < held[1] + 4.0) {
                    stopY = tip[1];
                    sim.command({OperatorCommandKind::QuickStop});
                    phase = Phase::Done;
                }
                if (s.mode == MotionMode::Program) phase = Phase::Done;
                break;
            case Phase::Done:
                break;
        }
    }
};

TEST(ContourReturn, JogAwayInAHoldThenCycleStartReturnsAndFinishesTheLine) {
    Interruption op;
    TestRun run = runCommands(millConfig(), lineAlongX(), Pose{}, {},
                              [&](SimulatedMachine& sim, const Sample& sample,
                                  const MotionStatus& s) { op.step(sim, sample, s); });
    ASSERT_EQ(op.phase, Interruption::Phase::Done);
    // Held on the line: X past 30 by at most the braking distance, Y and Z on the line.
    EXPECT_GT(op.held[0], 30.0);
    EXPECT_LT(op.held[0], 31.0);
    EXPECT_NEAR(op.held[1], 0.0, kOn);
    EXPECT_NEAR(op.held[2], 0.0, kOn);
    EXPECT_FALSE(op.jogEndedInIdle);  // each jog ended in the hold again
    EXPECT_TRUE(op.sawReturning);
    EXPECT_FALSE(op.xMovedOffThePoint);
    EXPECT_FALSE(op.bothMoved);  // one axis at a time
    EXPECT_EQ(op.firstBack, 1);  // Y first: the tool axis goes down last
    EXPECT_NEAR(run.report.finalPosition[0], 100.0, 1e-6);
    EXPECT_NEAR(run.report.finalPosition[1], 0.0, 1e-6);
    EXPECT_NEAR(run.report.finalPosition[2], 0.0, 1e-6);
    EXPECT_EQ(run.sim->status().mode, MotionMode::Idle);
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01) << run.checker->limitSummary();
}

TEST(ContourReturn, TheToolAxisGoesUpFirst) {
    Interruption op;
    op.jogZ = -3.0;  // jogged down: the way back goes up, before Y moves
    TestRun run = runCommands(millConfig(), lineAlongX(), Pose{}, {},
                              [&](SimulatedMachine& sim, const Sample& sample,
                                  const MotionStatus& s) { op.step(sim, sample, s); });
    ASSERT_EQ(op.phase, Interruption::Phase::Done);
    EXPECT_FALSE(op.xMovedOffThePoint);
    EXPECT_FALSE(op.bothMoved);
    EXPECT_EQ(op.firstBack, 2);
    EXPECT_NEAR(run.report.finalPosition[0], 100.0, 1e-6);
    EXPECT_NEAR(run.report.finalPosition[1], 0.0, 1e-6);
    EXPECT_NEAR(run.report.finalPosition[2], 0.0, 1e-6);
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01) << run.checker->limitSummary();
}

TEST(ContourReturn, QuickStopDuringTheReturnAbortsWhereTheAxesStand) {
    Interruption op;
    op.quickStopOnReturn = true;
    TestRun run = runCommands(millConfig(), lineAlongX(), Pose{}, {},
                              [&](SimulatedMachine& sim, const Sample& sample,
                                  const MotionStatus& s) { op.step(sim, sample, s); });
    ASSERT_EQ(op.phase, Interruption::Phase::Done);
    EXPECT_EQ(run.sim->status().mode, MotionMode::Idle);
    EXPECT_EQ(run.sim->status().queued, 0u);
    // Braked on Y: from at most 100 mm/s (jog fraction 0.2 of 500 mm/s) with 2000 mm/s^2 and
    // 1e6 mm/s^3 the stop takes v/2 (v/A + A/J) = 2.6 mm, less than the 4 mm left to the point.
    // X stays at the hold point and Z up: the program did not go on.
    EXPECT_LT(run.report.finalPosition[1], op.stopY);
    EXPECT_GT(run.report.finalPosition[1], 0.0);
    EXPECT_NEAR(run.report.finalPosition[0], op.held[0], kOn);
    EXPECT_NEAR(run.report.finalPosition[2], 10.0, kOn);
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01) << run.checker->limitSummary();
}

}  // namespace
}  // namespace kerf::motion::test
