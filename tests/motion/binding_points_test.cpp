#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "motion/kinematics/machine_model.h"
#include "motion/planner/planner.h"
#include "tests/motion/motion_test_run.h"

// Binding points (the servo cycle meets them with a = 0) on a polyline circle: equal limits
// along a run, and limits only as high as the element before allows, must not bind.
namespace kerf::motion::test {
namespace {

constexpr double kFarVelocity = 1e11;

Pose at(double x, double y) {
    Pose p;
    p[Axis::X] = x;
    p[Axis::Y] = y;
    return p;
}

// gen.py polycircle R50, `seg` mm, `decimals` decimals, F6000, `length` mm.
std::vector<canon::Command> polylineCircle(double length, double seg = 0.005, int decimals = 6,
                                           double feed = 6000.0) {
    const double r = 50.0;
    const double scale = std::pow(10.0, decimals);
    std::vector<canon::Command> commands;
    int count = static_cast<int>(std::lround(length / seg));
    for (int i = 1; i <= count; ++i) {
        double s = i * seg;
        canon::Command c;
        c.location.line = static_cast<uint32_t>(i);
        c.body = canon::LinearMove{at(std::round(r * std::sin(s / r) * scale) / scale,
                                      std::round((r - r * std::cos(s / r)) * scale) / scale),
                                   feed};
        commands.push_back(c);
    }
    return commands;
}

struct BindingCount {
    size_t elements = 0;
    size_t binding = 0;
    double slowest = 1e300;  // lowest velocity bound to before the stop at the end
};

BindingCount countBindingPoints(const std::vector<canon::Command>& commands) {
    MachineModel model = makeMachineModel(millConfig(), {});
    // The look-ahead on thousands of short elements: the polyline as programmed.
    model.options.smoothPolylines = false;
    Planner planner(model);
    planner.setPosition(Pose{}.values);
    std::set<double> binding;
    BindingCount count;
    auto take = [&] {
        while (auto item = planner.next()) {
            if (item->kind != MotionItem::Kind::Element) continue;
            ++count.elements;
            const PathElement& e = item->element;
            if (e.bindVelocity >= kFarVelocity) continue;
            binding.insert(e.bindS);
            if (e.bindVelocity > 0.0) count.slowest = std::min(count.slowest, e.bindVelocity);
        }
    };
    for (const canon::Command& c : commands) {
        EXPECT_TRUE(planner.add(c));
        take();
    }
    planner.flush();
    take();
    count.binding = binding.size();
    return count;
}

std::vector<MotionItem> planned(const std::vector<canon::Command>& commands, bool inPieces) {
    MachineModel model = makeMachineModel(millConfig(), {});
    // The look-ahead on thousands of short elements: the polyline as programmed.
    model.options.smoothPolylines = false;
    Planner planner(model);
    planner.setPosition(Pose{}.values);
    std::vector<MotionItem> items;
    auto take = [&] {
        while (auto item = planner.next())
            items.push_back(*item);
    };
    for (const canon::Command& c : commands) {
        EXPECT_TRUE(planner.add(c));
        if (inPieces) take();
    }
    planner.flush();
    take();
    return items;
}

TEST(BindingPoints, PlanningInPiecesGivesTheLimitsOfOnePass) {
    // Taken item by item, the look-ahead plans many times over a moving window and keeps the
    // curvature-step limits it found final; all at once it plans once. Both must give the same
    // limits (up to the rounding of the window's prefix sums): a limit kept too early would
    // miss steps that came later within its reach.
    for (int decimals : {4, 6}) {
        auto commands = polylineCircle(10.0, 0.005, decimals);
        std::vector<MotionItem> pieces = planned(commands, true);
        std::vector<MotionItem> once = planned(commands, false);
        ASSERT_EQ(pieces.size(), once.size());
        size_t binding = 0;
        for (size_t i = 0; i < once.size(); ++i) {
            const PathElement& a = pieces[i].element;
            const PathElement& b = once[i].element;
            if (a.bindVelocity >= kFarVelocity && b.bindVelocity < kFarVelocity) {
                // Released before anything ahead could bind it: the one pass's binding point
                // (the end) lies beyond its stopping distance from the highest feed (100 mm/s
                // x 1.5 override), at least v^2 / (2 A_t).
                ASSERT_GE(b.bindS - a.sEnd(), 150.0 * 150.0 / (2.0 * a.limits.accel)) << i;
                continue;
            }
            ASSERT_EQ(a.bindS, b.bindS) << i;
            ASSERT_NEAR(a.bindVelocity, b.bindVelocity, 1e-12 * std::fabs(b.bindVelocity)) << i;
            if (b.bindVelocity < kFarVelocity) ++binding;
        }
        EXPECT_GT(binding, once.size() / 2);  // the limits are exercised, not only the end
    }
}

TEST(BindingPoints, FewOnAPolylineCircle) {
    // 20 mm of R50 as 4000 lines: one curve, every vertex alike but for 1e-6 mm of rounding.
    // Before, the share of the tangential limits flipped between neighbours (a binding point at
    // each flip). Measured: 2597 of 6125 element ends before, 58 now (where the share steps down
    // and back up).
    BindingCount count = countBindingPoints(polylineCircle(20.0));
    EXPECT_GT(count.elements, 4000u);
    EXPECT_LE(count.binding, count.elements / 50) << count.binding << " of " << count.elements;
}

TEST(BindingPoints, EqualStepLimitsDoNotBind) {
    // R50 as 0.02 mm lines (6 decimals), F4800 (80 mm/s): every vertex is blended, and every
    // blend's limit is above the feed x 1.5 (120 mm/s), so each element end has that same
    // limit. The servo cycle holds each element at or below its feed anyway: none of them
    // needs to bind. Measured: 817 of 1651 bound when equal limits were binding (at F6000), 2
    // now (R50 at 0.2 mm: 113 of 168, now 1).
    for (double seg : {0.02, 0.2}) {
        BindingCount count = countBindingPoints(polylineCircle(20.0, seg, 6, 4800.0));
        EXPECT_LE(count.binding, 4u) << count.binding << " of " << count.elements;
    }
    // At F6000 (x 1.5: 150 mm/s) the blends with the top share (98 % of the acceleration) have
    // limits of their own between 130 and 152 mm/s (measured), so some bind: above the feed,
    // where they cost nothing at 100 % override.
    for (double seg : {0.02, 0.2}) {
        BindingCount count = countBindingPoints(polylineCircle(20.0, seg, 6));
        EXPECT_GT(count.slowest, 100.0) << count.binding << " of " << count.elements;
    }
}

// A line along X from the origin, a half turn of R10 to the left (tangent), then a tangent line
// of `exitLength` back along X: returns the tangential acceleration planned for that exit line.
double exitLineAccel(double exitLength) {
    std::vector<canon::Command> commands;
    canon::Command line;
    line.location.line = 1;
    line.body = canon::LinearMove{at(10.0, 0.0), 6000.0};
    commands.push_back(line);
    canon::ArcMove arc;
    arc.target = at(10.0, 20.0);
    arc.center = Vec3(10.0, 10.0, 0.0);
    arc.plane = Plane::XY;
    arc.sweepRad = std::acos(-1.0);
    arc.feed = 6000.0;
    canon::Command turn;
    turn.location.line = 2;
    turn.body = arc;
    commands.push_back(turn);
    canon::Command exit;
    exit.location.line = 3;
    exit.body = canon::LinearMove{at(10.0 - exitLength, 20.0), 6000.0};
    commands.push_back(exit);
    std::vector<MotionItem> items = planned(commands, false);
    for (auto it = items.rbegin(); it != items.rend(); ++it) {
        if (it->kind == MotionItem::Kind::Element) return it->element.limits.accel;
    }
    return -1.0;
}

TEST(BindingPoints, ALongElementTakesItsOwnShareWhereTheKeptOneWouldStillBeAccelerating) {
    // Mill: A 2000 mm/s^2 per axis, F6000 = 100 mm/s. The half turn of R10 runs at its feed
    // only at 60 % (1200 mm/s^2; the hand computation is in AShortArcTakesTheShareItsOwnSweep
    // AllowsAtTheFeed). The line after it runs at the feed with either share; its own is 90 %,
    // raised to the top share (98 %, 1960 mm/s^2: a line's limit does not depend on it). At
    // 60 % it would need 100^2 / (2 * 1200) = 4.17 mm to reach the feed from rest: a shorter
    // line takes its own share (a = 0 once where the share changes), a longer one, or one of
    // at most 0.6 mm (vertex noise, blends), keeps the arc's.
    EXPECT_DOUBLE_EQ(exitLineAccel(0.5), 1200.0);
    EXPECT_DOUBLE_EQ(exitLineAccel(2.0), 1960.0);
    EXPECT_DOUBLE_EQ(exitLineAccel(4.0), 1960.0);
    EXPECT_DOUBLE_EQ(exitLineAccel(4.5), 1200.0);
    EXPECT_DOUBLE_EQ(exitLineAccel(10.0), 1200.0);
}

// A line along X, then an arc of R10 turning left by `sweep` from the direction of X: returns
// the tangential acceleration planned for the arc, and checks the run against the limits.
double arcAccel(double sweep) {
    std::vector<canon::Command> commands;
    canon::Command line;
    line.location.line = 1;
    line.body = canon::LinearMove{at(10.0, 0.0), 6000.0};
    commands.push_back(line);
    canon::ArcMove arc;
    arc.target = at(10.0 + 10.0 * std::sin(sweep), 10.0 - 10.0 * std::cos(sweep));
    arc.center = Vec3(10.0, 10.0, 0.0);
    arc.plane = Plane::XY;
    arc.sweepRad = sweep;
    arc.feed = 6000.0;
    canon::Command turn;
    turn.location.line = 2;
    turn.body = arc;
    commands.push_back(turn);
    TestRun run = runCommands(millConfig(), commands, Pose{});
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01) << run.checker->limitSummary();
    for (const MotionItem& item : planned(commands, false)) {
        if (item.kind == MotionItem::Kind::Element && item.element.geometry.curved())
            return item.element.limits.accel;
    }
    return -1.0;
}

TEST(BindingPoints, AShortArcTakesTheShareItsOwnSweepAllowsAtTheFeed) {
    // R10 (k = 0.1) at F6000 (100 mm/s) on the mill (2000 mm/s^2 per axis). Summed over a whole
    // turn (|u| A_t + k v^2 <= A): 90 % gives 44.7 mm/s, 60 % 89.4, 30 % 118.3 >= 95 (the feed
    // within 5 %): 30 %, 600 mm/s^2. The arc runs at its feed with that share, so a higher one
    // is taken where the arc's own sweep allows 98 mm/s. A turn of 0.1 rad from the direction
    // of X reaches only sin <= 0.1: X 1800 cos + 0.1 v^2 sin <= 2000 and Y 1800 sin + 0.1 v^2
    // cos <= 2000 allow 144.7 and 134.9 mm/s at 90 %: 1800 mm/s^2. A half turn reaches every
    // phase, where the peaks add as sqrt((s A)^2 + (k v^2)^2) <= A: 90 % allows
    // sqrt(sqrt(2000^2 - 1800^2) / 0.1) = 93.4 mm/s (below 98), 60 % 126.5: 1200 mm/s^2.
    EXPECT_DOUBLE_EQ(arcAccel(0.1), 1800.0);
    EXPECT_DOUBLE_EQ(arcAccel(std::acos(-1.0)), 1200.0);
}

TEST(BindingPoints, ALineTakesTheTopAccelerationShare) {
    // Mill: 2000 mm/s^2 and 1e6 mm/s^3 per axis. A line's velocity limit is the axes' velocity
    // whatever the tangential share, so it takes the top one: 98 % of the acceleration
    // (1960 mm/s^2), the jerk at the highest share's 90 % (900000 mm/s^3); before, 1800 and
    // 900000. The sampled run reaches that acceleration on X and stays within every limit.
    std::vector<canon::Command> commands;
    canon::Command line;
    line.location.line = 1;
    line.body = canon::LinearMove{at(20.0, 0.0), 6000.0};
    commands.push_back(line);
    std::vector<MotionItem> items = planned(commands, false);
    ASSERT_EQ(items.size(), 1u);
    EXPECT_DOUBLE_EQ(items[0].element.limits.accel, 1960.0);
    EXPECT_DOUBLE_EQ(items[0].element.limits.jerk, 900000.0);
    TestRun run = runCommands(millConfig(), commands, Pose{});
    EXPECT_GT(run.checker->axis(0).accel, 1950.0);
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01) << run.checker->limitSummary();
}

