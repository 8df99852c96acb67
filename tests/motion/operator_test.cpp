#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "core/geometry/arc_math.h"
#include "core/machine/machine_loader.h"
#include "motion/kinematics/machine_model.h"
#include "motion/planner/soft_limits.h"
#include "motion/profile/jerk_profile.h"
#include "tests/motion/motion_test_run.h"

namespace kerf::motion::test {
namespace {

Pose at(double x, double y, double z) {
    Pose p;
    p[Axis::X] = x;
    p[Axis::Y] = y;
    p[Axis::Z] = z;
    return p;
}

canon::Command cmd(canon::CommandBody body, uint32_t line = 1) {
    canon::Command c;
    c.location.line = line;
    c.location.blockNumber = line * 10;
    c.body = std::move(body);
    return c;
}

// A 200 mm line along X at 3000 mm/min (50 mm/s).
std::vector<canon::Command> longLine() {
    return {cmd(canon::LinearMove{at(200, 0, 0), 3000.0})};
}

TEST(FeedHold, StopsWithinTheBrakingDistanceAndResumesOnThePath) {
    // On a straight line the tangential limits are the top share (planner rule): 98 % of the
    // axis acceleration, 90 % of its jerk: A = 1960 mm/s^2, J = 900000 mm/s^3. From v at a = 0
    // the time-optimal stop is symmetric and covers v/2 times its duration: with
    // v = 50 > A^2/J = 4.27 mm/s the deceleration reaches A, so the duration is
    // v/A + A/J = 0.027688 s and the distance v/2 (v/A + A/J) = 0.692200 mm (without a constant
    // phase it would be v sqrt(v/J)).
    const double a = 0.98 * 2000.0;
    const double j = 0.9 * 1000000.0;
    const double v = 50.0;
    ASSERT_GT(v, a * a / j);
    const double expected = v / 2.0 * (v / a + a / j);
    EXPECT_NEAR(expected, 0.692200, 1e-6);
    double holdAt = -1.0;
    double stoppedAt = -1.0;
    int cycles = 0;
    TestRun run =
        runCommands(millConfig(), longLine(), Pose{}, {},
                    [&](SimulatedMachine& sim, const Sample&, const MotionStatus& s) {
                        ++cycles;
                        if (cycles == 2000) {
                            ASSERT_NEAR(s.pathVelocity, v, 1e-9);
                            holdAt = s.pathPosition;
                            sim.command({OperatorCommandKind::FeedHold});
                        }
                        if (holdAt >= 0.0 && stoppedAt < 0.0 && s.mode == MotionMode::Hold) {
                            stoppedAt = s.pathPosition;
                        }
                        if (cycles == 2600) sim.command({OperatorCommandKind::CycleStart});
                    });
    ASSERT_GE(stoppedAt, 0.0);
    // The command is read at the start of the next cycle: one period of travel at v more.
    EXPECT_LE(stoppedAt - holdAt, expected + v * 0.001 + 1e-9);
    EXPECT_GE(stoppedAt - holdAt, expected - 1e-6);
    EXPECT_NEAR(run.report.finalPosition[0], 200.0, 1e-6);
    EXPECT_LE(run.checker->maxDeviation(), 1e-9);
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
}

TEST(QuickStop, StopsOnThePathAndAbortsTheProgram) {
    int cycles = 0;
    TestRun run = runCommands(millConfig(), longLine(), Pose{}, {},
                              [&](SimulatedMachine& sim, const Sample&, const MotionStatus&) {
                                  if (++cycles == 1500)
                                      sim.command({OperatorCommandKind::QuickStop});
                              });
    EXPECT_EQ(run.sim->status().mode, MotionMode::Idle);
    EXPECT_LT(run.report.finalPosition[0], 200.0);
    EXPECT_GT(run.report.finalPosition[0], 50.0);
    EXPECT_NEAR(run.report.finalPosition[1], 0.0, 1e-9);
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
}

// Spindle at 1000 rpm and flood coolant, then two 10 mm blocks along X, in single block: the
// program waits at X10 for cycle start.
std::vector<canon::Command> spindleCoolantTwoBlocks() {
    canon::SpindleControl spindle;
    spindle.direction = canon::SpindleDirection::Clockwise;
    spindle.speedRpm = 1000.0;
    canon::CoolantControl flood;
    flood.flood = true;
    return {cmd(spindle, 1), cmd(flood, 2), cmd(canon::LinearMove{at(10, 0, 0), 3000.0}, 3),
            cmd(canon::LinearMove{at(20, 0, 0), 3000.0}, 4)};
}

TEST(QuickStop, AtASingleBlockStopAbortsAndTurnsSpindleAndCoolantOff) {
    SimulationOptions options;
    options.autoCycleStart = false;
    options.maxSimulatedS = 30.0;  // a stop that never ends shows as this much time
    bool armed = false;
    double stopAtS = -1.0;
    TestRun run =
        runCommands(millConfig(), spindleCoolantTwoBlocks(), Pose{}, options,
                    [&](SimulatedMachine& sim, const Sample&, const MotionStatus& s) {
                        if (!armed) {
                            sim.command({OperatorCommandKind::SingleBlock, -1, 0.0, 0.0, true});
                            armed = true;
                        }
                        if (stopAtS < 0.0 && s.mode == MotionMode::Stopped) {
                            EXPECT_EQ(s.coolant, 1u);
                            EXPECT_GT(s.spindleRpm, 100.0);  // turning
                            stopAtS = s.timeS;
                            sim.command({OperatorCommandKind::QuickStop});
                        }
                    });
    ASSERT_GE(stopAtS, 0.0) << "no single-block stop";
    EXPECT_EQ(run.sim->status().mode, MotionMode::Idle);
    // Aborted where it waited: the second block never runs.
    EXPECT_NEAR(run.report.finalPosition[0], 10.0, 1e-6);
    EXPECT_LT(run.sim->timeS() - stopAtS, 1.0);
    // 1000 rpm at the mill's 3000 rpm/s spindle ramp: a third of a second and the jerk phases.
    run.sim->runFor(1.0);
    EXPECT_EQ(run.sim->status().spindleRpm, 0.0);
    EXPECT_EQ(run.sim->status().coolant, 0u);
}

TEST(QuickStop, EndsAReferenceRunAndLeavesTheAxisUnreferenced) {
    SimulationOptions options;
    options.motion.startHomed = false;
    TestRun run = runCommands(millConfig(), {}, at(37.0, -12.0, 20.0), options);
    SimulatedMachine& sim = *run.sim;
    sim.command({OperatorCommandKind::Home, -1});
    sim.runFor(0.2);
    ASSERT_EQ(sim.status().mode, MotionMode::Homing);
    sim.command({OperatorCommandKind::QuickStop});
    // The search runs at 5 % of 500 mm/s; braking from there takes milliseconds.
    ASSERT_TRUE(
        sim.runUntil([](const MotionStatus& s) { return s.mode == MotionMode::Idle; }, 1.0));
    EXPECT_EQ(sim.status().homedMask & 0x7, 0u);
}

TEST(EmergencyStop, DrivesStopThemselvesAndResetEnablesThemAgain) {
    int cycles = 0;
    TestRun run = runCommands(millConfig(), longLine(), Pose{}, {},
                              [&](SimulatedMachine& sim, const Sample&, const MotionStatus&) {
                                  if (++cycles == 1500)
                                      sim.command({OperatorCommandKind::EmergencyStop});
                              });
    EXPECT_EQ(run.sim->status().mode, MotionMode::EmergencyStop);
    double stopped = run.report.finalPosition[0];
    EXPECT_LT(stopped, 200.0);
    // The drives' own quick-stop ramp (50 mm/s at 5000 mm/s^2) takes 10 ms, longer than the
    // setpoint filter that drain() waits for: let them come to rest before the reset.
    run.sim->runFor(0.02);
    run.sim->command({OperatorCommandKind::Reset});
    run.sim->runFor(0.05);
    EXPECT_EQ(run.sim->status().mode, MotionMode::Idle);
    // Re-enabled without a jump: the setpoints continue from where the drives stopped.
    EXPECT_NEAR(run.sim->status().commandedPosition[0], run.sim->status().actualPosition[0], 1e-6);
}

// The E-stop button's chain is an input, not a command: while it is open nothing can switch the
// drives on; released, Reset does.
TEST(EmergencyStop, TheOpenChainStopsTheProgramAndRefusesResetUntilReleased) {
    int cycles = 0;
    TestRun run = runCommands(millConfig(), longLine(), Pose{}, {},
                              [&](SimulatedMachine& sim, const Sample&, const MotionStatus&) {
                                  if (++cycles == 1500) sim.drives().setEmergencyStopPressed(true);
                              });
    const MotionStatus& status = run.sim->status();
    EXPECT_EQ(status.mode, MotionMode::EmergencyStop);
    EXPECT_TRUE(status.emergencyStopOpen);
    // 50 mm/s for about 1.5 s: far from the end at X200, and stopped within the drives' ramp.
    EXPECT_GT(run.report.finalPosition[0], 50.0);
    EXPECT_LT(run.report.finalPosition[0], 80.0);
    run.sim->runFor(0.02);
    run.sim->command({OperatorCommandKind::Reset});
    run.sim->runFor(0.05);
    EXPECT_EQ(status.mode, MotionMode::EmergencyStop) << "switched on with the chain open";
    run.sim->drives().setEmergencyStopPressed(false);
    run.sim->runFor(0.002);
    EXPECT_FALSE(status.emergencyStopOpen);
    EXPECT_EQ(status.mode, MotionMode::EmergencyStop) << "releasing the button is not Reset";
    run.sim->command({OperatorCommandKind::Reset});
    run.sim->runFor(0.05);
    EXPECT_EQ(status.mode, MotionMode::Idle);
}

TEST(Probing, StopsOnTriggerAndLatchesTheContactPoint) {
    SimulationOptions options;
    // The workpiece top is at Z = -2.5 under X 0..50.
    options.probeSurface = [](const AxisVector& tip) {
        return tip[2] <= -2.5 && tip[0] >= 0.0 && tip[0] <= 50.0;
    };
    std::vector<canon::Command> program = {
        cmd(canon::RapidMove{at(10, 10, 5)}, 1),
        cmd(canon::ProbeMove{at(10, 10, -20), 300.0}, 2),
        cmd(canon::SyncPoint{canon::SyncReason::ProbeResult}, 3),
        cmd(canon::RapidMove{at(10, 10, 5)}, 4),
    };
    TestRun run = runCommands(millConfig(), program, Pose{}, options);
    // The simulation latches the crossing inside the period (touch probe): exact to rounding.
    EXPECT_TRUE(run.world.probeTriggered);
    EXPECT_NEAR(run.world.probePosition[Axis::Z], -2.5, 1e-6);
    EXPECT_NEAR(run.world.probePosition[Axis::X], 10.0, 1e-9);
    EXPECT_NEAR(run.report.finalPosition[2], 5.0, 1e-6);
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
}

TEST(Probing, ReportsAMissWhenNothingIsTouched) {
    SimulationOptions options;
    options.probeSurface = [](const AxisVector& tip) { return tip[2] <= -50.0; };
    TestRun run =
        runCommands(millConfig(), {cmd(canon::ProbeMove{at(0, 0, -5), 300.0})}, Pose{}, options);
    EXPECT_FALSE(run.world.probeTriggered);
    EXPECT_NEAR(run.report.finalPosition[2], -5.0, 1e-6);
}

TEST(Probing, TouchesTheMachineFilesBoxAndLatchesWhereTheProbeLeavesIt) {
    // [simulation.probe]: X 0..50, Z up to machine -102.5; the workpiece origin at machine Z -100
    // puts the top at workpiece Z -2.5.
    machine::MachineConfig config = millConfig();
    config.probeWorkpiece.enabled = true;
    config.probeWorkpiece.xMinMm = 0.0;
    config.probeWorkpiece.xMaxMm = 50.0;
    config.probeWorkpiece.zMaxMm = -102.5;
    SimulationOptions options;
    options.motion.workOffset[2] = -100.0;
    SimulatedMachine sim(config, options);
    sim.consume(cmd(canon::RapidMove{at(10, 10, 5)}, 1));
    sim.consume(cmd(canon::ProbeMove{at(10, 10, -20), 300.0}, 2));
    const interp::WorldSnapshot touch = sim.drain();
    EXPECT_TRUE(touch.probeTriggered);
    EXPECT_NEAR(touch.probePosition[Axis::Z], -2.5, 1e-6);
    EXPECT_LT(touch.position[Axis::Z], -2.5);  // stopped beyond the latch
    // Until release (FAGOR G76): back up, latched where the tip leaves the top.
    sim.consume(cmd(canon::ProbeMove{at(10, 10, 5), 300.0, true}, 3));
    const interp::WorldSnapshot release = sim.drain();
    EXPECT_TRUE(release.probeTriggered);
    EXPECT_NEAR(release.probePosition[Axis::Z], -2.5, 1e-6);
    EXPECT_GT(release.position[Axis::Z], -2.5);
    EXPECT_LT(release.position[Axis::Z], 5.0);
    // Beside the box (X 60) a touch probe move reaches its end: a miss.
    sim.consume(cmd(canon::RapidMove{at(60, 10, 5)}, 4));
    sim.consume(cmd(canon::ProbeMove{at(60, 10, -20), 300.0}, 5));
    const interp::WorldSnapshot miss = sim.drain();
    EXPECT_FALSE(miss.probeTriggered);
    EXPECT_NEAR(miss.position[Axis::Z], -20.0, 1e-6);
}

// Records the spindle angle and Z during a synchronised move.
struct SyncTrace {
    std::vector<std::pair<double, double>> zAndAngle;  // during synchronised elements
};

TEST(Threading, PositionIsLockedToTheSpindleAngle) {
    const double lead = 1.5;
    std::vector<canon::Command> program = {
        cmd(canon::SpindleControl{canon::SpindleDirection::Clockwise, 600.0}, 1),
        cmd(canon::RapidMove{at(0, 0, 2)}, 2),
        cmd(canon::SpindleSyncedMove{at(0, 0, -20), lead, 90.0}, 3),
        cmd(canon::RapidMove{at(5, 0, -20)}, 4),
    };
    std::vector<std::pair<double, double>> locked;
    SimulationOptions options;
    options.onSample = [&](const Sample& s, const MotionStatus&) {
        if (s.tip[2] < 2.0 - 1e-9 && s.tip[2] > -20.0 + 1e-9 && s.tip[0] < 1e-12) {
            locked.emplace_back(s.tip[2], s.spindleDeg);
        }
    };
    TestRun run = runCommands(millConfig(), program, at(0, 0, 10), options);
    ASSERT_GT(locked.size(), 100u);
    // The thread starts at spindle angle 90 deg (modulo 360) at Z = 2 and Z goes down 1.5 mm per
    // turn: angle = start + (2 - z) / lead * 360 on every sample (smoothed setpoints included).
    double start = locked.front().second + (locked.front().first - 2.0) / lead * 360.0;
    EXPECT_NEAR(std::fmod(start, 360.0), 90.0, 1e-6);
    for (const auto& [z, angle] : locked) {
        EXPECT_NEAR(angle, start + (2.0 - z) / lead * 360.0, 1e-6) << "z " << z;
    }
    EXPECT_NEAR(run.report.finalPosition[2], -20.0, 1e-6);
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
}

TEST(Threading, AVariableLeadIsRefusedRatherThanCutWithTheWrongLead) {
    canon::SpindleSyncedMove g34{at(0, 0, -20), 1.5, 0.0};
    g34.leadChangeMmPerRev = 0.1;
    std::vector<canon::Command> program = {
        cmd(canon::SpindleControl{canon::SpindleDirection::Clockwise, 600.0}, 1),
        cmd(canon::RapidMove{at(0, 0, 2)}, 2),
        cmd(g34, 3),
    };
    TestRun run = runCommands(millConfig(), program, at(0, 0, 10), {});
    ASSERT_TRUE(run.report.refused);
    ASSERT_FALSE(run.report.diagnostics.empty());
    EXPECT_EQ(run.report.diagnostics[0].code, "motion.variable-lead");
    EXPECT_EQ(run.report.diagnostics[0].line, 3u);
    EXPECT_NEAR(run.report.finalPosition[2], 2.0, 1e-6);
}

TEST(RigidTapping, TheSpindleTurnsBackOutOfTheThread) {
    // Cycle 207 as canonical moves: down 10 mm and back with pitch 1 mm (M3, right hand).
    const double pitch = 1.0;
    std::vector<canon::Command> program = {
        cmd(canon::SpindleControl{canon::SpindleDirection::Clockwise, 500.0}, 1),
        cmd(canon::RapidMove{at(0, 0, 2)}, 2),
        cmd(canon::SpindleSyncedMove{at(0, 0, -8), pitch, 0.0}, 3),
        cmd(canon::SpindleSyncedMove{at(0, 0, 2), pitch, 0.0}, 4),
        cmd(canon::SpindleControl{canon::SpindleDirection::Stopped, 0.0}, 5),
    };
    double angleAtTop = 0.0;
    double angleAtBottom = 0.0;
    double angleBackAtTop = 0.0;
    bool down = true;
    bool back = false;
    SimulationOptions options;
    options.onSample = [&](const Sample& s, const MotionStatus&) {
        if (s.tip[2] <= -8.0 + 1e-9) {
            angleAtBottom = s.spindleDeg;
            down = false;
        }
        if (down && std::fabs(s.tip[2] - 2.0) < 1e-9) angleAtTop = s.spindleDeg;
        if (!down && std::fabs(s.tip[2] - 2.0) < 1e-9 && !back) {
            angleBackAtTop = s.spindleDeg;
            back = true;
        }
    };
    TestRun run = runCommands(millConfig(), program, at(0, 0, 10), options);
    EXPECT_NEAR(angleAtBottom - angleAtTop, 10.0 / pitch * 360.0, 1e-6);
    EXPECT_NEAR(angleBackAtTop, angleAtTop, 1e-6);
    EXPECT_NEAR(run.report.finalPosition[2], 2.0, 1e-6);
}

TEST(FeedPerRevolution, FeedFollowsTheSpindleSpeed) {
    std::vector<canon::Command> program = {
        cmd(canon::SpindleControl{canon::SpindleDirection::Clockwise, 1200.0}, 1),
        cmd(canon::SetFeedMode{canon::FeedMode::PerRevolution}, 2),
        cmd(canon::LinearMove{at(20, 0, 0), 0.1}, 3),
    };
    TestRun run = runCommands(millConfig(), program, Pose{}, {});
    // 0.1 mm/rev at 1200 rpm = 2 mm/s.
    EXPECT_NEAR(run.checker->axis(0).velocity, 2.0, 1e-6);
    EXPECT_NEAR(run.report.finalPosition[0], 20.0, 1e-6);
}

TEST(SoftLimits, AMoveLeavingTheWorkAreaIsRefusedBeforeItMoves) {
    std::vector<canon::Command> program = {
        cmd(canon::LinearMove{at(100, 0, 0), 3000.0}, 1),
        cmd(canon::LinearMove{at(100, 0, 60), 3000.0}, 2),  // mill Z ends at +50
        cmd(canon::LinearMove{at(0, 0, 0), 3000.0}, 3),
    };
    TestRun run = runCommands(millConfig(), program, Pose{}, {});
    ASSERT_TRUE(run.report.refused);
    ASSERT_FALSE(run.report.diagnostics.empty());
    EXPECT_EQ(run.report.diagnostics[0].code, "motion.soft-limit");
    EXPECT_EQ(run.report.diagnostics[0].line, 2u);
    EXPECT_NE(run.report.diagnostics[0].message().find("20"), std::string::npos);  // block 20
    // It stopped at the end of the last accepted block.
    EXPECT_NEAR(run.report.finalPosition[0], 100.0, 1e-6);
    EXPECT_NEAR(run.report.finalPosition[2], 0.0, 1e-6);
}

TEST(SoftLimits, ArcExtremesAndToolLengthCount) {
    // A full circle of radius 30 about X 380 reaches X 410 > 400 although both ends are inside.
    canon::ArcMove arc;
    arc.target = at(350, 0, 0);
    arc.center = Vec3(380, 0, 0);
    arc.sweepRad = kTwoPi;
    arc.feed = 3000.0;
    TestRun circle = runCommands(
        millConfig(), {cmd(canon::LinearMove{at(350, 0, 0), 6000.0}, 1), cmd(arc, 2)}, Pose{}, {});
    ASSERT_TRUE(circle.report.refused);
    EXPECT_EQ(circle.report.diagnostics[0].line, 2u);
    // Z 45 plus a 10 mm tool is 55 in machine coordinates.
    canon::ToolChange tool;
    tool.number = 1;
    tool.geometry.lengthMm = 10.0;
    TestRun high = runCommands(
        millConfig(), {cmd(tool, 1), cmd(canon::LinearMove{at(0, 0, 45), 3000.0}, 2)}, Pose{}, {});
    ASSERT_TRUE(high.report.refused);
}

// The soft-limit bypass: an infinite, NaN or huge coordinate passed --motion with
// ok:true. The planner refuses it itself, before anything moves, whatever the interpreter did.
TEST(SoftLimits, NonFiniteAndHugeNumbersAreRefusedBeforeAnythingMoves) {
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    canon::ArcMove arcAboutNan;
    arcAboutNan.target = at(10, 0, 0);
    arcAboutNan.center = Vec3(nan, 0, 0);
    arcAboutNan.sweepRad = kPi;
    arcAboutNan.feed = 3000.0;
    const std::vector<canon::CommandBody> bad = {
        canon::RapidMove{at(inf, 0, 0)},
        canon::RapidMove{at(nan, 0, 0)},
        canon::RapidMove{at(1e200, 0, 0)},
        canon::LinearMove{at(10, 0, 0), nan},
        canon::LinearMove{at(0, -inf, 0), 1.0},
        arcAboutNan,
        canon::Dwell{nan},
    };
    for (const canon::CommandBody& body : bad) {
        TestRun run =
            runCommands(millConfig(),
                        {cmd(canon::LinearMove{at(5, 0, 0), 3000.0}, 1), cmd(body, 2)}, Pose{}, {});
        ASSERT_TRUE(run.report.refused) << body.index();
        ASSERT_FALSE(run.report.diagnostics.empty());
        EXPECT_EQ(run.report.diagnostics[0].code, "motion.unsafe-value");
        EXPECT_EQ(run.report.diagnostics[0].line, 2u);
        EXPECT_NEAR(run.report.finalPosition[0], 5.0, 1e-6);
        EXPECT_LT(run.report.durationS, 1.0);  // not the 86,400 s of the issue
    }
}

// The check itself, without the planner's guard in front: 0 * inf and NaN fail every comparison,
// so each test is written to pass only for a number inside the limits.
TEST(SoftLimits, TheCheckRefusesNonFiniteGeometry) {
    const MachineModel model = makeMachineModel(millConfig(), {});
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    AxisVector from{};
    AxisVector to{};
    to[0] = 10.0;
    ASSERT_FALSE(checkSoftLimits(model, makeLine(from, to), 0.0));
    for (const double bad : {inf, -inf, nan}) {
        PathGeometry g = makeLine(from, to);
        g.rate[0] = bad;  // origin + rate * length: inf or NaN
        EXPECT_TRUE(checkSoftLimits(model, g, 0.0)) << bad;
        g = makeLine(from, to);
        g.length = bad;
        EXPECT_TRUE(checkSoftLimits(model, g, 0.0)) << bad;
        g = makeLine(from, to);
        g.rate[0] = 0.0;
        g.length = inf;  // 0 * inf = NaN on every axis
        EXPECT_TRUE(checkSoftLimits(model, g, 0.0));
        g = makeLine(from, to);
        g.origin[1] = bad;
        EXPECT_TRUE(checkSoftLimits(model, g, 0.0)) << bad;
        EXPECT_TRUE(checkSoftLimits(model, makeLine(from, to), bad)) << "tool length " << bad;
    }
    // An arc of infinite radius: its extremes are infinite.
    PathGeometry arc = makeLine(from, to);
    arc.radius = inf;
    arc.e1 = {1.0, 0.0, 0.0};
    arc.k = 1.0;
    EXPECT_TRUE(checkSoftLimits(model, arc, 0.0));
}

TEST(SingleBlock, StopsAtTheEndOfEveryBlock) {
    std::vector<canon::Command> program;
    for (int i = 1; i <= 5; ++i)
        program.push_back(cmd(canon::LinearMove{at(10.0 * i, (i % 2) * 5.0, 0), 3000.0},
                              static_cast<uint32_t>(i)));
    int stops = 0;
    bool armed = false;
    TestRun run =
        runCommands(millConfig(), program, Pose{}, {},
                    [&](SimulatedMachine& sim, const Sample&, const MotionStatus& s) {
                        if (!armed) {
                            sim.command({OperatorCommandKind::SingleBlock, -1, 0.0, 0.0, true});
                            armed = true;
                        }
                        static MotionMode last = MotionMode::Idle;
                        if (s.mode == MotionMode::Stopped && last != MotionMode::Stopped) ++stops;
                        last = s.mode;
                    });
    EXPECT_EQ(stops, 5);
    EXPECT_NEAR(run.report.finalPosition[0], 50.0, 1e-6);
}

// A called cycle is one block (its moves carry the CYCL CALL's place): single block stops
// after the whole cycle, not after each of its moves (TNC 320; docs/hmi.md, "Single block").
TEST(SingleBlock, RunsACalledCycleAsOneBlock) {
    const std::vector<canon::Command> program = {
        cmd(canon::RapidMove{at(10, 0, 50)}, 1),
        // Block 2 "CYCL CALL": drilling at X10 down to Z-10, a dwell, back up.
        cmd(canon::RapidMove{at(10, 0, 2)}, 2),
        cmd(canon::LinearMove{at(10, 0, -10), 300.0}, 2),
        cmd(canon::Dwell{0.1}, 2),
        cmd(canon::RapidMove{at(10, 0, 2)}, 2),
        cmd(canon::RapidMove{at(10, 0, 50)}, 2),
        cmd(canon::RapidMove{at(30, 0, 50)}, 3),
    };
    std::vector<std::array<double, 3>> stops;
    bool armed = false;
    MotionMode last = MotionMode::Idle;
    TestRun run =
        runCommands(millConfig(), program, Pose{}, {},
                    [&](SimulatedMachine& sim, const Sample&, const MotionStatus& s) {
                        if (!armed) {
                            sim.command({OperatorCommandKind::SingleBlock, -1, 0.0, 0.0, true});
                            armed = true;
                        }
                        if (s.mode == MotionMode::Stopped && last != MotionMode::Stopped)
                            stops.push_back({s.commandedPosition[0], s.commandedPosition[1],
                                             s.commandedPosition[2]});
                        last = s.mode;
                    });
    // Three blocks, three stops: at the end of block 1, of the cycle (back at Z50), of block 3.
    ASSERT_EQ(stops.size(), 3u);
    const std::array<std::array<double, 3>, 3> expected = {
        {{10.0, 0.0, 50.0}, {10.0, 0.0, 50.0}, {30.0, 0.0, 50.0}}};
    for (size_t i = 0; i < 3; ++i)
        for (size_t a = 0; a < 3; ++a)
            // Single block is switched on in the servo cycle only, after all was planned: the
            // corners keep their blends and the stops are where those begin, within the path
            // tolerance (docs/motion.md), far from the hole (Z-10, Z2).
            EXPECT_NEAR(stops[i][a], expected[i][a], 0.1) << "stop " << i << " axis " << a;
    EXPECT_NEAR(run.report.finalPosition[0], 30.0, 1e-6);
}

// Fagor ESBLK .. DSBLK: the blocks between run as one block in single block, without a stop at
// the end of each (seed 002 §12.3); the blocks before and after stop as usual.
TEST(SingleBlock, BlocksAProgramJoinedRunAsOneBlock) {
    canon::ControlLocks join;
    join.joinBlocks = true;
    const std::vector<canon::Command> program = {
        cmd(canon::LinearMove{at(10, 0, 0), 3000.0}, 1),
        cmd(join, 2),  // (ESBLK)
        cmd(canon::LinearMove{at(20, 0, 0), 3000.0}, 3),
        cmd(canon::LinearMove{at(20, 10, 0), 3000.0}, 4),
        cmd(canon::LinearMove{at(30, 10, 0), 3000.0}, 5),
        cmd(canon::ControlLocks{}, 6),  // (DSBLK)
        cmd(canon::LinearMove{at(30, 20, 0), 3000.0}, 7),
    };
    std::vector<std::array<double, 2>> stops;
    bool armed = false;
    MotionMode last = MotionMode::Idle;
    TestRun run =
        runCommands(millConfig(), program, Pose{}, {},
                    [&](SimulatedMachine& sim, const Sample&, const MotionStatus& s) {
                        if (!armed) {
                            sim.command({OperatorCommandKind::SingleBlock, -1, 0.0, 0.0, true});
                            armed = true;
                        }
                        if (s.mode == MotionMode::Stopped && last != MotionMode::Stopped)
                            stops.push_back({s.commandedPosition[0], s.commandedPosition[1]});
                        last = s.mode;
                    });
    // Block 1, the joined blocks 3-5 (at X30 Y10), block 7.
    ASSERT_EQ(stops.size(), 3u);
    const std::array<std::array<double, 2>, 3> expected = {{{10, 0}, {30, 10}, {30, 20}}};
    for (size_t i = 0; i < 3; ++i)
        for (size_t a = 0; a < 2; ++a)
            EXPECT_NEAR(stops[i][a], expected[i][a], 0.5) << "stop " << i << " axis " << a;
    EXPECT_NEAR(run.report.finalPosition[1], 20.0, 1e-6);
}

// What the machine shows at each single-block stop; NC start is pressed at each.
struct StepStop {
    double x = 0.0;
    double spindleRpm = 0.0;
    uint8_t coolant = 0;
    uint32_t line = 0;
};

// `everyBlock`: blocks without a move are steps too (FAGOR).
std::vector<StepStop> singleBlockStops(const std::vector<canon::Command>& program,
                                       bool everyBlock = false) {
    SimulationOptions options;
    options.autoCycleStart = false;
    options.maxSimulatedS = 60.0;
    std::vector<StepStop> stops;
    bool armed = false;
    MotionMode last = MotionMode::Idle;
    runCommands(
        millConfig(), program, Pose{}, options,
        [&](SimulatedMachine& sim, const Sample&, const MotionStatus& s) {
            if (!armed) {
                sim.command({OperatorCommandKind::SingleBlock, -1, 0.0, 0.0, true});
                sim.command({OperatorCommandKind::SingleBlockEveryBlock, -1, 0.0, 0.0, everyBlock});
                armed = true;
            }
            if (s.mode == MotionMode::Stopped && last != MotionMode::Stopped) {
                stops.push_back({s.commandedPosition[0], s.spindleRpm, s.coolant, s.source.line});
                sim.command({OperatorCommandKind::CycleStart});
            }
            last = s.mode;
        });
    return stops;
}

canon::SpindleControl spindleAt(double rpm) {
    canon::SpindleControl spindle;
    spindle.direction =
        rpm > 0.0 ? canon::SpindleDirection::Clockwise : canon::SpindleDirection::Stopped;
    spindle.speedRpm = rpm;
    return spindle;
}

// One NC start runs one block completely: the M functions that act at the end of a block (M5,
// M9 after `L X+20 FMAX M5 M9`) run before its single-block stop, not at the next NC start.
TEST(SingleBlock, RunsTheBlocksEndFunctionsBeforeItsStop) {
    canon::CoolantControl flood;
    flood.flood = true;
    const std::vector<canon::Command> program = {
        // Block 1 "L X+10 F3000 M3 M8": spindle and coolant on before the move.
        cmd(spindleAt(2000.0), 1), cmd(flood, 1), cmd(canon::LinearMove{at(10, 0, 0), 3000.0}, 1),
        // Block 2 "L X+20 FMAX M5 M9": the move, then spindle and coolant off.
        cmd(canon::RapidMove{at(20, 0, 0)}, 2), cmd(spindleAt(0.0), 2),
        cmd(canon::CoolantControl{}, 2),
        // Block 3 "L X+30 F3000".
        cmd(canon::LinearMove{at(30, 0, 0), 3000.0}, 3)};
    const std::vector<StepStop> stops = singleBlockStops(program);
    ASSERT_EQ(stops.size(), 3u);
    EXPECT_NEAR(stops[0].x, 10.0, 1e-6);
    // M3 lets the move start once the spindle runs at its speed.
    EXPECT_NEAR(stops[0].spindleRpm, 2000.0, 1e-6);
    EXPECT_EQ(stops[0].coolant, 1u);
    // The stop after block 2: its M5 has stopped the spindle (the action waits for it), M9 the
    // coolant.
    EXPECT_NEAR(stops[1].x, 20.0, 1e-6);
    EXPECT_NEAR(stops[1].spindleRpm, 0.0, 1e-3);
    EXPECT_EQ(stops[1].coolant, 0u);
    EXPECT_NEAR(stops[2].x, 30.0, 1e-6);
}

// FAGOR single block stops after every block: an M8 alone, a G4 dwell, an M function, an S with
// M3 each get their stop, where the axes stand (they act at rest). Without every block (the
// TNC), the same blocks run with the next move and only the three moves stop.
TEST(SingleBlock, EveryBlockStopsAfterTheBlocksWithoutAMove) {
    canon::CoolantControl flood;
    flood.flood = true;
    canon::ToolChange tool;
    tool.number = 2;
    const std::vector<canon::Command> program = {
        cmd(canon::LinearMove{at(10, 0, 0), 3000.0}, 1),
        cmd(flood, 2),               // N2 M8
        cmd(canon::Dwell{0.05}, 3),  // N3 G4 K5
        cmd(canon::LinearMove{at(20, 0, 0), 3000.0}, 4),
        cmd(canon::MachineFunction{20}, 5),  // N5 M20
        cmd(spindleAt(1000.0), 6),           // N6 S1000 M3
        cmd(tool, 7),                        // N7 T2: its move follows in the same block
        cmd(canon::LinearMove{at(30, 0, 0), 3000.0}, 7)};
    const std::vector<StepStop> stops = singleBlockStops(program, true);
    const std::vector<uint32_t> lines = {1, 2, 3, 4, 5, 6, 7};
    const std::vector<double> xs = {10, 10, 10, 20, 20, 20, 30};
    ASSERT_EQ(stops.size(), lines.size());
    for (size_t i = 0; i < lines.size(); ++i) {
        EXPECT_EQ(stops[i].line, lines[i]) << "stop " << i;
        EXPECT_NEAR(stops[i].x, xs[i], 1e-6) << "stop " << i;
    }
    EXPECT_EQ(stops[0].coolant, 0u);  // M8 waits for its own NC start
    EXPECT_EQ(stops[1].coolant, 1u);
    EXPECT_NEAR(stops[4].spindleRpm, 0.0, 1e-6);
    EXPECT_NEAR(stops[5].spindleRpm, 1000.0, 1e-3);  // M3 waits for the speed
    const std::vector<StepStop> moveStops = singleBlockStops(program, false);
    ASSERT_EQ(moveStops.size(), 3u);
    EXPECT_EQ(moveStops[0].line, 1u);
    EXPECT_EQ(moveStops[1].line, 4u);
    EXPECT_EQ(moveStops[2].line, 7u);
}

// Between ESBLK and DSBLK a block without a move is part of the one joined block: no stop.
TEST(SingleBlock, EveryBlockKeepsTheBlocksAProgramJoined) {
    canon::ControlLocks join;
    join.joinBlocks = true;
    canon::CoolantControl flood;
    flood.flood = true;
    const std::vector<canon::Command> program = {
        cmd(canon::LinearMove{at(10, 0, 0), 3000.0}, 1), cmd(join, 2),                   // (ESBLK)
        cmd(canon::LinearMove{at(20, 0, 0), 3000.0}, 3), cmd(flood, 4),                  // M8
        cmd(canon::LinearMove{at(30, 0, 0), 3000.0}, 5), cmd(canon::ControlLocks{}, 6),  // (DSBLK)
        cmd(canon::LinearMove{at(40, 0, 0), 3000.0}, 7)};
    const std::vector<StepStop> stops = singleBlockStops(program, true);
    ASSERT_EQ(stops.size(), 3u);
    EXPECT_NEAR(stops[0].x, 10.0, 1e-6);
    EXPECT_NEAR(stops[1].x, 30.0, 1e-6);
    EXPECT_EQ(stops[1].coolant, 1u);
    EXPECT_NEAR(stops[2].x, 40.0, 1e-6);
}

TEST(ToolChange, JointsStayAndTheTipMovesByTheLengthChange) {
    canon::ToolChange tool;
    tool.number = 3;
    tool.geometry.lengthMm = 25.0;
    std::vector<canon::Command> program = {
        cmd(canon::LinearMove{at(10, 0, 0), 3000.0}, 1),
        cmd(tool, 2),
        cmd(canon::LinearMove{at(10, 0, -5), 3000.0}, 3),
    };
    TestRun run = runCommands(millConfig(), program, Pose{}, {});
    EXPECT_NEAR(run.report.finalPosition[2], -5.0, 1e-6);
    // The joint is the tip plus the tool length.
    EXPECT_NEAR(run.sim->drives().reportedPosition(2), 20.0, 1e-6);
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
}

TEST(Jog, ContinuousIncrementalAndHandwheel) {
    TestRun run = runCommands(millConfig(), {}, Pose{}, {});
    SimulatedMachine& sim = *run.sim;
    auto settle = [&] { sim.runFor(0.002); };
    sim.command({OperatorCommandKind::JogIncrement, 0, 12.5, 100.0});
    settle();
    ASSERT_TRUE(sim.runUntil(
        [](const MotionStatus& s) { return s.mode == MotionMode::Idle && s.cycle > 5; }, 5.0));
    sim.runFor(0.05);
    EXPECT_NEAR(sim.status().commandedPosition[0], 12.5, 1e-9);
    sim.command({OperatorCommandKind::JogContinuous, 1, -50.0});
    sim.runFor(0.5);
    sim.command({OperatorCommandKind::JogStop, 1});
    settle();
    ASSERT_TRUE(
        sim.runUntil([](const MotionStatus& s) { return s.mode == MotionMode::Idle; }, 5.0));
    EXPECT_LT(sim.status().commandedPosition[1], -15.0);
    for (int i = 0; i < 10; ++i)
        sim.command({OperatorCommandKind::Handwheel, 2, -0.01});
    settle();
    ASSERT_TRUE(
        sim.runUntil([](const MotionStatus& s) { return s.mode == MotionMode::Idle; }, 5.0));
    sim.runFor(0.05);
    EXPECT_NEAR(sim.status().commandedPosition[2], -0.1, 1e-9);
    // Past the soft limit (X max 400): clipped to it.
    sim.command({OperatorCommandKind::JogIncrement, 0, 1000.0, 400.0});
    settle();
    ASSERT_TRUE(sim.runUntil(
        [](const MotionStatus& s) { return s.mode == MotionMode::Idle && s.pathVelocity == 0.0; },
        20.0));
    sim.runFor(0.05);
    EXPECT_NEAR(sim.status().commandedPosition[0], 400.0, 1e-9);
}

// An axis can stand beyond its soft limit (the limit was changed in the machine file, the
// machine was pushed there while switched off): a jog may only bring it back. A jog that would
// go further is refused where it stands; before, the setpoint jumped back to the limit at once
// (50 mm here: 8.3 mm in one period after the servo filter, 17 times the axis velocity).
TEST(Jog, BeyondTheSoftLimitOnlyTheWayBackMoves) {
    TestRun run = runCommands(millConfig(), {}, at(450.0, 0.0, 0.0), {});
    SimulatedMachine& sim = *run.sim;
    const double period = sim.model().periodS;
    const double fastest = sim.model().axes[0].velocity;  // mm/s
    double largestStep = 0.0;
    double last = sim.status().commandedPosition[0];
    auto watch = [&](double seconds) {
        for (double t = 0.0; t < seconds; t += period) {
            sim.runFor(period);
            largestStep =
                std::max(largestStep, std::fabs(sim.status().commandedPosition[0] - last));
            last = sim.status().commandedPosition[0];
        }
    };
    ASSERT_NEAR(last, 450.0, 1e-9);
    sim.command({OperatorCommandKind::JogContinuous, 0, 50.0});
    watch(0.3);
    sim.command({OperatorCommandKind::JogStop, 0});
    watch(0.1);
    EXPECT_NEAR(sim.status().commandedPosition[0], 450.0, 1e-9);
    sim.command({OperatorCommandKind::JogIncrement, 0, 5.0, 100.0});
    watch(0.3);
    EXPECT_NEAR(sim.status().commandedPosition[0], 450.0, 1e-9);
    sim.command({OperatorCommandKind::Handwheel, 0, 0.5});
    watch(0.3);
    EXPECT_NEAR(sim.status().commandedPosition[0], 450.0, 1e-9);
    EXPECT_LE(largestStep, fastest * period + 1e-9);
    // Back towards the work area: 10 mm as asked, then on to the limit and no further.
    sim.command({OperatorCommandKind::JogIncrement, 0, -10.0, 100.0});
    watch(0.5);
    EXPECT_NEAR(sim.status().commandedPosition[0], 440.0, 1e-9);
    sim.command({OperatorCommandKind::JogContinuous, 0, -100.0});
    watch(0.2);
    EXPECT_LT(sim.status().commandedPosition[0], 440.0 - 10.0);
    sim.command({OperatorCommandKind::JogStop, 0});
    watch(0.2);
    EXPECT_LE(largestStep, fastest * period + 1e-9);
}

TEST(Homing, FindsTheSwitchAndEndsAtHome) {
    SimulationOptions options;
    options.motion.startHomed = false;
    TestRun run = runCommands(millConfig(), {}, at(37.0, -12.0, 20.0), options);
    SimulatedMachine& sim = *run.sim;
    // The drives report the true position plus an unknown offset until homed.
    sim.command({OperatorCommandKind::Home, -1});
    sim.runFor(0.002);
    ASSERT_TRUE(
        sim.runUntil([](const MotionStatus& s) { return (s.homedMask & 0x7) == 0x7; }, 120.0));
    sim.runFor(0.5);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(sim.status().actualPosition[static_cast<size_t>(i)], 0.0, 1e-6);  // home = 0
        // The switch sits at home; it is read once per period, so the latch is late by up to one
        // period of the search velocity (5 % of 500 mm/s: 0.025 mm).
        EXPECT_NEAR(sim.drives().truePosition(i), 0.0, 0.025);
    }
}

// The joints in the order their reference bits came on during Home all; `during` runs every
// servo period before the reference run ends.
std::vector<int> homingOrder(SimulatedMachine& sim, int axes,
                             const std::function<void(SimulatedMachine&)>& during) {
    const uint16_t all = static_cast<uint16_t>((1u << axes) - 1u);
    std::vector<int> order;
    uint16_t seen = 0;
    sim.command({OperatorCommandKind::Home, -1});
    for (int step = 0; step < 120000 && (seen & all) != all; ++step) {
        sim.runFor(0.001);
        during(sim);
        const uint16_t now = sim.status().homedMask & all;
        for (int j = 0; j < axes; ++j) {
            if ((now >> j & 1u) && !(seen >> j & 1u)) order.push_back(j);
        }
        seen = now;
    }
    return order;
}

TEST(Homing, TheMillHomesZFirstAndUpwardsThenXAndY) {
    SimulationOptions options;
    options.motion.startHomed = false;
    // The tool 300 mm down, e.g. in a part: X and Y must not move before Z is up at its home.
    TestRun run = runCommands(millConfig(), {}, at(37.0, -12.0, -300.0), options);
    SimulatedMachine& sim = *run.sim;
    double lowestZ = 0.0;
    bool xyMovedBeforeZ = false;
    const std::vector<int> order = homingOrder(sim, 3, [&](SimulatedMachine& s) {
        lowestZ = std::min(lowestZ, s.drives().truePosition(2));
        if ((s.status().homedMask & 0x4) == 0 &&
            (std::fabs(s.drives().truePosition(0) - 37.0) > 1e-6 ||
             std::fabs(s.drives().truePosition(1) + 12.0) > 1e-6))
            xyMovedBeforeZ = true;
    });
    // home_sequence: Z 1, X and Y 2 (display order within a group).
    EXPECT_EQ(order, (std::vector<int>{2, 0, 1}));
    EXPECT_FALSE(xyMovedBeforeZ);
    // Z only rises from -300 (to the switch at its home 0, the top, and back onto it).
    EXPECT_GE(lowestZ, -300.0 - 1e-6);
    sim.runFor(0.5);
    for (int i = 0; i < 3; ++i)
        EXPECT_NEAR(sim.drives().truePosition(i), 0.0, 0.025);
}

TEST(Homing, TheLatheHomesXFirstThenZ) {
    SimulationOptions options;
    options.motion.startHomed = false;
    // The tool at radius 20 (X40 as a diameter), 100 mm towards the chuck.
    TestRun run = runCommands(*machine::loadMachine("lathe"), {}, at(40.0, 0.0, -100.0), options);
    SimulatedMachine& sim = *run.sim;
    const double startX = sim.drives().truePosition(0);
    double lowestX = startX;
    bool zMovedBeforeX = false;
    const std::vector<int> order = homingOrder(sim, 2, [&](SimulatedMachine& s) {
        lowestX = std::min(lowestX, s.drives().truePosition(0));
        if ((s.status().homedMask & 0x1) == 0 &&
            std::fabs(s.drives().truePosition(1) + 100.0) > 1e-6)
            zMovedBeforeX = true;
    });
    EXPECT_EQ(order, (std::vector<int>{0, 1}));  // joints: X, Z
    EXPECT_FALSE(zMovedBeforeX);
    // X only moves out, away from the part and the chuck, to its home at radius 250; Z to +50.
    EXPECT_GE(lowestX, startX - 1e-6);
    sim.runFor(0.5);
    EXPECT_NEAR(sim.drives().truePosition(0), 250.0, 0.025);
    EXPECT_NEAR(sim.drives().truePosition(1), 50.0, 0.025);
}

TEST(Dwell, WaitsTheProgrammedTime) {
    std::vector<canon::Command> program = {cmd(canon::Dwell{0.5}, 1)};
    TestRun run = runCommands(millConfig(), program, Pose{}, {});
    EXPECT_GE(run.report.durationS, 0.5);
    EXPECT_LT(run.report.durationS, 0.6);
}

// What a Klartext probing cycle hands over: a face the drives' tip reaches at X 7.5.
class FaceAtX final : public canon::ProbeSurface {
public:
    bool touches(const Vec3& tip) const override { return tip.x() >= 7.5; }
};

TEST(Probing, AProbeMovesOwnSurfaceReplacesTheMachineFilesBoxForThatMove) {
    // The box of [simulation.probe] (X 0..50, top at workpiece Z -2.5) stays for moves that
    // carry no surface (FAGOR G75); a move with its own surface latches on that one.
    machine::MachineConfig config = millConfig();
    config.probeWorkpiece.enabled = true;
    config.probeWorkpiece.xMinMm = 0.0;
    config.probeWorkpiece.xMaxMm = 50.0;
    config.probeWorkpiece.zMaxMm = -102.5;
    SimulationOptions options;
    options.motion.workOffset[2] = -100.0;
    SimulatedMachine sim(config, options);
    sim.consume(cmd(canon::RapidMove{at(-10, 10, 5)}, 1));
    auto face = std::make_shared<FaceAtX>();
    sim.consume(cmd(canon::ProbeMove{at(20, 10, 5), 300.0, false, face}, 2));
    const interp::WorldSnapshot touch = sim.drain();
    EXPECT_TRUE(touch.probeTriggered);
    EXPECT_NEAR(touch.probePosition[Axis::X], 7.5, 1e-6);
    EXPECT_GT(touch.position[Axis::X], 7.5);  // braked beyond the trigger
    EXPECT_LT(touch.position[Axis::X], 8.0);
    // Back at Z 5 over the box: without a surface the box is touched again.
    sim.consume(cmd(canon::RapidMove{at(10, 10, 5)}, 3));
    sim.consume(cmd(canon::ProbeMove{at(10, 10, -20), 300.0}, 4));
    const interp::WorldSnapshot box = sim.drain();
    EXPECT_TRUE(box.probeTriggered);
    EXPECT_NEAR(box.probePosition[Axis::Z], -2.5, 1e-6);
}

}  // namespace
}  // namespace kerf::motion::test
