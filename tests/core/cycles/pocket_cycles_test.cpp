// Pocket, slot and stud cycles called directly: parameter effects and errors that the golden
// cases (tests/golden/klartext/cycle_25x_*) and the material checks
// (tests/graphics/pocket_material_test.cpp) do not show. Values derived by hand in the comments.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/cycles/cycle_registry.h"

namespace kerf::cycles {
namespace {

struct Move {
    enum Kind { Rapid, Line, Arc } kind;
    Vec3 target;
    Vec2 centre;
    double sweep;
    Feed feed;
};

struct Recorder final : CycleEmitter {
    std::vector<Move> moves;
    void rapid(const Vec3& t) override {
        moves.push_back({Move::Rapid, t, Vec2::Zero(), 0.0, Feed::rapid()});
    }
    void line(const Vec3& t, const Feed& f) override {
        moves.push_back({Move::Line, t, Vec2::Zero(), 0.0, f});
    }
    void arc(const Vec3& t, const Vec2& c, double s, const Feed& f) override {
        moves.push_back({Move::Arc, t, c, s, f});
    }
    void threadMove(const Vec3&, double, double) override {}
    void dwell(double) override {}
    void spindle(canon::SpindleDirection, double) override {}
    void orientSpindle(double) override {}
    void miscFunction(int) override {}