canon::Command halfTurn(uint32_t line, Pose target, Vec3 center, double feed) {
    canon::ArcMove arc;
    arc.target = target;
    arc.center = center;
    arc.plane = Plane::XY;
    arc.sweepRad = std::acos(-1.0);
    arc.feed = feed;
    canon::Command c;
    c.location.line = line;
    c.body = arc;
    return c;
}

TEST(BindingPoints, AnArcEnteredBelowItsCapTakesTheShareThatCrossesItSoonest) {
    // F9000 (150 mm/s) on the mill: 20 mm along X, a half turn of R2, a half turn of R5 turning
    // the same way (tangent), 20 mm back along X. Summed over a whole turn R5 (k = 0.2) gives
    // 60 % 63.2 mm/s, 30 % 83.7, 10 % 94.9, 2 % 99.0 (not 5 % more): 10 %, whose own cap is
    // sqrt(sqrt(2000^2 - 200^2) / 0.2) = 99.75 mm/s. The R2 before it is capped at
    // sqrt(sqrt(2000^2 - 200^2) / 0.5) = 63.09 mm/s, so R5 (15.71 mm) is entered at most that
    // fast. Accelerating from 63.09 to each share's cap, then cruising: 10 % (200 mm/s^2, 99.75)
    // 0.1912 s, 30 % (600, 97.67) 0.1710 s, 60 % (1200, 89.44) 0.1789 s, 90 % (1800, 66.02)
    // 0.2380 s: 30 %, 600 mm/s^2.
    std::vector<canon::Command> commands;
    canon::Command in;
    in.location.line = 1;
    in.body = canon::LinearMove{at(20.0, 0.0), 9000.0};
    commands.push_back(in);
    commands.push_back(halfTurn(2, at(20.0, 4.0), Vec3(20.0, 2.0, 0.0), 9000.0));
    commands.push_back(halfTurn(3, at(20.0, -6.0), Vec3(20.0, -1.0, 0.0), 9000.0));
    canon::Command out;
    out.location.line = 4;
    out.body = canon::LinearMove{at(40.0, -6.0), 9000.0};
    commands.push_back(out);
    size_t arcs = 0;
    for (const MotionItem& item : planned(commands, false)) {
        if (item.kind != MotionItem::Kind::Element || !item.element.geometry.curved()) continue;
        if (std::fabs(item.element.geometry.radius - 5.0) > 1e-9) continue;
        ++arcs;
        EXPECT_DOUBLE_EQ(item.element.limits.accel, 600.0);
    }
    EXPECT_GE(arcs, 1u);
    TestRun run = runCommands(millConfig(), commands, Pose{});
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01) << run.checker->limitSummary();
    EXPECT_LE(run.checker->maxDeviation(), 0.01 * 1.01);
}

TEST(BindingPoints, PolylineCircleReachesTheFeedAsFastAsTheLimitsAllow) {
    // From rest to 100 mm/s along R50 (centripetal 200 mm/s^2). With a = 0 at every element end
    // the start ramped as v ~ s^(1/3) and did not reach the feed within these 20 mm. With the
    // 30 % share of the limits all the way (600 mm/s^2, 3e5 mm/s^3) it takes
    // v / A + A / J = 100 / 600 + 600 / 3e5 = 0.169 s; measured now 0.121 s.
    double reached = -1.0;
    double time = 0.0;
    SimulationOptions options;
    TestRun run = runCommands(millConfig(), polylineCircle(20.0), Pose{}, options,
                              [&](SimulatedMachine& sim, const Sample&, const MotionStatus& s) {
                                  time += sim.model().periodS;
                                  if (reached < 0.0 && s.pathVelocity >= 99.9) reached = time;
                              });
    SCOPED_TRACE(run.checker->limitSummary());
    ASSERT_GT(reached, 0.0) << "never at the feed";
    EXPECT_LE(reached, 0.169);
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
}

}  // namespace
}  // namespace kerf::motion::test
