#include "core/canon/value_limits.h"

#include <limits>

#include <gtest/gtest.h>

namespace kerf::canon {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
const double kNan = std::numeric_limits<double>::quiet_NaN();

Pose at(double x, double y, double z) {
    Pose p;
    p[Axis::X] = x;
    p[Axis::Y] = y;
    p[Axis::Z] = z;
    return p;
}

TEST(ValueLimits, EveryNumberOfEveryCommandIsChecked) {
    EXPECT_FALSE(findUnsafeValue(RapidMove{at(1e6, -1e6, 0)}));  // the bound itself is allowed
    EXPECT_FALSE(findUnsafeValue(Message{MessageKind::Info, "text"}));
    ArcMove arc;
    arc.target = at(10, 0, 0);
    arc.center = Vec3(5, 0, 0);
    arc.sweepRad = 3.14;
    arc.feed = 100;
    EXPECT_FALSE(findUnsafeValue(arc));

    struct Case {
        CommandBody body;
        const char* quantity;
    };
    ArcMove nanCentre = arc;
    nanCentre.center[1] = kNan;
    ArcMove hugeSweep = arc;
    hugeSweep.sweepRad = 2e6;
    ToolChange tool;
    tool.geometry.lengthMm = kInf;
    SpindleControl spindle;
    spindle.speedRpm = 1.5e6;
    SpindleSyncedMove thread;
    thread.leadMmPerRev = -kInf;
    StockDefinition blank{StockBox{Vec3(0, 0, 0), Vec3(0, 0, kNan)}};
    const Case cases[] = {
        {RapidMove{at(kInf, 0, 0)}, "X"},
        {LinearMove{at(0, 1e6 + 1, 0), 100}, "Y"},
        {LinearMove{at(0, 0, 0), kNan}, "feed"},
        {nanCentre, "arc centre Y"},
        {hugeSweep, "arc angle"},
        {Dwell{kNan}, "dwell time"},
        {spindle, "spindle speed"},
        {SpindleOrient{-kInf}, "spindle angle"},
        {tool, "tool length"},
        {thread, "lead"},
        {ProbeMove{at(0, 0, 0), kInf, false}, "feed"},
        {blank, "blank Z"},
        {PathTolerance{kNan}, "path tolerance"},
    };
    for (const Case& c : cases) {
        const auto unsafe = findUnsafeValue(c.body);
        ASSERT_TRUE(unsafe) << c.quantity;
        EXPECT_STREQ(unsafe->quantity, c.quantity);
    }
    Pose rotary = at(0, 0, 0);
    rotary[Axis::C] = kNan;
    EXPECT_STREQ(findUnsafeValue(RapidMove{rotary})->quantity, "C");
}

}  // namespace
}  // namespace kerf::canon
