#include "core/canon/path_statistics.h"

#include <cmath>

#include <gtest/gtest.h>

namespace kerf::canon {
namespace {

Pose xyz(double x, double y, double z) {
    Pose p;
    p[Axis::X] = x;
    p[Axis::Y] = y;
    p[Axis::Z] = z;
    return p;
}

TEST(PathStatistics, CountsLengthsAndBounds) {
    PathStatistics stats;
    stats.setStart(xyz(0, 0, 0));
    stats.consume({{}, RapidMove{xyz(0, 0, 50)}});
    stats.consume({{}, LinearMove{xyz(30, 40, 50), 600}});  // 50 mm at 10 mm/s
    // Half circle of radius 10 around (30,50) from (30,40) to (30,60), CCW, 3 mm down.
    ArcMove arc{xyz(30, 60, 47), Vec3(30, 50, 0), Plane::XY, 3.14159265358979323846, 600};
    stats.consume({{}, arc});
    stats.consume({{}, Dwell{2}});
    stats.consume({{}, ToolChange{1, "", {}, Axis::Z}});
    EXPECT_EQ(stats.rapidCount(), 1);
    EXPECT_DOUBLE_EQ(stats.rapidLengthMm(), 50);
    EXPECT_EQ(stats.feedCount(), 2);
    const double arcLength = std::hypot(10 * 3.14159265358979323846, 3.0);
    EXPECT_NEAR(stats.feedLengthMm(), 50 + arcLength, 1e-9);
    // The half circle from 270 to 90 degrees passes 0 degrees: x reaches 40.
    EXPECT_NEAR(stats.feedBounds().max[0], 40, 1e-9);
    EXPECT_NEAR(stats.feedBounds().min[2], 47, 1e-9);
    EXPECT_EQ(stats.toolChanges(), 1);
}

// The start of every feed move is in the bounds: the start of the run, a point reached by a rapid
// move, and the end of the previous feed move (counted once, as that move's end).
TEST(PathStatistics, FeedBoundsHoldEveryFeedMoveStart) {
    PathStatistics stats;
    stats.setStart(xyz(-7, 0, 0));
    stats.consume({{}, LinearMove{xyz(0, 0, 0), 600}});
    EXPECT_DOUBLE_EQ(stats.feedBounds().min[0], -7);
    stats.consume({{}, RapidMove{xyz(100, 0, 20)}});
    stats.consume({{}, LinearMove{xyz(50, 0, 20), 600}});
    stats.consume({{}, LinearMove{xyz(50, -3, 20), 600}});
    // An arc right after a rapid move: its start (the rapid's end) counts.
    stats.consume({{}, RapidMove{xyz(0, 90, 0)}});
    ArcMove arc{xyz(0, 80, 0), Vec3(0, 85, 0), Plane::XY, -3.14159265358979323846, 600};
    stats.consume({{}, arc});
    const auto& bounds = stats.feedBounds();
    EXPECT_DOUBLE_EQ(bounds.min[0], -7);
    EXPECT_DOUBLE_EQ(bounds.max[0], 100);  // the rapid's end, where a feed move starts
    EXPECT_DOUBLE_EQ(bounds.min[1], -3);
    EXPECT_DOUBLE_EQ(bounds.max[1], 90);
    EXPECT_DOUBLE_EQ(bounds.max[2], 20);
    EXPECT_EQ(stats.feedCount(), 4);
}

}  // namespace
}  // namespace kerf::canon
