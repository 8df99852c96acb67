#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "canon_builders.h"
#include "motion/kinematics/machine_model.h"
#include "motion/planner/planner.h"
#include "tests/motion/motion_test_run.h"

// A planner that only judges (WorkAreaCheck, `kerf check`) skips smoothing, corners and
// look-ahead: it must refuse exactly what a planning one refuses, at the same block, with the
// same message, and accept the rest. The built-in mill: X +-400, Y +-300, Z -500..+50 mm.
namespace kerf::motion::test {
namespace {

using kerf::test::command;
using kerf::test::pose;

struct Outcome {
    bool accepted = true;
    DiagnosticList diagnostics;
    AxisVector position{};
    size_t items = 0;  // planned items taken from next()
};

Outcome feed(PlannerRole role, const std::vector<canon::Command>& commands) {
    MachineModel model = makeMachineModel(millConfig(), {});
    Planner planner(model, role);
    planner.setPosition(Pose{}.values);
    Outcome out;
    for (const canon::Command& c : commands) {
        if (!planner.add(c)) {
            out.accepted = false;
            break;
        }
        while (planner.next())
            ++out.items;
    }
    planner.flush();
    while (planner.next())
        ++out.items;
    out.diagnostics = planner.diagnostics();
    out.position = planner.position();
    return out;
}

// 200 lines of 0.1 mm along X, zigzagging by 1 µm (a run the smoother fits) and ending at
// (20, 0, 0), then `last` as block 202.
std::vector<canon::Command> shortLinesThen(canon::CommandBody last) {
    std::vector<canon::Command> commands;
    commands.push_back(
        command(canon::SpindleControl{canon::SpindleDirection::Clockwise, 8000.0}, 1));
    for (int i = 1; i <= 200; ++i) {
        commands.push_back(command(canon::LinearMove{pose(0.1 * i, 0.001 * (i % 2), 0.0), 1500.0},
                                   static_cast<uint32_t>(i + 1)));
    }
    commands.push_back(command(std::move(last), 202));
    return commands;
}

void expectSameRefusal(const std::vector<canon::Command>& commands, const char* code,
                       const char* reached) {
    const Outcome planned = feed(PlannerRole::Plan, commands);
    const Outcome judged = feed(PlannerRole::JudgeOnly, commands);
    ASSERT_FALSE(planned.accepted);
    ASSERT_FALSE(judged.accepted);
    ASSERT_EQ(planned.diagnostics.size(), 1u);
    ASSERT_EQ(judged.diagnostics.size(), 1u);
    EXPECT_EQ(judged.diagnostics[0].code, code);
    EXPECT_EQ(judged.diagnostics[0].line, 202u);
    EXPECT_NE(judged.diagnostics[0].message().find(reached), std::string::npos)
        << judged.diagnostics[0].message();
    EXPECT_EQ(judged.diagnostics[0].code, planned.diagnostics[0].code);
    EXPECT_EQ(judged.diagnostics[0].line, planned.diagnostics[0].line);
    EXPECT_EQ(judged.diagnostics[0].message(), planned.diagnostics[0].message());
    EXPECT_EQ(judged.items, 0u);
}

TEST(JudgeOnlyPlanner, RefusesALineBeyondTheSoftLimitAsPlanningDoes) {
    // Z ends at +50: a line to Z 60 is refused, whatever was smoothed before it.
    expectSameRefusal(shortLinesThen(canon::LinearMove{pose(20.0, 0.0, 60.0), 1500.0}),
                      "motion.soft-limit", "60.000");
}

TEST(JudgeOnlyPlanner, RefusesAnArcLeavingTheWorkAreaAsPlanningDoes) {
    // Centre (20, 200), radius 200: the half turn from (20, 0) ends at (20, 400), beyond Y's
    // soft limit of 300.
    canon::ArcMove arc{pose(20.0, 400.0, 0.0), Vec3(20.0, 200.0, 0.0), Plane::XY, -M_PI, 1500.0};
    expectSameRefusal(shortLinesThen(arc), "motion.soft-limit", "300.000");
}

TEST(JudgeOnlyPlanner, RefusesAFeedMoveWithoutFeedAsPlanningDoes) {
    expectSameRefusal(shortLinesThen(canon::LinearMove{pose(30.0, 0.0, 0.0), 0.0}),
                      "motion.no-feed", "202");
}

TEST(JudgeOnlyPlanner, RefusesAnArcWhoseEndIsOffItsCircleAsPlanningDoes) {
    // Centre (30, 0), radius 10 from (20, 0): (40, 5) is 5 mm off the circle.
    canon::ArcMove arc{pose(40.0, 5.0, 0.0), Vec3(30.0, 0.0, 0.0), Plane::XY, -M_PI, 1500.0};
    expectSameRefusal(shortLinesThen(arc), "motion.arc-end", "202");
}

TEST(JudgeOnlyPlanner, AcceptsWhatPlanningAcceptsAndEndsAtTheLastTarget) {
    std::vector<canon::Command> commands = shortLinesThen(
        canon::ArcMove{pose(40.0, 0.0, 0.0), Vec3(30.0, 0.0, 0.0), Plane::XY, -M_PI, 1500.0});
    commands.push_back(command(canon::RapidMove{pose(40.0, 0.0, 40.0)}, 203));
    const Outcome planned = feed(PlannerRole::Plan, commands);
    const Outcome judged = feed(PlannerRole::JudgeOnly, commands);
    EXPECT_TRUE(planned.accepted);
    EXPECT_TRUE(judged.accepted);
    EXPECT_TRUE(judged.diagnostics.empty());
    EXPECT_GT(planned.items, 0u);
    EXPECT_EQ(judged.items, 0u);  // nothing is planned
    EXPECT_DOUBLE_EQ(judged.position[0], 40.0);
    EXPECT_DOUBLE_EQ(judged.position[1], 0.0);
    EXPECT_DOUBLE_EQ(judged.position[2], 40.0);
    EXPECT_EQ(judged.position, planned.position);
}

}  // namespace
}  // namespace kerf::motion::test
