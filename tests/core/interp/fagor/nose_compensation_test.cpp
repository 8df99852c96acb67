#include "core/interp/fagor/nose_compensation.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace kerf::fagor {
namespace {

class Recorder final : public canon::Sink {
public:
    void consume(const canon::Command& c) override { commands.push_back(c); }
    std::vector<canon::Command> commands;
};

Pose at(double z, double x) {
    Pose p{};
    p[Axis::Z] = z;
    p[Axis::X] = x;
    return p;
}

// Z and X of a move's target.
Vec2 target(const canon::Command& c) {
    if (const auto* l = std::get_if<canon::LinearMove>(&c.body))
        return {l->target[Axis::Z], l->target[Axis::X]};
    if (const auto* r = std::get_if<canon::RapidMove>(&c.body))
        return {r->target[Axis::Z], r->target[Axis::X]};
    if (const auto* a = std::get_if<canon::ArcMove>(&c.body))
        return {a->target[Axis::Z], a->target[Axis::X]};
    return {1e9, 1e9};
}

class FagorNoseCompensation : public testing::Test {
protected:
    Recorder out;
    NoseCompensation comp{out};
    Pose position = at(10, 20);

    void SetUp() override {
        comp.reset(position);
        // Nose radius 1, location code F3: the tip is 1 to -Z and 1 to -X of the nose centre;
        // in the ZX plane (abscissa Z, ordinate X) that is (-1, -1).
        comp.setTool(1.0, Vec2(-1.0, -1.0));
        comp.setCompMode(1);
    }
    void move(double z, double x, interp::CompSide side, MoveKind kind = MoveKind::Feed,
              int window = 0) {
        Move m;
        m.geometry = ContourElement::line(Plane::ZX, position, at(z, x));
        m.kind = kind;
        m.feed = 100;
        m.side = side;
        m.collisionWindow = window;
        m.location.line = static_cast<uint32_t>(out.commands.size() + 100);
        ASSERT_FALSE(comp.add(m).has_value());
        position = at(z, x);
    }
    void expectTargets(const std::vector<Vec2>& expected) {
        ASSERT_EQ(out.commands.size(), expected.size());
        for (size_t i = 0; i < expected.size(); ++i) {
            EXPECT_NEAR(target(out.commands[i]).x(), expected[i].x(), 1e-9) << "move " << i;
            EXPECT_NEAR(target(out.commands[i]).y(), expected[i].y(), 1e-9) << "move " << i;
        }
    }
};

constexpr auto kRight = interp::CompSide::Right;
constexpr auto kLeft = interp::CompSide::Left;
constexpr auto kOff = interp::CompSide::None;

// External turning with G42 and F3: the nose centre runs 1 above the cylinder X20 and 1 right of
// the face Z-20 (inside corner: the offsets meet at Z-19 X21); the tip (centre - (1, 1)) stays on
// X20 while turning and on Z-20 while facing. The G00 G40 exit ends the face perpendicular.
TEST_F(FagorNoseCompensation, TurningAndFacingKeepTheTipOnTheContour) {
    move(0, 20, kRight);
    move(-20, 20, kRight);
    move(-20, 30, kRight);
    move(10, 40, kOff, MoveKind::Rapid);
    comp.suspend();
    expectTargets({{-1, 20}, {-20, 20}, {-20, 29}, {10, 40}});
    EXPECT_TRUE(std::holds_alternative<canon::RapidMove>(out.commands.back().body));
}

// An outside corner (turning, then a step down the face): the centre paths X21 and Z-21 meet
// around the corner (Z-20, X20).
TEST_F(FagorNoseCompensation, OutsideCornerArcCompMode1) {
    move(0, 20, kRight);
    move(-20, 20, kRight);
    move(-20, 10, kRight);
    comp.suspend();
    ASSERT_EQ(out.commands.size(), 4u);
    const auto* arc = std::get_if<canon::ArcMove>(&out.commands[2].body);
    ASSERT_NE(arc, nullptr);
    EXPECT_NEAR(arc->center[axisIndex(Axis::Z)], -21.0, 1e-9);  // (-20, 20) + tip
    EXPECT_NEAR(arc->center[axisIndex(Axis::X)], 19.0, 1e-9);
    EXPECT_NEAR(arc->sweepRad, kPi / 2, 1e-9);
    expectTargets({{-1, 20}, {-21, 20}, {-22, 19}, {-22, 9}});
}

// COMPMODE 0 below 300 degrees: tangent extensions of R tan(90/4) and a line between them.
TEST_F(FagorNoseCompensation, OutsideCornerStraightSectionsCompMode0) {
    comp.setCompMode(0);
    move(0, 20, kRight);
    move(-20, 20, kRight);
    move(-20, 10, kRight);
    comp.suspend();
    const double d = std::tan(kPi / 8);
    expectTargets({{-1, 20}, {-21 - d, 20}, {-22, 19 + d}, {-22, 9}});
}

// COMPMODE 2 below 300 degrees: the offsets extended to their intersection (Z-21, X21).
TEST_F(FagorNoseCompensation, OutsideCornerIntersectionCompMode2) {
    comp.setCompMode(2);
    move(0, 20, kRight);
    move(-20, 20, kRight);
    move(-20, 10, kRight);
    comp.suspend();
    expectTargets({{-1, 20}, {-22, 20}, {-22, 9}});
}

// The G40 line is joined as if it were compensated: turning -Z then a G01 G40 exit up to
// (Z-10, X30) is an inside corner; the offsets X21 and the exit line's offset meet before Z-20.
TEST_F(FagorNoseCompensation, CancelWithAFeedLineJoinsTheCorner) {
    move(0, 20, kRight);
    move(-20, 20, kRight);
    move(-10, 30, kOff);
    // The exit goes (10, 10)/|.| from (-20, 20); right of it (offset -1 in left terms) is
    // (-20, 20) + (0.7071, -0.7071); its line is X - Z = 40 - 1.4142; with X = 21: Z = -20.4142
    // + 1.
    const double z = 21.0 - (40.0 - std::sqrt(2.0));
    expectTargets({{-1, 20}, {z - 1, 20}, {-10, 30}});
}

// G01 -> G00 -> G01: the feed element ends perpendicular, the rapid move is not compensated and
// the next feed move starts again from where the tool is.
TEST_F(FagorNoseCompensation, RapidSuspendsCompensation) {
    move(0, 20, kRight);
    move(-20, 20, kRight);
    move(-20, 40, kRight, MoveKind::Rapid);
    move(-30, 40, kRight);
    move(-40, 40, kRight);
    comp.suspend();
    // Restart at (-20, 40): the activation line ends where its offset X41 meets the next one
    // (tangent: the perpendicular at Z-30), tip (-31, 40).
    expectTargets({{-1, 20}, {-21, 20}, {-20, 40}, {-31, 40}, {-41, 40}});
}

// G41 -> G42 without G40: each element on its own side. X19 (left of -Z, ending at Z-20) and
// Z-21 (right of -X, starting at X20) do not cross: an extra segment joins the perpendiculars.
TEST_F(FagorNoseCompensation, SideChangeAtACorner) {
    move(0, 20, kLeft);
    move(-20, 20, kLeft);
    move(-20, 10, kRight);
    comp.suspend();
    expectTargets({{-1, 18}, {-21, 18}, {-22, 19}, {-22, 9}});
}

// Without an intersection, an extra segment joins the perpendiculars: X19 of the -Z element
// ends at (Z-20, X19); the next element (-Z again, now right) starts at (Z-20, X21).
TEST_F(FagorNoseCompensation, SideChangeWithAnExtraSegment) {
    move(0, 20, kLeft);
    move(-20, 20, kLeft);
    move(-40, 20, kRight);
    comp.suspend();
    expectTargets({{-1, 18}, {-21, 18}, {-21, 20}, {-41, 20}});
}

// A groove 1 wide and R 1: the offsets cannot follow it. Without collision detection it is an
// error; with G42 N5 the loops are cut out and the tool rolls over the groove: the arcs around
// (Z-10, X20) and (Z-11, X20) meet at (Z-10.5, X20 + sqrt(0.75)).
TEST_F(FagorNoseCompensation, NarrowGrooveNeedsCollisionDetection) {
    move(0, 20, kRight);
    move(-10, 20, kRight);
    move(-10, 15, kRight);
    Move bottom;
    bottom.geometry = ContourElement::line(Plane::ZX, position, at(-11, 15));
    bottom.side = kRight;
    EXPECT_TRUE(comp.add(bottom).has_value());
}

TEST_F(FagorNoseCompensation, CollisionDetectionRemovesTheLoop) {
    move(0, 20, kRight, MoveKind::Feed, 5);
    move(-10, 20, kRight, MoveKind::Feed, 5);
    move(-10, 15, kRight, MoveKind::Feed, 5);
    move(-11, 15, kRight, MoveKind::Feed, 5);
    move(-11, 20, kRight, MoveKind::Feed, 5);
    move(-20, 20, kRight, MoveKind::Feed, 5);
    move(-20, 30, kRight, MoveKind::Feed, 5);
    comp.suspend();
    EXPECT_FALSE(comp.takeRemovedLoops().empty());
    // The nose centre never drops under the crest X20 + h, the tip (1 lower) under X19 + h.
    const double h = std::sqrt(0.75);
    for (const canon::Command& c : out.commands)
        EXPECT_GE(target(c).y(), 19.0 + h - 1e-9);
    bool crest = false;
    for (const canon::Command& c : out.commands) {
        const Vec2 t = target(c);
        if (std::fabs(t.x() - (-11.5)) < 1e-9 && std::fabs(t.y() - (19.0 + h)) < 1e-9) crest = true;
    }
    EXPECT_TRUE(crest);
}

// Start without plane motion: compensation is taken up where the tool is; the first move in the
// plane goes perpendicular to its start first.
TEST_F(FagorNoseCompensation, StartWithoutPlaneMotion) {
    Move still;
    Pose y = position;
    y[Axis::Y] = 5;
    still.geometry = ContourElement::line(Plane::ZX, position, y);
    still.side = kRight;
    ASSERT_FALSE(comp.add(still).has_value());
    position = y;
    move(0, y[Axis::X], kRight);
    comp.suspend();
    // At (10, 20): perpendicular to the -Z line is X21, tip (9, 20); then along it.
    expectTargets({{10, 20}, {9, 20}, {-1, 20}});
}

}  // namespace
}  // namespace kerf::fagor
