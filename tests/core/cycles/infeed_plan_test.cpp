// Infeed depths and the Q379 rule, values from the spec's text and tables.
#include <gtest/gtest.h>

#include "core/cycles/drilling/deepened_start.h"
#include "core/cycles/drilling/hole_levels.h"

namespace kerf::cycles {
namespace {

TEST(InfeedPlan, DecrementDownToTheMinimum) {
    // Spec §2 cycle 203: Q202=5, Q212=1, Q205=3 -> 5, 4, 3, 3 ...
    std::vector<double> d;
    ASSERT_FALSE(planInfeeds(203, 15.0, 5.0, 1.0, 3.0, d));
    EXPECT_EQ(d, (std::vector<double>{5.0, 9.0, 12.0, 15.0}));
}

TEST(InfeedPlan, SinglePassWhenThePlungingDepthIsLargerOrZero) {
    std::vector<double> d;
    ASSERT_FALSE(planInfeeds(200, 15.0, 20.0, 0.0, 0.0, d));
    EXPECT_EQ(d, (std::vector<double>{15.0}));
    ASSERT_FALSE(planInfeeds(200, 15.0, 0.0, 0.0, 0.0, d));
    EXPECT_EQ(d, (std::vector<double>{15.0}));
}

TEST(InfeedPlan, AnInfeedDecreasedToNothingDrillsTheRest) {
    std::vector<double> d;
    ASSERT_FALSE(planInfeeds(203, 10.0, 3.0, 2.0, 0.0, d));
    EXPECT_EQ(d, (std::vector<double>{3.0, 4.0, 10.0}));
}

TEST(InfeedPlan, TooManyInfeedsAreAnError) {
    std::vector<double> d;
    EXPECT_TRUE(planInfeeds(200, 99999.0, 0.0001, 0.0, 0.0, d));
}

TEST(DeepenedStart, MatchesTheSpecTable) {
    // Spec §2 "Positioning with Q379" (Q203 = 0, working direction -Z).
    HoleLevels l;
    l.surface = 0.0;
    l.up = 1.0;
    struct Row {
        double q200, q379, start, retract;
    };
    for (Row r : {Row{2, 2, -1.6, -0.4}, Row{2, 5, -4, -3}, Row{2, 100, -98, -98},
                  Row{5, 5, -4, -1}, Row{5, 25, -20, -20}, Row{20, 10, -8, -2}}) {
        l.clearance = r.q200;
        DeepenedStart s = deepenedStart(l, r.q379, r.q200);
        EXPECT_NEAR(s.drillStart, r.start, 1e-12) << r.q200 << " " << r.q379;
        EXPECT_NEAR(s.retract, r.retract, 1e-12) << r.q200 << " " << r.q379;
    }
}

}  // namespace
}  // namespace kerf::cycles
