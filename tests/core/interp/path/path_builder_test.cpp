#include "core/interp/path/path_builder.h"

#include <cmath>

#include <gtest/gtest.h>

namespace kerf::interp {
namespace {

class Recorder : public canon::Sink {
public:
    void consume(const canon::Command& c) override { commands.push_back(c); }
    std::vector<canon::Command> commands;
};

Pose xy(double x, double y) {
    Pose p;
    p[Axis::X] = x;
    p[Axis::Y] = y;
    return p;
}

PathMove line(const Pose& from, const Pose& to, CompSide side) {
    PathMove m;
    m.geometry = ContourElement::line(Plane::XY, from, to);
    m.feed = 100;
    m.side = side;
    return m;
}

Vec2 endOf(const canon::Command& c) {
    if (const auto* l = std::get_if<canon::LinearMove>(&c.body)) {
        return {l->target[Axis::X], l->target[Axis::Y]};
    }
    const auto& a = std::get<canon::ArcMove>(c.body);
    return {a.target[Axis::X], a.target[Axis::Y]};
}

TEST(PathBuilder, ObtuseOutsideCornerGetsATransitionArc) {
    // A 45 degree right turn with the tool on the left (RL): outside corner.
    Recorder out;
    PathBuilder b(out);
    b.reset(xy(-10, 0));
    b.setToolRadius(1);
    ASSERT_FALSE(b.addMove(line(xy(-10, 0), xy(0, 0), CompSide::Left)));
    ASSERT_FALSE(b.addMove(line(xy(0, 0), xy(10, 0), CompSide::Left)));
    ASSERT_FALSE(b.addMove(line(xy(10, 0), xy(20, -10), CompSide::Left)));
    ASSERT_FALSE(b.addMove(line(xy(20, -10), xy(30, -10), CompSide::None)));
    ASSERT_FALSE(b.flush());
    // activation, line to (10,1), arc around (10,0) to (10,0)+(1/sqrt2)(1,1), diagonal, end.
    ASSERT_EQ(out.commands.size(), 5u);
    EXPECT_NEAR(endOf(out.commands[1]).x(), 10, 1e-12);
    EXPECT_NEAR(endOf(out.commands[1]).y(), 1, 1e-12);
    const auto& arc = std::get<canon::ArcMove>(out.commands[2].body);
    EXPECT_NEAR(arc.sweepRad, -std::atan(1.0), 1e-12);
    EXPECT_NEAR(endOf(out.commands[2]).x(), 10 + std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(endOf(out.commands[2]).y(), std::sqrt(0.5), 1e-12);
    // The last compensated element ends perpendicular to itself at (20,-10) + (1,1)/sqrt2.
    EXPECT_NEAR(endOf(out.commands[3]).x(), 20 + std::sqrt(0.5), 1e-12);
}

TEST(PathBuilder, CommandsKeepTheirPlaceBehindLookAhead) {
    Recorder out;
    PathBuilder b(out);
    b.reset(xy(0, 0));
    ASSERT_FALSE(b.addMove(line(xy(0, 0), xy(10, 0), CompSide::None)));
    b.addCommand(canon::Command{{}, canon::CoolantControl{true, false}});
    ASSERT_FALSE(b.addMove(line(xy(10, 0), xy(10, 10), CompSide::None)));
    ASSERT_FALSE(b.flush());
    ASSERT_EQ(out.commands.size(), 3u);
    EXPECT_TRUE(std::holds_alternative<canon::LinearMove>(out.commands[0].body));
    EXPECT_TRUE(std::holds_alternative<canon::CoolantControl>(out.commands[1].body));
}

TEST(PathBuilder, RoundingNeedsAnElementOnBothSides) {
    Recorder out;
    PathBuilder b(out);
    b.reset(xy(0, 0));
    EXPECT_TRUE(b.addRounding(2, std::nullopt, {}));
    ASSERT_FALSE(b.addMove(line(xy(0, 0), xy(10, 0), CompSide::None)));
    ASSERT_FALSE(b.addRounding(2, std::nullopt, {}));
    EXPECT_TRUE(b.flush());
}

TEST(PathBuilder, ArcsInsideCompensationChangeRadius) {
    // A CCW quarter circle of radius 10 with RL (tool inside): tool path radius 8.
    Recorder out;
    PathBuilder b(out);
    b.reset(xy(10, -5));
    b.setToolRadius(2);
    ASSERT_FALSE(b.addMove(line(xy(10, -5), xy(10, 0), CompSide::Left)));
    PathMove arc;
    arc.geometry = ContourElement::arc(Plane::XY, xy(10, 0), xy(0, 10), {0, 0}, M_PI / 2);
    arc.feed = 100;
    arc.side = CompSide::Left;
    ASSERT_FALSE(b.addMove(arc));
    ASSERT_FALSE(b.flush());
    const auto& a = std::get<canon::ArcMove>(out.commands.back().body);
    EXPECT_NEAR(a.target[Axis::X], 0, 1e-12);
    EXPECT_NEAR(a.target[Axis::Y], 8, 1e-12);
    EXPECT_NEAR(endOf(out.commands[0]).x(), 8, 1e-12);  // activation ends on the offset arc
}

}  // namespace
}  // namespace kerf::interp
