// Expansions called directly (the golden cases cover them through the interpreter): behaviour
// the golden driver cannot switch on, such as displayDepthErr = off, and the move limit.
#include <gtest/gtest.h>

#include "core/cycles/cycle_registry.h"

namespace kerf::cycles {
namespace {

struct Recorder final : CycleEmitter {
    std::vector<Vec3> targets;
    void rapid(const Vec3& t) override { targets.push_back(t); }
    void line(const Vec3& t, const Feed&) override { targets.push_back(t); }
    void arc(const Vec3& t, const Vec2&, double, const Feed&) override { targets.push_back(t); }
    void threadMove(const Vec3& t, double, double) override { targets.push_back(t); }
    void dwell(double) override {}
    void spindle(canon::SpindleDirection, double) override {}
    void orientSpindle(double) override {}
    void miscFunction(int) override {}
};

CycleValues drilling(double depth) {
    CycleValues v;
    v.set(200, 2.0);
    v.set(201, depth);
    v.set(206, 100.0);
    v.set(202, 0.0);
    v.set(203, 0.0);
    v.set(204, 10.0);
    return v;
}

TEST(CycleExpansion, PositiveDepthInvertsWhenAllowed) {
    CycleContext ctx;
    ctx.positiveDepthIsError = false;
    Recorder out;
    CyclePath path(out, ctx.start);
    ASSERT_FALSE(findCycle(200)->expand(drilling(5.0), ctx, path));
    // Set-up clearance below the surface, drilling upwards, end at -max(Q200, Q204).
    ASSERT_EQ(out.targets.size(), 3u);
    EXPECT_DOUBLE_EQ(out.targets[0].z(), -2.0);
    EXPECT_DOUBLE_EQ(out.targets[1].z(), 5.0);
    EXPECT_DOUBLE_EQ(out.targets[2].z(), -10.0);
}

TEST(CycleExpansion, PositiveDepthIsAnErrorByDefault) {
    CycleContext ctx;
    Recorder out;
    CyclePath path(out, ctx.start);
    auto error = findCycle(200)->expand(drilling(5.0), ctx, path);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "cycle-depth");
    EXPECT_TRUE(out.targets.empty());
}

TEST(CycleExpansion, DepthZeroIsNotExecuted) {
    CycleContext ctx;
    Recorder out;
    CyclePath path(out, ctx.start);
    EXPECT_FALSE(findCycle(200)->expand(drilling(0.0), ctx, path));
    EXPECT_TRUE(out.targets.empty());
}

TEST(CycleExpansion, HugeHelixIsRefusedBeforeMoving) {
    CycleContext ctx;
    ctx.tool.radius = 4.0;
    CycleValues v = drilling(-99999.0);
    v.set(334, 0.0001);
    v.set(335, 12.0);
    v.set(351, 1.0);
    Recorder out;
    CyclePath path(out, ctx.start);
    auto error = findCycle(208)->expand(v, ctx, path);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "cycle-limit");
    EXPECT_TRUE(out.targets.empty());
}

TEST(CycleExpansion, ThreadMillingDirectionFollowsTheSpecTables) {
    // Internal: right-hand climb and left-hand up-cut cut towards the surface (Z+).
    CycleValues v;
    v.set(335, 10.0);
    v.set(201, -6.0);
    v.set(253, 750.0);
    v.set(200, 2.0);
    v.set(207, 500.0);
    CycleContext ctx;
    ctx.tool.radius = 3.0;
    for (auto [pitch, climb, upwards] :
         {std::tuple{1.5, 1.0, true}, std::tuple{-1.5, -1.0, true}, std::tuple{1.5, -1.0, false},
          std::tuple{-1.5, 1.0, false}}) {
        v.set(239, pitch);
        v.set(351, climb);
        Recorder out;
        CyclePath path(out, ctx.start);
        ASSERT_FALSE(findCycle(262)->expand(v, ctx, path));
        // targets: clearance, compensating move, approach, one turn, departure, end height
        ASSERT_GE(out.targets.size(), 5u);
        const double turnStart = out.targets[2].z(), turnEnd = out.targets[3].z();
        EXPECT_EQ(turnEnd > turnStart, upwards) << pitch << " " << climb;
    }
}

}  // namespace
}  // namespace kerf::cycles
