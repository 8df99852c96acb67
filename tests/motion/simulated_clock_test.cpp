// The machining clock of the test run: each command's end read off the servo cycle in simulated
// time. Two 10 mm lines at F600 (1 s each plus their ramps) with a setting and a 2 s dwell
// between them.
#include "motion/sim/simulated_clock.h"

#include <gtest/gtest.h>

#include "tests/motion/motion_test_run.h"

namespace kerf::motion::test {
namespace {

canon::Command command(canon::CommandBody body) {
    canon::Command c;
    c.body = std::move(body);
    return c;
}

Pose atX(double x) {
    Pose p;
    p[Axis::X] = x;
    return p;
}

TEST(SimulatedClock, EachCommandEndsWhenTheMachineIsDoneWithIt) {
    SimulatedClock clock(millConfig());
    clock.setStart(Pose{});
    clock.consume(command(canon::LinearMove{atX(10.0), 600.0}));
    clock.consume(command(canon::SetFeedMode{canon::FeedMode::PerMinute}));
    clock.consume(command(canon::Dwell{2.0}));
    clock.consume(command(canon::LinearMove{atX(20.0), 600.0}));
    clock.finish();
    const std::vector<double> ends = clock.endTimesS();
    ASSERT_EQ(ends.size(), 4u);
    const double period = makeMachineModel(millConfig(), {}).periodS;
    // A line: 1 s at the feed, a little more for the ramps (v / A + A / J is 0.007 s here).
    EXPECT_GT(ends[0], 1.0);
    EXPECT_LT(ends[0], 1.05);
    // The setting takes no time; the dwell takes its 2 s (ends are seen to the cycle).
    EXPECT_EQ(ends[1], ends[0]);
    EXPECT_NEAR(ends[2] - ends[1], 2.0, 3.0 * period);
    EXPECT_GT(ends[3] - ends[2], 1.0);
    EXPECT_LT(ends[3] - ends[2], 1.05);
    // The whole program, as the program run counts it: until the filter and the simulated
    // drives stand at the last end point (0.18 s after the interpolator here).
    EXPECT_GE(clock.totalS(), ends[3]);
    EXPECT_LT(clock.totalS() - ends[3], 0.3);
}

}  // namespace
}  // namespace kerf::motion::test