    double lowest() const {
        double w = 1e9;
        for (const Move& m : moves)
            w = std::min(w, m.target.z());
        return w;
    }
    size_t arcsAt(double w) const {
        size_t n = 0;
        for (const Move& m : moves)
            if (m.kind == Move::Arc && std::fabs(m.target.z() - w) < 1e-9) ++n;
        return n;
    }
};

// Cycle 251: 30 x 20, R5, tool position at the centre, depth 6 in one infeed.
CycleValues pocket251() {
    CycleValues v;
    const std::pair<uint16_t, double> values[] = {
        {215, 0},   {218, 30}, {219, 20}, {220, 5}, {368, 0}, {224, 0},   {367, 0},
        {207, 500}, {351, 1},  {201, -6}, {202, 6}, {369, 0}, {206, 150}, {338, 0},
        {200, 2},   {203, 0},  {204, 20}, {370, 1}, {366, 0}, {385, 300}, {439, 0}};
    for (auto [q, value] : values)
        v.set(q, value);
    return v;
}

CycleContext toolR4() {
    CycleContext ctx;
    ctx.start = {0.0, 0.0, 50.0};
    ctx.tool.radius = 4.0;
    ctx.tool.plungeAngleDeg = 10.0;
    return ctx;
}

std::optional<CycleError> run(int cycle, const CycleValues& v, const CycleContext& ctx,
                              Recorder& out) {
    CyclePath path(out, ctx.start);
    return findCycle(cycle)->expand(v, ctx, path);
}

TEST(PocketCycles, UpCutReversesEveryRing) {
    Recorder climb;
    ASSERT_FALSE(run(251, pocket251(), toolR4(), climb));
    CycleValues v = pocket251();
    v.set(351, -1);
    Recorder upCut;
    ASSERT_FALSE(run(251, v, toolR4(), upCut));
    ASSERT_EQ(climb.arcsAt(-6), 4u);
    ASSERT_EQ(upCut.arcsAt(-6), 4u);
    for (const Move& m : climb.moves)
        if (m.kind == Move::Arc) {
            EXPECT_GT(m.sweep, 0.0);
        }
    for (const Move& m : upCut.moves)
        if (m.kind == Move::Arc) {
            EXPECT_LT(m.sweep, 0.0);
        }
    // A mirror image reverses the path afterwards; the cycle turns it round first to keep the
    // milling type, so the local arcs run as up-cut ones.
    CycleContext mirrored = toolR4();
    mirrored.mirroredMain = true;
    Recorder keep;
    ASSERT_FALSE(run(251, pocket251(), mirrored, keep));
    for (const Move& m : keep.moves)
        if (m.kind == Move::Arc) {
            EXPECT_LT(m.sweep, 0.0);
        }
}

TEST(PocketCycles, RotationAndPositionPlaceThePocket) {
    // Q367 = 3: the tool is at the upper-right corner; Q224 = 90 turns the pocket about it, so
    // the centre (-15, -10) before the rotation lies at (10, -15).
    CycleValues v = pocket251();
    v.set(367, 3);
    v.set(224, 90);
    Recorder out;
    ASSERT_FALSE(run(251, v, toolR4(), out));
    // The vertical plunge at the centre is the first feed move.
    const auto plunge = std::find_if(out.moves.begin(), out.moves.end(),
                                     [](const Move& m) { return m.kind == Move::Line; });
    ASSERT_NE(plunge, out.moves.end());
    EXPECT_NEAR(plunge->target.x(), 10.0, 1e-9);
    EXPECT_NEAR(plunge->target.y(), -15.0, 1e-9);
    EXPECT_NEAR(plunge->target.z(), -6.0, 1e-9);
    // It ends back at the start position.
    EXPECT_NEAR(out.moves.back().target.x(), 0.0, 1e-9);
    EXPECT_NEAR(out.moves.back().target.y(), 0.0, 1e-9);
    EXPECT_NEAR(out.moves.back().target.z(), 20.0, 1e-9);
    // Every arc centre lies on the turned corner centres: x in {10 +- 5}, y in {-15 +- 10}.
    for (const Move& m : out.moves) {
        if (m.kind != Move::Arc) continue;
        EXPECT_NEAR(std::fabs(m.centre.x() - 10.0), 5.0, 1e-9);
        EXPECT_NEAR(std::fabs(m.centre.y() + 15.0), 10.0, 1e-9);
    }
}

TEST(PocketCycles, InfeedsAndTheCuttingLengthLimit) {
    CycleValues v = pocket251();
    v.set(201, -10);
    v.set(202, 4);
    v.set(369, 0.5);
    Recorder out;
    CycleContext ctx = toolR4();
    ASSERT_FALSE(run(251, v, ctx, out));
    // Roughing to 10 - 0.5 = 9.5 at 4: Z-4, Z-8, Z-9.5; the floor finished at Z-10.
    EXPECT_GT(out.arcsAt(-4), 0u);
    EXPECT_GT(out.arcsAt(-8), 0u);
    EXPECT_GT(out.arcsAt(-9.5), 0u);
    EXPECT_GT(out.arcsAt(-10), 0u);
    EXPECT_NEAR(out.lowest(), -10.0, 1e-9);
    // LCUTS 3 < Q202 limits the infeed: Z-3, -6, -9, -9.5.
    ctx.tool.cuttingLength = 3.0;
    Recorder limited;
    ASSERT_FALSE(run(251, v, ctx, limited));
    EXPECT_EQ(limited.arcsAt(-4), 0u);
    for (double w : {-3.0, -6.0, -9.0, -9.5})
        EXPECT_GT(limited.arcsAt(w), 0u) << w;
}

TEST(PocketCycles, MachiningOperationSelectsRoughingOrFinishing) {
    CycleValues v = pocket251();
    v.set(368, 0.5);
    v.set(369, 0.2);
    v.set(215, 1);
    Recorder rough;
    ASSERT_FALSE(run(251, v, toolR4(), rough));
    EXPECT_NEAR(rough.lowest(), -5.8, 1e-9);  // the floor allowance stays
    for (const Move& m : rough.moves)
        EXPECT_FALSE(m.kind != Move::Rapid && m.feed.value == 300.0);
    v.set(215, 2);
    Recorder finish;
    ASSERT_FALSE(run(251, v, toolR4(), finish));
    EXPECT_NEAR(finish.lowest(), -6.0, 1e-9);
    // Only finishing feeds cut (and the plunges at Q206).
    for (const Move& m : finish.moves) {
        if (m.kind == Move::Rapid) continue;
        EXPECT_TRUE(m.feed.value == 300.0 || m.feed.value == 150.0) << m.feed.value;
    }
}

TEST(PocketCycles, ReciprocatingPlungeDescendsAlongTheCore) {
    // 60 x 20 pocket, tool R4 ANGLE 10: the core runs from X-20 to X20 (60 - 8 - 20 = 32 long
    // region of 52 x 12, core (52 - 12) / 2 = 20 either side). Strokes of max(4 D, Q202 /
    // tan 10) = max(16, 34.03) capped at the room 40 + 6 = 46: 34.03 long, dropping 6 mm each.
    CycleValues v = pocket251();
    v.set(218, 60);
    v.set(366, 2);
    Recorder out;
    ASSERT_FALSE(run(251, v, toolR4(), out));
    const double stroke = 6.0 / std::tan(10.0 * std::numbers::pi / 180.0);
    std::vector<Vec3> ramp;
    for (const Move& m : out.moves)
        if (m.kind == Move::Line && m.feed.value == 150.0) ramp.push_back(m.target);
    ASSERT_GE(ramp.size(), 2u);
    EXPECT_NEAR(ramp[0].x(), -20.0 + stroke, 1e-9);
    EXPECT_NEAR(ramp[0].z(), 2.0 - 6.0, 1e-9);
    EXPECT_NEAR(ramp[1].x(), -20.0, 1e-9);
    EXPECT_NEAR(ramp[1].z(), -6.0, 1e-9);
}

TEST(PocketCycles, ErrorsStopBeforeAnyMove) {
    struct Case {
        int cycle;
        uint16_t q;
        double value;
        double toolRadius;
        double angle;
        const char* code;
    };
    const Case cases[] = {
        {251, 219, 7.0, 4.0, 10.0, "cycle-tool"},     // 7 < the tool diameter 8
        {251, 366, 1.0, 4.0, 0.0, "cycle-tool"},      // helix without ANGLE
        {251, 219, 12.0, 4.0, 10.0, "cycle-plunge"},  // helix of radius 4 needs 8 + 8 + 8
        {251, 0, 0.0, 0.0, 10.0, "cycle-tool"},       // tool radius 0
        {251, 201, 5.0, 4.0, 10.0, "cycle-depth"},    // positive depth (displayDepthErr)
    };
    for (const Case& c : cases) {
        CycleValues v = pocket251();
        if (c.q != 0) v.set(c.q, c.value);
        if (c.q == 219 && c.value == 12.0) v.set(366, 1);
        CycleContext ctx = toolR4();
        ctx.tool.radius = c.toolRadius;
        ctx.tool.plungeAngleDeg = c.angle;
        Recorder out;
        auto error = run(c.cycle, v, ctx, out);
        ASSERT_TRUE(error) << c.q << "=" << c.value;
        EXPECT_EQ(error->code, c.code) << c.q << "=" << c.value;
        EXPECT_TRUE(out.moves.empty()) << c.q << "=" << c.value;
    }
}

TEST(PocketCycles, StudsRefuseABlankSmallerThanThePart) {
    CycleValues v;
    const std::pair<uint16_t, double> values[] = {
        {223, 40},  {222, 30}, {368, 0}, {207, 500}, {351, 1}, {201, -5}, {202, 5},
        {206, 150}, {200, 2},  {203, 0}, {204, 20},  {370, 1}, {376, 0}};
    for (auto [q, value] : values)
        v.set(q, value);
    Recorder out;
    auto error = run(257, v, toolR4(), out);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "cycle-parameter");
    EXPECT_TRUE(out.moves.empty());
}

TEST(PocketCycles, ChamferedStudPassesAreArcsAtTheCorners) {
    // 256: 40 x 30 with 5 mm chamfers from a 50 x 40 blank, roughing only, one level: every
    // pass keeps its distance from the octagon, so each corner of the octagon gets an arc of
    // 45 deg about it; the last pass (R4 away) has arcs of radius 4.
    CycleValues v;
    const std::pair<uint16_t, double> values[] = {
        {218, 40}, {424, 50},  {219, 30}, {425, 40}, {220, -5}, {368, 0},   {224, 0},
        {367, 0},  {207, 500}, {351, 1},  {201, -5}, {202, 5},  {206, 150}, {200, 2},
        {203, 0},  {204, 20},  {370, 1},  {437, 0},  {215, 1}};
    for (auto [q, value] : values)
        v.set(q, value);
    Recorder out;
    ASSERT_FALSE(run(256, v, toolR4(), out));
    size_t lastPassArcs = 0;
    for (const Move& m : out.moves) {
        if (m.kind != Move::Arc || std::fabs(m.sweep) > std::numbers::pi / 4.0 + 1e-9) continue;
        EXPECT_NEAR(std::fabs(m.sweep), std::numbers::pi / 4.0, 1e-9);
        EXPECT_LT(m.sweep, 0.0);  // climb round a stud: clockwise
        if (std::fabs((m.target.head<2>() - m.centre).norm() - 4.0) < 1e-9) ++lastPassArcs;
    }
    EXPECT_EQ(lastPassArcs, 8u);
}

TEST(PocketCycles, RectangularStudFromACornerSpiralsInAlongTheDiagonal) {
    // 256 with Q437 = 1: a sharp 60 x 40 stud from an 80 x 60 blank, tool R4, roughing only.
    // Start beside the blank's lower-left corner, the tool's edge 2 mm from both sides:
    // (-(40 + 4 + 2), -(30 + 4 + 2)) = (-46, -36). Margin: the blank corner (40, 30) is
    // sqrt(10^2 + 10^2) = 14.1421 from the stud, so 4 passes (step <= R 4) at 4 + 14.1421 x 3/4,
    // 2/4, 1/4, 0 from it. Each starts where it comes nearest to the start point: on its arc
    // about the stud's corner (-30, -20), on the 45 degree ray towards (-46, -36).
    CycleValues v;
    const std::pair<uint16_t, double> values[] = {
        {218, 60}, {424, 80},  {219, 40}, {425, 60}, {220, 0}, {368, 0},   {224, 0},
        {367, 0},  {207, 500}, {351, 1},  {201, -5}, {202, 5}, {206, 150}, {200, 2},
        {203, 0},  {204, 20},  {370, 1},  {437, 1},  {215, 1}};
    for (auto [q, value] : values)
        v.set(q, value);
    Recorder out;
    ASSERT_FALSE(run(256, v, toolR4(), out));
    ASSERT_FALSE(out.moves.empty());
    EXPECT_NEAR(out.moves[0].target.x(), -46.0, 1e-9);
    EXPECT_NEAR(out.moves[0].target.y(), -36.0, 1e-9);
    const double margin = std::sqrt(200.0);
    const Vec2 corner(-30.0, -20.0);
    const Vec2 diagonal = Vec2(-1.0, -1.0).normalized();
    auto reached = [&](double d, Move::Kind kind) {
        const Vec2 p = corner + d * diagonal;
        for (const Move& m : out.moves) {
            if (m.kind == kind && std::fabs(m.target.z() + 5.0) < 1e-9 &&
                (m.target.head<2>() - p).norm() < 1e-9) {
                return true;
            }
        }
        return false;
    };
    EXPECT_TRUE(reached(4.0 + margin * 0.75, Move::Arc));  // the tangential approach
    for (double d : {4.0 + margin * 0.5, 4.0 + margin * 0.25, 4.0})
        EXPECT_TRUE(reached(d, Move::Line)) << d;  // the stepovers along the ray
    // Q437 = 3: the upper-right corner.
    v.set(437, 3);
    Recorder upperRight;
    ASSERT_FALSE(run(256, v, toolR4(), upperRight));
    EXPECT_NEAR(upperRight.moves[0].target.x(), 46.0, 1e-9);
    EXPECT_NEAR(upperRight.moves[0].target.y(), 36.0, 1e-9);
}

TEST(PocketCycles, PolygonStudStartsBesideTheBlankOnASideNormal) {
    // 258: hexagon, inscribed circle D40, first corner at 30 degrees, so a side normal points
    // along +X; blank D60. Start point: blank radius 30 + R 4 + 2 = 36 beside the centre on that
    // normal; roughing passes from the blank (margin 30 - 20 = 10, 3 passes of 3.3333) in to
    // the inradius 20 + R: the last pass crosses +X at 24.
    CycleValues v;
    const std::pair<uint16_t, double> values[] = {
        {573, 0},   {571, 40}, {222, 60}, {572, 6}, {224, 30},  {220, 0},  {368, 0},
        {207, 500}, {351, 1},  {201, -5}, {202, 5}, {206, 150}, {200, 2},  {203, 0},
        {204, 20},  {370, 1},  {215, 1},  {369, 0}, {338, 0},   {385, 500}};
    for (auto [q, value] : values)
        v.set(q, value);
    Recorder out;
    ASSERT_FALSE(run(258, v, toolR4(), out));
    ASSERT_GE(out.moves.size(), 3u);
    EXPECT_NEAR(out.moves[0].target.x(), 36.0, 1e-9);
    EXPECT_NEAR(out.moves[0].target.y(), 0.0, 1e-9);
    bool lastPass = false;
    for (const Move& m : out.moves) {
        if (m.kind == Move::Line && std::fabs(m.target.x() - 24.0) < 1e-9 &&
            std::fabs(m.target.y()) < 1e-9) {
            lastPass = true;
        }
    }
    EXPECT_TRUE(lastPass);
    v.set(572, 2);
    Recorder none;
    auto error = run(258, v, toolR4(), none);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "cycle-parameter");
    v.set(572, 6);
    v.set(220, -13);  // a chamfer longer than half a side (23.09 / 2)
    error = run(258, v, toolR4(), none);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "cycle-parameter");
    EXPECT_TRUE(none.moves.empty());
}

