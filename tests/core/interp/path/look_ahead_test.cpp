// M120 LA n: the compensated path calculated n elements ahead leaves out the contour elements the
// tool cannot follow without cutting into the contour. Expected paths by hand: tool radius 5, the
// tool on the left (RL) of contours running in +X, so above them.
#include <cmath>

#include <gtest/gtest.h>

#include "core/interp/path/path_builder.h"

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

Vec2 endOf(const canon::Command& c) {
    if (const auto* l = std::get_if<canon::LinearMove>(&c.body)) {
        return {l->target[Axis::X], l->target[Axis::Y]};
    }
    const auto& a = std::get<canon::ArcMove>(c.body);
    return {a.target[Axis::X], a.target[Axis::Y]};
}

// A contour given by its corner points; block n is the element ending at point n.
class Contour {
public:
    explicit Contour(int lookAhead) : builder(out) {
        builder.reset(xy(-10, 0));
        builder.setToolRadius(5);
        EXPECT_FALSE(builder.setLookAhead(lookAhead));
    }
    std::optional<PathError> run(const std::vector<Vec2>& points) {
        Pose from = xy(-10, 0);
        for (size_t i = 0; i < points.size(); ++i) {
            const Pose to = xy(points[i].x(), points[i].y());
            PathMove m;
            m.geometry = ContourElement::line(Plane::XY, from, to);
            m.feed = 100;
            m.side = i + 1 < points.size() ? CompSide::Left : CompSide::None;
            m.location.line = static_cast<uint32_t>(i + 1);
            if (auto e = builder.addMove(m)) return e;
            if (i == 3) builder.addCommand(canon::Command{{}, canon::CoolantControl{true, false}});
            from = to;
        }
        return builder.flush();
    }
    Recorder out;
    PathBuilder builder;
};

// Activation at (0,0), an edge along y=0, a notch 2 wide and 3 deep at x=20..22, the edge goes on
// to x=40, R0 to (50,10). Blocks: 1 activation, 2 edge, 3 4 5 the notch, 6 edge, 7 R0.
const std::vector<Vec2> kNotch = {{0, 0}, {20, 0}, {20, -3}, {22, -3}, {22, 0}, {40, 0}, {50, 10}};

TEST(PathLookAhead, WithoutM120TheNotchIsRadiusTooLarge) {
    Contour c(0);
    auto e = c.run(kNotch);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->code, "radius-too-large");
    EXPECT_EQ(e->location.line, 3u);  // the notch's first side is swallowed
}

TEST(PathLookAhead, M120LeavesOutTheNotchAndStaysAtTheRadiusAboveTheEdge) {
    Contour c(3);
    ASSERT_FALSE(c.run(kNotch));
    // Activation ends perpendicular above the edge's start; the offsets y=5 of both edges lie on
    // one line, so the tool runs straight over the notch: no arc, never below y=5.
    const std::vector<Vec2> expected = {{0, 5}, {22, 5}, {40, 5}, {50, 10}};
    std::vector<Vec2> moves;
    for (const canon::Command& cmd : c.out.commands) {
        ASSERT_FALSE(std::holds_alternative<canon::ArcMove>(cmd.body));
        if (std::holds_alternative<canon::LinearMove>(cmd.body)) moves.push_back(endOf(cmd));
    }
    ASSERT_EQ(moves.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        EXPECT_NEAR(moves[i].x(), expected[i].x(), 1e-9) << i;
        EXPECT_NEAR(moves[i].y(), expected[i].y(), 1e-9) << i;
    }
    // The line over the notch belongs to the edge before it (block 2); the coolant command
    // queued after the left-out block 4 comes between it and the edge after the notch.
    ASSERT_EQ(c.out.commands.size(), 5u);
    EXPECT_EQ(c.out.commands[1].location.line, 2u);
    EXPECT_TRUE(std::holds_alternative<canon::CoolantControl>(c.out.commands[2].body));
    EXPECT_EQ(c.out.commands[3].location.line, 6u);
    // R0 ends the look-ahead.
    EXPECT_EQ(c.builder.lookAhead(), 0);
}

