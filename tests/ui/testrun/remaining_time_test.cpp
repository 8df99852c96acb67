#include <cmath>

#include <gtest/gtest.h>

#include "ui/testrun/test_run_program.h"

namespace kerf::ui {
namespace {

// A rapid of 2 s, a feed move of 4 s and a dwell of 1 s, as the planner timed them.
TestRunProgram rapidFeedDwell() {
    TestRunProgram program;
    auto add = [&](canon::CommandBody body, double endS) {
        canon::Command c;
        c.body = std::move(body);
        program.commands.push_back(std::move(c));
        program.endTimeS.push_back(endS);
    };
    add(canon::RapidMove{}, 2.0);
    add(canon::LinearMove{}, 6.0);
    add(canon::Dwell{1.0}, 7.0);
    program.setOverrideTimes();
    return program;
}

TEST(RemainingTime, TheOverridesStretchTheirOwnMovesOnly) {
    const TestRunProgram program = rapidFeedDwell();
    // At 100 % the planner's time is left as it is.
    EXPECT_DOUBLE_EQ(program.remainingTimeS({0, 0.0}, 1.0, 1.0), 7.0);
    // Feed at 50 %, rapids at 25 %: 2/0.25 + 4/0.5 + 1 (the dwell keeps its time) = 17 s.
    EXPECT_DOUBLE_EQ(program.remainingTimeS({0, 0.0}, 0.5, 0.25), 17.0);
    // Half-way through the feed move: 2/0.5 + 1 = 5 s; the rapid override no longer matters.
    EXPECT_DOUBLE_EQ(program.remainingTimeS({1, 0.5}, 0.5, 0.25), 5.0);
    EXPECT_DOUBLE_EQ(program.remainingTimeS({1, 0.5}, 0.5, 0.0), 5.0);
    // Feed at 150 %: 2/1.5 + 1.
    EXPECT_NEAR(program.remainingTimeS({1, 0.5}, 1.5, 1.0), 2.0 / 1.5 + 1.0, 1e-12);
    // Only the dwell is left: no override changes it; at the end nothing is left.
    EXPECT_DOUBLE_EQ(program.remainingTimeS({2, 0.0}, 0.1, 0.1), 1.0);
    EXPECT_DOUBLE_EQ(program.remainingTimeS({3, 0.0}, 0.1, 0.1), 0.0);
}

TEST(RemainingTime, AFeedOverrideAtZeroLeavesNoEnd) {
    const TestRunProgram program = rapidFeedDwell();
    EXPECT_TRUE(std::isinf(program.remainingTimeS({0, 0.0}, 0.0, 1.0)));
}

}  // namespace
}  // namespace kerf::ui