// 258 with a negative side allowance (spec: allowed): the hexagon of the test above, Q368 -0.5,
// roughing and finishing: the last pass comes to 20 + R4 - 0.5 = 23.5 on +X (the polygon made
// 0.5 smaller), there is no finishing ring at 24, and the start point stays 36 beside the blank.
TEST(PocketCycles, PolygonStudWithNegativeSideAllowanceIsMadeSmaller) {
    const CycleDescriptor* d = findCycle(258);
    ASSERT_NE(d, nullptr);
    const auto q368 = std::find_if(d->parameters.begin(), d->parameters.end(),
                                   [](const ParameterDescriptor& p) { return p.q == 368; });
    ASSERT_NE(q368, d->parameters.end());
    EXPECT_LT(q368->min, -0.5);
    CycleValues v;
    const std::pair<uint16_t, double> values[] = {
        {573, 0},   {571, 40}, {222, 60}, {572, 6}, {224, 30},  {220, 0},  {368, -0.5},
        {207, 500}, {351, 1},  {201, -5}, {202, 5}, {206, 150}, {200, 2},  {203, 0},
        {204, 20},  {370, 1},  {215, 0},  {369, 0}, {338, 0},   {385, 500}};
    for (auto [q, value] : values)
        v.set(q, value);
    Recorder out;
    ASSERT_FALSE(run(258, v, toolR4(), out));
    ASSERT_GE(out.moves.size(), 3u);
    EXPECT_NEAR(out.moves[0].target.x(), 36.0, 1e-9);
    double nearest = 1e9;
    for (const Move& m : out.moves) {
        if (m.kind != Move::Rapid) nearest = std::min(nearest, m.target.head<2>().norm());
    }
    EXPECT_NEAR(nearest, 23.5, 1e-9);
}