TEST(PathLookAhead, TooFewBlocksAheadToSeePastTheNotchIsAnError) {
    for (int n : {1, 2}) {
        Contour c(n);
        auto e = c.run(kNotch);
        ASSERT_TRUE(e) << n;
        EXPECT_EQ(e->code, "radius-too-large");
        EXPECT_EQ(e->location.line, 3u) << n;
    }
}

TEST(PathLookAhead, StepDownSmallerThanTheRadius) {
    // Edge y=0 to x=20, down 2, edge y=-2. The tool rolls over the corner (20,0) until it stands
    // 5 above the lower edge: (x-20)^2 + 3^2 = 5^2 gives x = 24.
    const std::vector<Vec2> step = {{0, 0}, {20, 0}, {20, -2}, {40, -2}, {50, 10}};
    Contour plain(0);
    ASSERT_TRUE(plain.run(step));
    Contour c(1);
    ASSERT_FALSE(c.run(step));
    ASSERT_EQ(c.out.commands.size(), 6u);
    EXPECT_NEAR(endOf(c.out.commands[1]).x(), 20, 1e-9);
    EXPECT_NEAR(endOf(c.out.commands[1]).y(), 5, 1e-9);
    const auto& arc = std::get<canon::ArcMove>(c.out.commands[2].body);
    EXPECT_NEAR(arc.center.x(), 20, 1e-9);
    EXPECT_NEAR(arc.center.y(), 0, 1e-9);
    EXPECT_NEAR(arc.sweepRad, -std::acos(0.6), 1e-9);  // clockwise from (0,5) to (4,3)
    EXPECT_NEAR(endOf(c.out.commands[2]).x(), 24, 1e-9);
    EXPECT_NEAR(endOf(c.out.commands[2]).y(), 3, 1e-9);
    EXPECT_EQ(c.out.commands[2].location.line, 4u);
    EXPECT_NEAR(endOf(c.out.commands[3]).x(), 40, 1e-9);
    EXPECT_NEAR(endOf(c.out.commands[3]).y(), 3, 1e-9);
}

TEST(PathLookAhead, StepUpSmallerThanTheRadius) {
    // Edge y=0 to x=20, up 2, edge y=2. The tool reaches the corner (20,2) at (16,5)
    // ((x-20)^2 + 3^2 = 5^2) and rolls over it to (20,7), 5 above the upper edge.
    const std::vector<Vec2> step = {{0, 0}, {20, 0}, {20, 2}, {40, 2}, {50, 10}};
    Contour plain(0);
    ASSERT_TRUE(plain.run(step));
    Contour c(1);
    ASSERT_FALSE(c.run(step));
    ASSERT_EQ(c.out.commands.size(), 6u);
    EXPECT_NEAR(endOf(c.out.commands[1]).x(), 16, 1e-9);
    EXPECT_NEAR(endOf(c.out.commands[1]).y(), 5, 1e-9);
    const auto& arc = std::get<canon::ArcMove>(c.out.commands[2].body);
    EXPECT_NEAR(arc.center.x(), 20, 1e-9);
    EXPECT_NEAR(arc.center.y(), 2, 1e-9);
    EXPECT_NEAR(arc.sweepRad, -std::acos(0.6), 1e-9);  // clockwise from (-4,3) to (0,5)
    EXPECT_NEAR(endOf(c.out.commands[2]).x(), 20, 1e-9);
    EXPECT_NEAR(endOf(c.out.commands[2]).y(), 7, 1e-9);
    EXPECT_NEAR(endOf(c.out.commands[3]).x(), 40, 1e-9);
    EXPECT_NEAR(endOf(c.out.commands[3]).y(), 7, 1e-9);
}

}  // namespace
}  // namespace kerf::interp
