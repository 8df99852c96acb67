// Cycles 25 CONTOUR TRAIN and 275 TROCHOIDAL SLOT called directly with hand-made paths: the
// loop centres and pitches of the trochoid, the tool side and direction of the train, and the
// errors. Values derived by hand in the comments.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/cycles/cycle_registry.h"

namespace kerf::cycles {
namespace {

constexpr double kPi = std::numbers::pi;

struct Move {
    bool arc = false;
    Vec3 target;
    Vec2 centre;
    double sweep = 0.0;
};

struct Recorder final : CycleEmitter {
    std::vector<Move> moves;
    void rapid(const Vec3& t) override { moves.push_back({false, t, Vec2::Zero(), 0.0}); }
    void line(const Vec3& t, const Feed&) override {
        moves.push_back({false, t, Vec2::Zero(), 0.0});
    }
    void arc(const Vec3& t, const Vec2& c, double s, const Feed&) override {
        moves.push_back({true, t, c, s});
    }
    void threadMove(const Vec3&, double, double) override {}
    void dwell(double) override {}
    void spindle(canon::SpindleDirection, double) override {}
    void orientSpindle(double) override {}
    void miscFunction(int) override {}

    std::vector<Move> fullCircles() const {
        std::vector<Move> out;
        for (const Move& m : moves) {
            if (m.arc && std::fabs(std::fabs(m.sweep) - 2.0 * kPi) < 1e-9) out.push_back(m);
        }
        return out;
    }
};

std::optional<CycleError> run(int cycle, const CycleValues& v, const CycleContext& ctx,
                              Recorder& out) {
    CyclePath path(out, ctx.start);
    return findCycle(cycle)->expand(v, ctx, path);
}

CycleValues slot(double width, double allowance, double depth) {
    CycleValues v;
    const std::pair<uint16_t, double> values[] = {
        {215, 0.0},   {219, width}, {368, allowance}, {436, 2.0}, {207, 500.0}, {351, 1.0},
        {201, depth}, {202, 5.0},   {206, 150.0},     {338, 0.0}, {385, 500.0}, {200, 2.0},
        {203, 0.0},   {204, 50.0},  {366, 0.0},       {369, 0.0}, {439, 0.0}};
    for (auto [q, value] : values)
        v.set(q, value);
    return v;
}

CycleContext trainContext(std::vector<PlanarSegment> segments) {
    CycleContext ctx;
    ctx.start = {0.0, 0.0, 100.0};
    ctx.tool.radius = 4.0;
    ctx.spindle = canon::SpindleDirection::Clockwise;
    ctx.train.closed = (segments.back().end - segments.front().start).norm() < 1e-9;
    ctx.train.segments = std::move(segments);
    ctx.train.labelCount = 1;
    ctx.train.label = 1;
    return ctx;
}

// Width 10, tool R4, no allowance: loops of radius 1. The line X0..5 with Q436 = 2 has loop
// centres at X0, 2, 4 and 5 (the last at the end, a shorter pitch); climb with M3 turns them
// counter-clockwise, so each starts and ends on the right of the line (Y-1), where the links run.
TEST(TrochoidalSlot, LoopCentresAdvanceByTheInfeedPerRevolution) {
    Recorder out;
    ASSERT_FALSE(run(275, slot(10.0, 0.0, -3.0),
                     trainContext({PlanarSegment::line({0.0, 0.0}, {5.0, 0.0})}), out));
    const std::vector<Move> loops = out.fullCircles();
    const double centres[] = {0.0, 2.0, 4.0, 5.0};
    ASSERT_EQ(loops.size(), 4u);
    for (size_t k = 0; k < 4; ++k) {
        EXPECT_NEAR(loops[k].centre.x(), centres[k], 1e-9);
        EXPECT_NEAR(loops[k].centre.y(), 0.0, 1e-9);
        EXPECT_NEAR(loops[k].sweep, 2.0 * kPi, 1e-9);
        EXPECT_NEAR(loops[k].target.x(), centres[k], 1e-9);
        EXPECT_NEAR(loops[k].target.y(), -1.0, 1e-9);
        EXPECT_NEAR(loops[k].target.z(), -3.0, 1e-9);
    }
}

// Up-cut (Q351 -1) with M3, or climb with M4 (seed 003: the spindle direction counts): clockwise
// loops, links on the left (Y+1).
TEST(TrochoidalSlot, UpCutOrM4TurnsTheLoopsClockwise) {
    CycleValues upCut = slot(10.0, 0.0, -3.0);
    upCut.set(351, -1.0);
    CycleContext m4 = trainContext({PlanarSegment::line({0.0, 0.0}, {5.0, 0.0})});
    m4.spindle = canon::SpindleDirection::CounterClockwise;
    for (const auto& [values, ctx] :
         {std::pair{upCut, trainContext({PlanarSegment::line({0.0, 0.0}, {5.0, 0.0})})},
          std::pair{slot(10.0, 0.0, -3.0), m4}}) {
        Recorder out;
        ASSERT_FALSE(run(275, values, ctx, out));
        const std::vector<Move> loops = out.fullCircles();
        ASSERT_EQ(loops.size(), 4u);
        for (const Move& m : loops) {
            EXPECT_NEAR(m.sweep, -2.0 * kPi, 1e-9);
            EXPECT_NEAR(m.target.y(), 1.0, 1e-9);
        }
    }
}

// A centre line on the arc of radius 10 about the origin from angle 0 over 90 degrees (length
// 5 pi = 15.708): loop centres every 2 mm, i.e. every 0.2 rad, and the last at 90 degrees;
// counter-clockwise loops link on the right of the counter-clockwise line, outside: arcs of
// radius 10 + 1 about the origin turning 0.2 rad (the last 5 pi / 10 - 1.4 rad).
TEST(TrochoidalSlot, LoopsFollowAnArcWithArcLinks) {
    Recorder out;
    ASSERT_FALSE(run(275, slot(10.0, 0.0, -3.0),
                     trainContext({PlanarSegment::arc({10.0, 0.0}, {0.0, 0.0}, kPi / 2.0)}), out));
    const std::vector<Move> loops = out.fullCircles();
    ASSERT_EQ(loops.size(), 9u);  // stations 0, 2, ..., 14 and 5 pi
    for (size_t k = 0; k < loops.size(); ++k) {
        const double angle = k + 1 < loops.size() ? 0.2 * static_cast<double>(k) : kPi / 2.0;
        EXPECT_NEAR(loops[k].centre.x(), 10.0 * std::cos(angle), 1e-9) << k;
        EXPECT_NEAR(loops[k].centre.y(), 10.0 * std::sin(angle), 1e-9) << k;
        EXPECT_NEAR(Vec2(loops[k].target.x(), loops[k].target.y()).norm(), 11.0, 1e-9) << k;
    }
    size_t links = 0;
    for (const Move& m : out.moves) {
        if (!m.arc || std::fabs(std::fabs(m.sweep) - 2.0 * kPi) < 1e-9) continue;
        ++links;
        EXPECT_NEAR(m.centre.norm(), 0.0, 1e-9);
        const double expected = links < 8 ? 0.2 : kPi / 2.0 - 1.4;
        EXPECT_NEAR(m.sweep, expected, 1e-9) << links;
    }
    EXPECT_EQ(links, 8u);
}

TEST(TrochoidalSlot, RefusesWhatTheSeedForbids) {
    const std::vector<PlanarSegment> line{PlanarSegment::line({0.0, 0.0}, {5.0, 0.0})};
    Recorder out;
    // Narrower than the tool (7.5, or 10 less 2 x 1.5; D8), wider than twice its diameter.
    EXPECT_TRUE(run(275, slot(7.5, 0.0, -3.0), trainContext(line), out));
    EXPECT_TRUE(run(275, slot(10.0, 1.5, -3.0), trainContext(line), out));
    auto wide = run(275, slot(16.5, 0.0, -3.0), trainContext(line), out);
    ASSERT_TRUE(wide);
    EXPECT_NE(wide->messageTemplate.find("twice the tool diameter"), std::string::npos);
    // Two labels in cycle 14.
    CycleContext two = trainContext(line);
    two.train.labelCount = 2;
    auto e = run(275, slot(10.0, 0.0, -3.0), two, out);
    ASSERT_TRUE(e);
    EXPECT_NE(e->messageTemplate.find("exactly one"), std::string::npos);
    // A closed centre line starting on a corner of the square 0..20.
    const Vec2 p[] = {{0.0, 0.0}, {20.0, 0.0}, {20.0, 20.0}, {0.0, 20.0}};
    std::vector<PlanarSegment> square;
    for (size_t i = 0; i < 4; ++i)
        square.push_back(PlanarSegment::line(p[i], p[(i + 1) % 4]));
    e = run(275, slot(10.0, 0.0, -3.0), trainContext(square), out);
    ASSERT_TRUE(e);
    EXPECT_NE(e->messageTemplate.find("corner"), std::string::npos);
    // Q202 = 0.
    CycleValues noInfeed = slot(10.0, 0.0, -3.0);
    noInfeed.set(202, 0.0);
    EXPECT_TRUE(run(275, noInfeed, trainContext(line), out));
}

// Q436 = 1e-300 (Q436 = Q1 with Q1 = 10 ^ -300 passes the range check 0 < Q436): the loop
// centres were listed before any move limit, 1e302 of them; `kerf check` ended in std::bad_alloc
// after 1 GB. A pitch that needs more loops than a cycle may have moves is refused first.
TEST(TrochoidalSlot, APitchThatNeedsMoreLoopsThanACycleMayHaveIsAnError) {
    const std::vector<PlanarSegment> line{PlanarSegment::line({0.0, 0.0}, {5.0, 0.0})};
    for (double pitch : {1e-300, 1e-4}) {
        CycleValues v = slot(10.0, 0.0, -3.0);
        v.set(436, pitch);
        Recorder out;
        auto e = run(275, v, trainContext(line), out);
        ASSERT_TRUE(e) << pitch;
        EXPECT_EQ(e->code, "cycle-limit") << pitch;
        EXPECT_TRUE(out.moves.empty()) << pitch;
    }
    // 5 mm at 0.0001 mm need 50,000 loops of two moves each: 100,000, the limit; 0.0002 fits.
    CycleValues fits = slot(10.0, 0.0, -3.0);
    fits.set(436, 2e-4);
    Recorder out;
    EXPECT_FALSE(run(275, fits, trainContext(line), out));
    EXPECT_EQ(out.fullCircles().size(), 25001u);  // centres at 0, 0.0002 ... 5
}

CycleValues train(double allowance, int direction) {
    CycleValues v;
    const std::pair<uint16_t, double> values[] = {
        {1, -4.0},   {3, allowance},  {5, 0.0},  {7, 50.0},   {10, 4.0},   {11, 100.0},
        {12, 400.0}, {15, direction}, {18, 0.0}, {446, 0.01}, {447, 10.0}, {448, 2.0}};
    for (auto [q, value] : values)
        v.set(q, value);
    return v;
}

// The points of the feed moves in the plane at the depth, in order.
std::vector<Vec2> pathAt(const Recorder& out, double w) {
    std::vector<Vec2> points;
    for (const Move& m : out.moves) {
        if (std::fabs(m.target.z() - w) < 1e-9) points.emplace_back(m.target.x(), m.target.y());
    }
    return points;
}

// The line X0 -> X20 with RR (side -1): the tool right of it, R4 + Q3 1 = 5 below (Y-5).
// Climb keeps the tool left of its travel, so it runs the line backwards (X20 -> X0); up-cut
// forwards; a mirror image swaps the two.
TEST(ContourTrain, SideFromRadiusCompensationDirectionFromClimb) {
    CycleContext ctx = trainContext({PlanarSegment::line({0.0, 0.0}, {20.0, 0.0})});
    ctx.train.side = -1;
    struct Case {
        int q15;
        bool mirrored;
        double from;
        double to;
    };
    for (const Case& c :
         {Case{1, false, 20.0, 0.0}, Case{-1, false, 0.0, 20.0}, Case{1, true, 0.0, 20.0}}) {
        CycleContext run25 = ctx;
        run25.mirroredMain = c.mirrored;
        Recorder out;
        ASSERT_FALSE(run(25, train(1.0, c.q15), run25, out));
        const std::vector<Vec2> points = pathAt(out, -4.0);
        ASSERT_EQ(points.size(), 2u) << c.q15;  // plunge, then the line
        EXPECT_NEAR((points[0] - Vec2(c.from, -5.0)).norm(), 0.0, 1e-9) << c.q15;
        EXPECT_NEAR((points[1] - Vec2(c.to, -5.0)).norm(), 0.0, 1e-9) << c.q15;
    }
}

TEST(ContourTrain, Errors) {
    CycleContext ctx = trainContext({PlanarSegment::line({0.0, 0.0}, {20.0, 0.0})});
    Recorder out;
    // No cycle 14.
    CycleContext none = ctx;
    none.train = ContourTrain{};
    EXPECT_TRUE(run(25, train(0.0, 1), none, out));
    // A coarse tool (Q18) that the tool table does not have.
    CycleValues rest = train(0.0, 1);
    rest.set(18, 2.0);
    EXPECT_TRUE(run(25, rest, ctx, out));
    // Cycle 270 gives the side: the subprogram must not program RL/RR.
    CycleValues data;
    data.set(390, 1.0);
    data.set(391, 1.0);
    data.set(392, 3.0);
    data.set(393, 45.0);
    data.set(394, 2.0);
    CycleContext withData = ctx;
    withData.trainData = &data;
    EXPECT_FALSE(run(25, train(0.0, 1), withData, out));
    withData.train.side = 1;
    auto e = run(25, train(0.0, 1), withData, out);
    ASSERT_TRUE(e);
    EXPECT_NE(e->messageTemplate.find("without RL/RR"), std::string::npos);
}

// Rest machining (Q18): the path X0 -> X40 -> Y30 with RL has an inside corner at X40 Y0. The
// coarse R5 ran at 5 beside it (Y5 to X35, X35 up); the fine R2 runs at 2 (Y2 to X38, X38 up).
// Along the straight parts the fine tool stays 3 = 5 - 2 inside the coarse sweep; near the
// corner its distance from the coarse corner (35, 5) is sqrt((x - 35)^2 + 9), above 3 + Q446
// (0.01) for x > 35 + sqrt(3.01^2 - 9) = 35.245153, and likewise for y < 5 - 0.245153. With
// Q448 = 2 the piece runs from X33.245153 Y2 to X38 Y2 to X38 Y6.754847, entered from above.
TEST(ContourTrain, RestMachiningFollowsOnlyWhereTheCoarseToolLeftMaterial) {
    CycleContext ctx = trainContext({PlanarSegment::line({0.0, 0.0}, {40.0, 0.0}),
                                     PlanarSegment::line({40.0, 0.0}, {40.0, 30.0})});
    ctx.train.side = 1;
    ctx.tool.radius = 2.0;
    ctx.toolByNumber = [](int number) {
        ToolInfo coarse;
        coarse.radius = 5.0;
        return number == 7 ? std::optional<ToolInfo>(coarse) : std::nullopt;
    };
    CycleValues v = train(0.0, 1);
    v.set(18, 7.0);
    const double edge = std::sqrt(3.01 * 3.01 - 9.0);
    // 276 the same on a contour programmed at Z-4 (Q1 = 0: one pass on its heights).
    CycleContext ctx3d = ctx;
    ctx3d.train.heights = {{-4.0, -4.0}, {-4.0, -4.0}};
    CycleValues v3d = v;
    v3d.set(1, 0.0);
    for (const int cycle : {25, 276}) {
        Recorder out;
        ASSERT_FALSE(run(cycle, cycle == 25 ? v : v3d, cycle == 25 ? ctx : ctx3d, out)) << cycle;
        const std::vector<Vec2> points = pathAt(out, -4.0);
        ASSERT_EQ(points.size(), 3u) << cycle;
        EXPECT_NEAR((points[0] - Vec2(35.0 + edge - 2.0, 2.0)).norm(), 0.0, 1e-6) << cycle;
        EXPECT_NEAR((points[1] - Vec2(38.0, 2.0)).norm(), 0.0, 1e-9) << cycle;
        EXPECT_NEAR((points[2] - Vec2(38.0, 5.0 - edge + 2.0)).norm(), 0.0, 1e-6) << cycle;
    }
    // A U (Y30 -> Y0 at X0, to X40, up to Y30): rest at both inner corners, pieces from Y6.755
    // to X6.755 and from X33.245 to Y6.755, 26.49 apart along the floor: with Q447 = 10 two
    // pieces, each entered from above (down to the surface Z0 over its start); Q447 = 30 joins
    // them into one, run along the path at the depth.
    CycleContext u = ctx;
    u.train.segments = {PlanarSegment::line({0.0, 30.0}, {0.0, 0.0}),
                        PlanarSegment::line({0.0, 0.0}, {40.0, 0.0}),
                        PlanarSegment::line({40.0, 0.0}, {40.0, 30.0})};
    for (const auto& [connection, entries] : {std::pair{10.0, 2u}, std::pair{30.0, 1u}}) {
        v.set(447, connection);
        Recorder out;
        ASSERT_FALSE(run(25, v, u, out));
        size_t downs = 0;
        for (const Move& m : out.moves)
            downs += std::fabs(m.target.z()) < 1e-9 ? 1u : 0u;
        EXPECT_EQ(downs, entries) << connection;
        const std::vector<Vec2> points = pathAt(out, -4.0);
        ASSERT_FALSE(points.empty());
        EXPECT_NEAR((points.front() - Vec2(2.0, 5.0 - edge + 2.0)).norm(), 0.0, 1e-6);
        EXPECT_NEAR((points.back() - Vec2(38.0, 5.0 - edge + 2.0)).norm(), 0.0, 1e-6);
    }
}

// A closed square X0..20 Y0..20, counter-clockwise from its corner X0 Y0, with RL (the tool
// inside): the coarse R5 ran on the square 5..15, the fine R2 runs on 2..18 from its corner
// (2, 2) nearest the contour's start. Rest at each corner as above, from 5 - 0.245153 before
// the corner to as far after it (Q447 = Q448 = 0). The rest round the start corner is one piece
// from (2, 4.754847) through (2, 2) to (4.754847, 2), run last, not two entered separately: four
// pieces, four entries from above.
TEST(ContourTrain, RestAcrossTheStartOfAClosedContourIsOnePiece) {
    const Vec2 p[] = {{0.0, 0.0}, {20.0, 0.0}, {20.0, 20.0}, {0.0, 20.0}};
    std::vector<PlanarSegment> square;
    for (size_t i = 0; i < 4; ++i)
        square.push_back(PlanarSegment::line(p[i], p[(i + 1) % 4]));
    CycleContext ctx = trainContext(square);
    ctx.train.side = 1;
    ctx.tool.radius = 2.0;
    ctx.toolByNumber = [](int) {
        ToolInfo coarse;
        coarse.radius = 5.0;
        return std::optional<ToolInfo>(coarse);
    };
    CycleValues v = train(0.0, 1);
    v.set(18, 7.0);
    v.set(447, 0.0);
    v.set(448, 0.0);
    Recorder out;
    ASSERT_FALSE(run(25, v, ctx, out));
    size_t downs = 0;
    for (const Move& m : out.moves)
        downs += std::fabs(m.target.z()) < 1e-9 ? 1u : 0u;
    EXPECT_EQ(downs, 4u);
    const double near = 5.0 - std::sqrt(3.01 * 3.01 - 9.0);
    const std::vector<Vec2> points = pathAt(out, -4.0);
    ASSERT_EQ(points.size(), 12u);  // per piece: its start and the ends of its two lines
    EXPECT_NEAR((points[9] - Vec2(2.0, near)).norm(), 0.0, 1e-6);
    EXPECT_NEAR((points[10] - Vec2(2.0, 2.0)).norm(), 0.0, 1e-9);
    EXPECT_NEAR((points[11] - Vec2(near, 2.0)).norm(), 0.0, 1e-6);
    // The other corners in the order of the path: (18, 2), (18, 18), (2, 18).
    EXPECT_NEAR((points[1] - Vec2(18.0, 2.0)).norm(), 0.0, 1e-9);
    EXPECT_NEAR((points[4] - Vec2(18.0, 18.0)).norm(), 0.0, 1e-9);
    EXPECT_NEAR((points[7] - Vec2(2.0, 18.0)).norm(), 0.0, 1e-9);
}

// Cycle 276 follows the heights of a 3-D path: the line X0..20 from Z-1 to Z-3 with R0 is
// followed on itself, the end at Z-3; the tool must come from at or above Q7; one label only.
TEST(ContourTrain3d, FollowsTheHeightsAndRefusesATooLowStart) {
    CycleContext ctx = trainContext({PlanarSegment::line({0.0, 0.0}, {20.0, 0.0})});
    ctx.train.heights = {{-1.0, -3.0}};
    CycleValues v = train(0.0, 1);
    v.set(1, 0.0);
    Recorder out;
    ASSERT_FALSE(run(276, v, ctx, out));
    ASSERT_GE(out.moves.size(), 4u);
    const Move& cut = out.moves[out.moves.size() - 2];
    EXPECT_NEAR((cut.target - Vec3(20.0, 0.0, -3.0)).norm(), 0.0, 1e-9);
    CycleContext low = ctx;
    low.start.z() = 10.0;  // below Q7 = 50
    EXPECT_TRUE(run(276, v, low, out));
    CycleContext two = ctx;
    two.train.labelCount = 2;
    EXPECT_TRUE(run(276, v, two, out));
}

}  // namespace
}  // namespace kerf::cycles