// Obsolete finishing cycles 212-215 (docs/cycles.md): centre Q216/Q217 = (50, 40), surface 0,
// set-up clearance 2, 2nd set-up clearance 20, depth -10 in Q202 = 5 mm infeeds, plunge F150,
// milling F500; tool R4 starting at (0, 0, 50).
CycleValues obsoleteFinishing(std::initializer_list<std::pair<uint16_t, double>> shape) {
    CycleValues v;
    const std::pair<uint16_t, double> values[] = {{200, 2},  {201, -10}, {206, 150},
                                                  {202, 5},  {207, 500}, {203, 0},
                                                  {204, 20}, {216, 50},  {217, 40}};
    for (auto [q, value] : values)
        v.set(q, value);
    for (auto [q, value] : shape)
        v.set(q, value);
    return v;
}

// Signed distance of p from the rounded rectangle with half sides a x b and corner radius r
// centred on (50, 40): negative inside.
double fromRoundedRectangle(const Vec3& p, double a, double b, double r) {
    const double qx = std::fabs(p.x() - 50.0) - (a - r);
    const double qy = std::fabs(p.y() - 40.0) - (b - r);
    return std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0) - r;
}

// What every finishing cycle shows (the old manuals' sequence of 213 and 215): first at rapid to
// the 2nd set-up clearance 0 + 20 (down from the start at Z50) and over the centre; the walls at
// -5 and -10 only (two infeeds), each reached at the plunge feed; the end over the centre at the
// 2nd set-up clearance 20. Returns the endpoints of the feed moves at -10.
std::vector<Vec3> checkFinishing(int cycle, const CycleValues& v) {
    Recorder out;
    EXPECT_FALSE(run(cycle, v, toolR4(), out));
    std::vector<Vec3> atFloor;
    if (out.moves.size() < 4) {
        ADD_FAILURE() << cycle << ": " << out.moves.size() << " moves";
        return atFloor;
    }
    EXPECT_EQ(out.moves[0].kind, Move::Rapid);
    EXPECT_TRUE(out.moves[0].target.isApprox(Vec3(0, 0, 20))) << out.moves[0].target.transpose();
    EXPECT_EQ(out.moves[1].kind, Move::Rapid);
    EXPECT_TRUE(out.moves[1].target.isApprox(Vec3(50, 40, 20))) << out.moves[1].target.transpose();
    EXPECT_TRUE(out.moves.back().target.isApprox(Vec3(50, 40, 20)))
        << out.moves.back().target.transpose();
    EXPECT_NEAR(out.lowest(), -10.0, 1e-9);
    std::vector<double> plunges;
    for (const Move& m : out.moves) {
        if (m.kind == Move::Rapid) continue;
        const double w = m.target.z();
        EXPECT_TRUE(std::fabs(w + 5.0) < 1e-9 || std::fabs(w + 10.0) < 1e-9) << w;
        if (m.feed.value == 150.0)
            plunges.push_back(w);
        else
            EXPECT_EQ(m.feed.value, 500.0);
        if (std::fabs(w + 10.0) < 1e-9) atFloor.push_back(m.target);
    }
    EXPECT_EQ(plunges, (std::vector<double>{-5.0, -10.0}));
    return atFloor;
}

// 212: pocket 60 x 40, R5, allowance 0.5: the tool centre stays R4 inside the wall and touches
// it (distance -4 from the finished rounded rectangle).
TEST(ObsoleteCycles, PocketFinishing212FinishesTheWallsAtSize) {
    const auto floor =
        checkFinishing(212, obsoleteFinishing({{218, 60}, {219, 40}, {220, 5}, {221, 0.5}}));
    ASSERT_FALSE(floor.empty());
    double outermost = -1e9;
    for (const Vec3& p : floor)
        outermost = std::max(outermost, fromRoundedRectangle(p, 30, 20, 5));
    EXPECT_NEAR(outermost, -4.0, 1e-6);
}

// An allowance of 0 still finishes the walls (the old cycle does).
TEST(ObsoleteCycles, PocketFinishingWithoutAllowanceStillFinishes) {
    const auto floor =
        checkFinishing(212, obsoleteFinishing({{218, 60}, {219, 40}, {220, 5}, {221, 0}}));
    EXPECT_FALSE(floor.empty());
}

// 213: stud 60 x 40, R5, blank allowance 2: the tool centre stays R4 outside the stud and
// touches it.
TEST(ObsoleteCycles, StudFinishing213FinishesTheWallsAtSize) {
    const auto floor =
        checkFinishing(213, obsoleteFinishing({{218, 60}, {219, 40}, {220, 5}, {221, 2}}));
    ASSERT_FALSE(floor.empty());
    double innermost = 1e9;
    for (const Vec3& p : floor)
        innermost = std::min(innermost, fromRoundedRectangle(p, 30, 20, 5));
    EXPECT_NEAR(innermost, 4.0, 1e-6);
}

// 214: pocket from the blank diameter 46 to 50: the tool centre on radius 25 - 4 = 21 at most.
TEST(ObsoleteCycles, CircularPocketFinishing214FinishesTheWallAtSize) {
    const auto floor = checkFinishing(214, obsoleteFinishing({{222, 46}, {223, 50}}));
    ASSERT_FALSE(floor.empty());
    double outermost = 0.0;
    for (const Vec3& p : floor)
        outermost = std::max(outermost, std::hypot(p.x() - 50, p.y() - 40));
    EXPECT_NEAR(outermost, 21.0, 1e-6);
}

// 215: stud from the blank diameter 54 to 50: the tool centre on radius 25 + 4 = 29 at least.
TEST(ObsoleteCycles, CircularStudFinishing215FinishesTheWallAtSize) {
    const auto floor = checkFinishing(215, obsoleteFinishing({{222, 54}, {223, 50}}));
    ASSERT_FALSE(floor.empty());
    double innermost = 1e9;
    for (const Vec3& p : floor)
        innermost = std::min(innermost, std::hypot(p.x() - 50, p.y() - 40));
    EXPECT_NEAR(innermost, 29.0, 1e-6);
}

// The obsolete cycles run but the menus do not offer them.
TEST(ObsoleteCycles, FoundButNotListed) {
    for (const CycleDescriptor* c : allCycles())
        EXPECT_FALSE(c->obsolete) << c->number;
    for (int n : {210, 211, 212, 213, 214, 215, 230, 231}) {
        ASSERT_NE(findCycle(n), nullptr) << n;
        EXPECT_TRUE(findCycle(n)->obsolete) << n;
        for (const CycleDescriptor* c : allCycles())
            EXPECT_NE(c->number, n);
    }
}

// 230: start (10, 20) at Z-2, 60 x 30 in 4 cuts (stepover 30 / 3 = 10), tool R4 from (0, 0, 50):
// in the plane to R before the start edge (6, 20), down to the set-up clearance -2 + 2 = 0, at
// Q206 to -2; cuts from X6 to 10 + 60 + 4 = 74 and back at Q207, stepovers at Q209; up to 0.
TEST(ObsoleteCycles, MultipassMilling230CutsToAndFro) {
    CycleValues v;
    const std::pair<uint16_t, double> values[] = {{225, 10},  {226, 20}, {227, -2},  {218, 60},
                                                  {219, 30},  {240, 4},  {206, 100}, {207, 400},
                                                  {209, 300}, {200, 2}};
    for (auto [q, value] : values)
        v.set(q, value);
    Recorder out;
    ASSERT_FALSE(run(230, v, toolR4(), out));
    const std::vector<std::pair<Vec3, double>> expected = {
        {{6, 20, 50}, 0},    {{6, 20, 0}, 0},    {{6, 20, -2}, 100}, {{74, 20, -2}, 400},
        {{74, 30, -2}, 300}, {{6, 30, -2}, 400}, {{6, 40, -2}, 300}, {{74, 40, -2}, 400},
        {{74, 50, -2}, 300}, {{6, 50, -2}, 400}, {{6, 50, 0}, 0}};
    ASSERT_EQ(out.moves.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        EXPECT_LT((out.moves[i].target - expected[i].first).norm(), 1e-9)
            << i << ": " << out.moves[i].target.transpose();
        EXPECT_EQ(out.moves[i].kind == Move::Rapid, expected[i].second == 0.0) << i;
        if (expected[i].second != 0.0) {
            EXPECT_EQ(out.moves[i].feed.value, expected[i].second) << i;
        }
    }
}

// One cut: no stepover, the single cut on the starting line.
TEST(ObsoleteCycles, MultipassMillingWithOneCut) {
    CycleValues v;
    const std::pair<uint16_t, double> values[] = {{225, 0},   {226, 0}, {227, 0},   {218, 20},
                                                  {219, 30},  {240, 1}, {206, 100}, {207, 400},
                                                  {209, 300}, {200, 2}};
    for (auto [q, value] : values)
        v.set(q, value);
    Recorder out;
    ASSERT_FALSE(run(230, v, toolR4(), out));
    ASSERT_EQ(out.moves.size(), 5u);
    EXPECT_TRUE((out.moves[3].target - Vec3(24, 0, 0)).norm() < 1e-9);
}

// 210: slot 60 x 10 centred on (50, 40) along X, depth -6 from Z0, Q202 = 4 per to-and-fro
// (2 per stroke), roughing only (Q215 = 1), tool R4 from (0, 0, 50). The end circles' centres
// are 60 / 2 - 10 / 2 = 25 from the centre: X25 and X75. Over X25 at rapid, down to the set-up
// clearance Z2, at Q206 F150 to Z0; strokes to X75 Z-2, X25 Z-4, X75 Z-6, one at the depth back
// to X25; at Q207 F500 to the centre; up to the 2nd set-up clearance Z20.
CycleValues slot210(int operation) {
    CycleValues v;
    const std::pair<uint16_t, double> values[] = {
        {200, 2},  {201, -6}, {207, 500}, {202, 4},  {215, operation}, {203, 0}, {204, 20},
        {216, 50}, {217, 40}, {218, 60},  {219, 10}, {224, 0},         {338, 0}, {206, 150}};
    for (auto [q, value] : values)
        v.set(q, value);
    return v;
}

void expectMoves(const Recorder& out, const std::vector<std::pair<Vec3, double>>& expected) {
    ASSERT_EQ(out.moves.size(), expected.size());
    for (size_t i = 0; i < expected.size(); ++i) {
        EXPECT_LT((out.moves[i].target - expected[i].first).norm(), 1e-9)
            << i << ": " << out.moves[i].target.transpose();
        EXPECT_EQ(out.moves[i].kind == Move::Rapid, expected[i].second == 0.0) << i;
        if (expected[i].second != 0.0) {
            EXPECT_EQ(out.moves[i].feed.value, expected[i].second) << i;
        }
    }
}

TEST(ObsoleteCycles, SlotRoughing210ReciprocatesAlongTheCentreLine) {
    Recorder out;
    ASSERT_FALSE(run(210, slot210(1), toolR4(), out));
    expectMoves(out, {{{25, 40, 50}, 0},
                      {{25, 40, 2}, 0},
                      {{25, 40, 0}, 150},
                      {{75, 40, -2}, 150},
                      {{25, 40, -4}, 150},
                      {{75, 40, -6}, 150},
                      {{25, 40, -6}, 150},
                      {{50, 40, -6}, 500},
                      {{50, 40, 20}, 0}});
}

// Roughing and finishing: the walls are finished, the tool centre reaching 30 - 4 = 26 from the
// centre along the slot (the roughing only 25) and 5 - 4 = 1 across it.
TEST(ObsoleteCycles, Slot210FinishesTheWallsAtSize) {
    Recorder out;
    ASSERT_FALSE(run(210, slot210(0), toolR4(), out));
    double along = 0.0;
    double across = 0.0;
    for (const Move& m : out.moves) {
        if (m.kind == Move::Rapid || std::fabs(m.target.z() + 6.0) > 1e-9) continue;
        along = std::max(along, std::fabs(m.target.x() - 50.0));
        across = std::max(across, std::fabs(m.target.y() - 40.0));
    }
    EXPECT_NEAR(along, 26.0, 1e-6);
    EXPECT_NEAR(across, 1.0, 1e-6);
    EXPECT_NEAR(out.lowest(), -6.0, 1e-9);
}

// A tool wider than the slot is refused.
TEST(ObsoleteCycles, Slot210RefusesAToolWiderThanTheSlot) {
    CycleValues v = slot210(1);
    v.set(219, 7.0);
    Recorder out;
    const auto error = run(210, v, toolR4(), out);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->args.at(0), "210");
}

// 211: pitch circle 100 about (50, 40), from 0 deg over 90 deg, width 10, roughing only: the
// strokes are quarter arcs between (100, 40) and (50, 90), dropping 2 each, as in 210.
TEST(ObsoleteCycles, CircularSlotRoughing211ReciprocatesAlongThePitchCircle) {
    CycleValues v;
    const std::pair<uint16_t, double> values[] = {
        {200, 2},  {201, -6},  {207, 500}, {202, 4}, {215, 1},  {203, 0}, {204, 20}, {216, 50},
        {217, 40}, {244, 100}, {219, 10},  {245, 0}, {248, 90}, {338, 0}, {206, 150}};
    for (auto [q, value] : values)
        v.set(q, value);
    Recorder out;
    ASSERT_FALSE(run(211, v, toolR4(), out));
    expectMoves(out, {{{100, 40, 50}, 0},
                      {{100, 40, 2}, 0},
                      {{100, 40, 0}, 150},
                      {{50, 90, -2}, 150},
                      {{100, 40, -4}, 150},
                      {{50, 90, -6}, 150},
                      {{100, 40, -6}, 150},
                      {{100, 40, 20}, 0}});
    for (size_t i = 3; i < 7; ++i) {
        EXPECT_EQ(out.moves[i].kind, Move::Arc) << i;
        EXPECT_LT((out.moves[i].centre - Vec2(50, 40)).norm(), 1e-9) << i;
    }
}

// Without Q206 (older software; the interpreter passes its default 0) the plunge runs at Q207.
TEST(ObsoleteCycles, SlotWithoutQ206PlungesAtTheMillingFeed) {
    CycleValues v = slot210(1);
    v.set(206, 0.0);
    Recorder out;
    ASSERT_FALSE(run(210, v, toolR4(), out));
    ASSERT_GE(out.moves.size(), 4u);
    EXPECT_EQ(out.moves[2].feed.value, 500.0);
    EXPECT_EQ(out.moves[3].feed.value, 500.0);
}

// 231 (no set-up clearance parameter: the tool clears the surface by its diameter 8): points
// 1 (10, 5, 0), 2 (110, 5, -10), 3 (110, 55, -10), 4 (10, 55, 0), 3 cuts at the fractions 0,
// 1/2, 1 of the edges 1-4 and 2-3: (10, 5, 0)-(110, 5, -10), (110, 30, -10)-(10, 30, 0),
// (10, 55, 0)-(110, 55, -10), joined along the edges; before: over point 1, down to 0 + 8 at
// rapid, at Q207 / 2 = F200 onto it and along the first cut (the old manual's first step at
// half the feed); after: up to the highest point + 8 = Z8.
CycleValues ruledSurface231(int cuts) {
    CycleValues v;
    const std::pair<uint16_t, double> values[] = {
        {225, 10}, {226, 5},   {227, 0},  {228, 110}, {229, 5}, {230, -10},  {231, 110},
        {232, 55}, {233, -10}, {234, 10}, {235, 55},  {236, 0}, {240, cuts}, {207, 400}};
    for (auto [q, value] : values)
        v.set(q, value);
    return v;
}

TEST(ObsoleteCycles, RuledSurface231CutsBetweenTheEdges) {
    Recorder out;
    ASSERT_FALSE(run(231, ruledSurface231(3), toolR4(), out));
    expectMoves(out, {{{10, 5, 50}, 0},
                      {{10, 5, 8}, 0},
                      {{10, 5, 0}, 200},
                      {{110, 5, -10}, 200},
                      {{110, 30, -10}, 400},
                      {{10, 30, 0}, 400},
                      {{10, 55, 0}, 400},
                      {{110, 55, -10}, 400},
                      {{110, 55, 8}, 0}});
}

// A tool below the clearance (Z3 < 0 + 8) rises to it before moving over point 1; one cut runs
// from point 1 to point 2 only, at half the feed.
TEST(ObsoleteCycles, RuledSurface231RisesBeforeMovingOverPoint1) {
    CycleContext ctx = toolR4();
    ctx.start = {0.0, 0.0, 3.0};
    Recorder out;
    ASSERT_FALSE(run(231, ruledSurface231(1), ctx, out));
    expectMoves(out, {{{0, 0, 8}, 0},
                      {{10, 5, 8}, 0},
                      {{10, 5, 0}, 200},
                      {{110, 5, -10}, 200},
                      {{110, 5, 8}, 0}});
}

}  // namespace
}  // namespace kerf::cycles
