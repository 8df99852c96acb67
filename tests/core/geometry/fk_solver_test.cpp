// FK contours dimensioned by hand; every expected point is worked out in the comments.
#include "core/geometry/fk/fk_solver.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/geometry/arc_math.h"

namespace kerf::fk {
namespace {

constexpr double kTol = 1e-6;

FkValue abs(double v) {
    return FkValue{v, false, std::nullopt};
}
FkValue relativeTo(int64_t block, double v) {
    return FkValue{v, true, block};
}

void expectPoint(const Vec2& p, double x, double y) {
    EXPECT_NEAR(p.x(), x, kTol);
    EXPECT_NEAR(p.y(), y, kTol);
}

FkElement line() {
    return FkElement{};
}
FkElement arc(FkRotation rotation) {
    FkElement e;
    e.kind = FkKind::Arc;
    e.rotation = rotation;
    return e;
}

// The manual's pocket (seed example C20): a circle r30 about (30,30) with a slot 20 wide at 60
// degrees into a circle r20 whose centre lies 55 from (30,30) at 60 degrees. With u = (cos 60,
// sin 60) and n = (-sin 60, cos 60) the slot sides are the lines 10 n + t u and -10 n + t u;
// they meet the big circle at t = +-sqrt(30^2 - 10^2) = +-28.284271 and the small one at
// t = 55 -+ sqrt(20^2 - 10^2) = 37.679492 and 72.320508.
TEST(FkSolver, SeedPocketWithItsFselectChoices) {
    const Vec2 o(30.0, 30.0), u(0.5, std::sqrt(3.0) / 2.0), n(-std::sqrt(3.0) / 2.0, 0.5);
    FkSolver solver;
    solver.begin({0.0, 30.0}, Vec2(0.0, 1.0));
    FkElement big = arc(FkRotation::Cw);
    big.radius = 30.0;
    big.ccx = abs(30.0);
    big.ccy = abs(30.0);
    FkStep step = solver.add(big, 17, std::nullopt);
    EXPECT_TRUE(step.resolved.empty());
    EXPECT_EQ(step.choices, 0u);

    FkElement side = line();
    side.an = abs(60.0);
    side.pdx = abs(30.0);
    side.pdy = abs(30.0);
    side.distance = 10.0;
    step = solver.add(side, 18, std::nullopt);
    ASSERT_FALSE(step.problem);
    ASSERT_EQ(step.choices, 4u);  // two sides of the slot, two crossings with the circle each
    // Right side first, each side's crossing farther along the line first: 3 is the left side
    // (+10 n) at t = +28.28.
    const Vec2 slotEntry = o + 10.0 * n + 28.284271247 * u;
    expectPoint(solver.alternatives()[2].segment.end, slotEntry.x(), slotEntry.y());
    expectPoint(solver.alternatives()[0].segment.end, (o - 10.0 * n + 28.284271247 * u).x(),
                (o - 10.0 * n + 28.284271247 * u).y());
    step = solver.select(3);
    ASSERT_EQ(step.resolved.size(), 1u);
    EXPECT_EQ(step.resolved[0].tag, 17u);
    expectPoint(step.resolved[0].segment.end, 35.481882, 59.494897);  // (30-8.66+14.14, 30+5+24.49)
    EXPECT_LT(step.resolved[0].segment.sweep, 0.0);

    FkElement small = arc(FkRotation::Cw);
    small.radius = 20.0;
    small.ccpr = abs(55.0);
    small.ccpa = abs(60.0);
    step = solver.add(small, 21, Vec2(30.0, 30.0));
    ASSERT_EQ(step.choices, 2u);
    step = solver.select(2);  // the nearer crossing, t = 37.68
    ASSERT_EQ(step.resolved.size(), 1u);
    EXPECT_EQ(step.resolved[0].tag, 18u);
    expectPoint(step.resolved[0].segment.end, 40.179492, 67.631397);

    FkElement back = line();
    back.an = abs(-120.0);
    back.pdx = abs(30.0);
    back.pdy = abs(30.0);
    back.distance = 10.0;
    step = solver.add(back, 23, Vec2(30.0, 30.0));
    ASSERT_EQ(step.choices, 4u);
    step = solver.select(3);
    ASSERT_EQ(step.resolved.size(), 1u);
    // -10 n + 37.68 u = (57.5, 57.63): straight below the small circle's centre (57.5, 77.63).
    expectPoint(step.resolved[0].segment.end, 57.5, 57.631397);
    EXPECT_NEAR(std::fabs(step.resolved[0].segment.sweep), degToRad(300.0),
                1e-6);  // all but the slot's 60 degrees

    FkElement closing = arc(FkRotation::Cw);
    closing.x = abs(0.0);
    closing.radius = 30.0;
    closing.ccx = abs(30.0);
    closing.ccy = abs(30.0);
    step = solver.add(closing, 25, Vec2(30.0, 30.0));
    ASSERT_EQ(step.choices, 2u);
    step = solver.select(2);
    ASSERT_EQ(step.resolved.size(), 2u);  // the slot side and then the closing arc at once
    expectPoint(step.resolved[0].segment.end, 52.802390, 49.494897);
    expectPoint(step.resolved[1].segment.end, 0.0, 30.0);
    EXPECT_FALSE(solver.finish().problem);
}

// A line along X from the origin, an arc r10 counter-clockwise tangent to it, and a line tangent
// to the arc that runs up through (30,50) at 90 degrees: the arc's centre is 10 above the first
// line and 10 left of x = 30, so (20,10); the arc runs from (20,0) to (30,10). The arc is known
// only by its radius and tangency until the third block arrives.
TEST(FkSolver, TangentArcBetweenLinesKnownOnlyByRadius) {
    FkSolver solver;
    solver.begin({0.0, 0.0}, std::nullopt);
    FkElement first = line();
    first.an = abs(0.0);
    EXPECT_TRUE(solver.add(first, 1, std::nullopt).resolved.empty());
    FkElement round = arc(FkRotation::Ccw);
    round.kind = FkKind::TangentArc;
    round.radius = 10.0;
    EXPECT_TRUE(solver.add(round, 2, std::nullopt).resolved.empty());
    FkElement up = line();
    up.kind = FkKind::TangentLine;
    up.an = abs(90.0);
    up.x = abs(30.0);
    up.y = abs(50.0);
    FkStep step = solver.add(up, 3, std::nullopt);
    ASSERT_FALSE(step.problem);
    ASSERT_EQ(step.resolved.size(), 3u);
    expectPoint(step.resolved[0].segment.end, 20.0, 0.0);
    expectPoint(step.resolved[1].segment.center, 20.0, 10.0);
    expectPoint(step.resolved[1].segment.end, 30.0, 10.0);
    EXPECT_NEAR(step.resolved[1].segment.sweep, kPi / 2.0, 1e-9);
    expectPoint(step.resolved[2].segment.end, 30.0, 50.0);
}

// A line through the start (0,0) and the point P1 (10,10) ends where the next line, y = 20
// through (50,20), begins: (20,20).
TEST(FkSolver, EndPointFromAPointOnTheElement) {
    FkSolver solver;
    solver.begin({0.0, 0.0}, std::nullopt);
    FkElement diagonal = line();
    diagonal.pointsOn[0] = Vec2(10.0, 10.0);
    EXPECT_TRUE(solver.add(diagonal, 1, std::nullopt).resolved.empty());
    FkElement flat = line();
    flat.an = abs(0.0);
    flat.x = abs(50.0);
    flat.y = abs(20.0);
    FkStep step = solver.add(flat, 2, std::nullopt);
    ASSERT_EQ(step.resolved.size(), 2u);
    expectPoint(step.resolved[0].segment.end, 20.0, 20.0);
    expectPoint(step.resolved[1].segment.end, 50.0, 20.0);
}

// D 0: the point lies on the line, so the line runs through (0,0) and (10,10) as above.
TEST(FkSolver, PointAtDistanceZeroLiesOnTheElement) {
    FkSolver solver;
    solver.begin({0.0, 0.0}, std::nullopt);
    FkElement diagonal = line();
    diagonal.pdx = abs(10.0);
    diagonal.pdy = abs(10.0);
    diagonal.distance = 0.0;
    EXPECT_TRUE(solver.add(diagonal, 1, std::nullopt).resolved.empty());
    FkElement flat = line();
    flat.an = abs(0.0);
    flat.x = abs(50.0);
    flat.y = abs(20.0);
    FkStep step = solver.add(flat, 2, std::nullopt);
    EXPECT_EQ(step.choices, 0u);
    ASSERT_EQ(step.resolved.size(), 2u);
    expectPoint(step.resolved[0].segment.end, 20.0, 20.0);
}

// An arc about the origin r10, counter-clockwise from (10,0), left by a tangent line running in
// -X: it touches where the arc runs in -X, at (0,10); the line ends at X-30.
TEST(FkSolver, TangentLineLeavesAnOpenArc) {
    FkSolver solver;
    solver.begin({10.0, 0.0}, std::nullopt);
    FkElement a = arc(FkRotation::Ccw);
    a.ccx = abs(0.0);
    a.ccy = abs(0.0);
    a.radius = 10.0;
    EXPECT_TRUE(solver.add(a, 1, std::nullopt).resolved.empty());
    FkElement leave = line();
    leave.kind = FkKind::TangentLine;
    leave.an = abs(180.0);
    leave.x = abs(-30.0);
    FkStep step = solver.add(leave, 2, std::nullopt);
    ASSERT_EQ(step.resolved.size(), 2u);
    expectPoint(step.resolved[0].segment.end, 0.0, 10.0);
    EXPECT_NEAR(step.resolved[0].segment.sweep, kPi / 2.0, 1e-9);
    expectPoint(step.resolved[1].segment.end, -30.0, 10.0);
}

// Block 12 ends at (30,0). Block 13: polar radius 10 more than block 12's end (30 + 10) at 90
// degrees about the pole (0,0): (0,40). Block 14: centre 30 left of block 12's end, on Y 0: the
// origin; counter-clockwise to (-40,0), a quarter circle. Block 15: 90 degrees more than block
// 12's direction (0), LEN 10: from (-40,0) to (-40,10).
TEST(FkSolver, RelativeDataReferToEarlierBlocks) {
    FkSolver solver;
    solver.begin({0.0, 0.0}, std::nullopt);
    FkElement b12 = line();
    b12.blockNumber = 12;
    b12.x = abs(30.0);
    b12.y = abs(0.0);
    ASSERT_EQ(solver.add(b12, 12, std::nullopt).resolved.size(), 1u);
    FkElement b13 = line();
    b13.blockNumber = 13;
    b13.pr = relativeTo(12, 10.0);
    b13.pa = abs(90.0);
    FkStep step = solver.add(b13, 13, Vec2(0.0, 0.0));
    ASSERT_EQ(step.resolved.size(), 1u);
    expectPoint(step.resolved[0].segment.end, 0.0, 40.0);
    FkElement b14 = arc(FkRotation::Ccw);
    b14.blockNumber = 14;
    b14.ccx = relativeTo(12, -30.0);
    b14.ccy = abs(0.0);
    b14.x = abs(-40.0);
    b14.y = abs(0.0);
    step = solver.add(b14, 14, Vec2(0.0, 0.0));
    ASSERT_EQ(step.resolved.size(), 1u);
    expectPoint(step.resolved[0].segment.center, 0.0, 0.0);
    EXPECT_NEAR(step.resolved[0].segment.sweep, kPi / 2.0, 1e-9);
    FkElement b15 = line();
    b15.an = relativeTo(12, 90.0);
    b15.length = 10.0;
    step = solver.add(b15, 15, Vec2(0.0, 0.0));
    ASSERT_EQ(step.resolved.size(), 1u);
    expectPoint(step.resolved[0].segment.end, -40.0, 10.0);
}

// An arc r20 counter-clockwise from (0,0) to (20,0): the centre is (10,-17.32) (the long way,
// 300 degrees) or (10,17.32) (60 degrees). FSELECT picks either.
TEST(FkSolver, FselectChoosesEitherSolution) {
    for (int choice : {1, 2}) {
        FkSolver solver;
        solver.begin({0.0, 0.0}, std::nullopt);
        FkElement a = arc(FkRotation::Ccw);
        a.radius = 20.0;
        a.x = abs(20.0);
        a.y = abs(0.0);
        FkStep step = solver.add(a, 1, std::nullopt);
        ASSERT_EQ(step.choices, 2u);
        step = solver.select(choice);
        ASSERT_EQ(step.resolved.size(), 1u);
        const PlanarSegment& s = step.resolved[0].segment;
        expectPoint(s.end, 20.0, 0.0);
        const double h = std::sqrt(300.0);
        expectPoint(s.center, 10.0, choice == 1 ? -h : h);
        EXPECT_NEAR(s.sweep, degToRad(choice == 1 ? 300.0 : 60.0), 1e-9);
    }
}

TEST(FkSolver, ClosedContourEndsAtItsStart) {
    FkSolver solver;
    solver.begin({0.0, 0.0}, std::nullopt);
    FkElement a = line();
    a.closeStart = true;
    a.x = abs(40.0);
    a.y = abs(0.0);
    ASSERT_EQ(solver.add(a, 1, std::nullopt).resolved.size(), 1u);
    FkElement b = line();
    b.x = abs(0.0);
    b.y = abs(30.0);
    ASSERT_EQ(solver.add(b, 2, std::nullopt).resolved.size(), 1u);
    FkElement c = line();
    c.closeEnd = true;
    FkStep step = solver.add(c, 3, std::nullopt);
    ASSERT_EQ(step.resolved.size(), 1u);
    expectPoint(step.resolved[0].segment.end, 0.0, 0.0);
}

TEST(FkSolverErrors, UnderDeterminedAtTheEndOfTheSequence) {
    FkSolver solver;
    solver.begin({0.0, 0.0}, std::nullopt);
    FkElement a = line();
    a.an = abs(30.0);
    EXPECT_FALSE(solver.add(a, 7, std::nullopt).problem);
    FkStep step = solver.finish();
    ASSERT_TRUE(step.problem);
    EXPECT_EQ(step.problem->tag, 7u);
    EXPECT_NE(std::string(step.problem->messageTemplate).find("not determined"), std::string::npos);
}

// A line continued tangentially by a line: the joint could be anywhere on it.
TEST(FkSolverErrors, TangentLineAfterAnOpenLineLeavesTheJointOpen) {
    FkSolver solver;
    solver.begin({0.0, 0.0}, std::nullopt);
    FkElement a = line();
    a.an = abs(0.0);
    EXPECT_FALSE(solver.add(a, 1, std::nullopt).problem);
    FkElement b = line();
    b.kind = FkKind::TangentLine;
    b.x = abs(50.0);
    b.y = abs(0.0);
    FkStep step = solver.add(b, 2, std::nullopt);
    EXPECT_FALSE(step.problem);
    EXPECT_TRUE(step.resolved.empty());
    step = solver.finish();
    ASSERT_TRUE(step.problem);
    EXPECT_EQ(step.problem->tag, 1u);
}

TEST(FkSolverErrors, TooManyUndeterminedElementsInARow) {
    FkSolver solver;
    solver.begin({0.0, 0.0}, std::nullopt);
    FkElement a = arc(FkRotation::Ccw);
    a.radius = 10.0;  // no centre, no end: every one waits for the next
    for (size_t tag = 1; tag <= FkSolver::kMaxWaiting; ++tag)
        EXPECT_FALSE(solver.add(a, tag, std::nullopt).problem);
    FkStep step = solver.add(a, 9, std::nullopt);
    ASSERT_TRUE(step.problem);
    EXPECT_EQ(step.problem->tag, 1u);
}

TEST(FkSolverErrors, ContradictionAtTheBlockThatMakesIt) {
    FkSolver solver;
    solver.begin({0.0, 0.0}, std::nullopt);
    FkElement a = line();
    a.x = abs(10.0);
    a.y = abs(0.0);
    a.an = abs(90.0);  // (0,0) to (10,0) does not run at 90 degrees
    FkStep step = solver.add(a, 4, std::nullopt);
    ASSERT_TRUE(step.problem);
    EXPECT_EQ(step.problem->tag, 4u);
    EXPECT_NE(std::string(step.problem->messageTemplate).find("contradict"), std::string::npos);

    // A circle about (100,0) r10 never meets a line along X at y = 50.
    FkSolver second;
    second.begin({0.0, 50.0}, std::nullopt);
    FkElement l = line();
    l.an = abs(0.0);
    EXPECT_FALSE(second.add(l, 1, std::nullopt).problem);
    FkElement c = arc(FkRotation::Ccw);
    c.ccx = abs(100.0);
    c.ccy = abs(0.0);
    c.radius = 10.0;
    step = second.add(c, 2, std::nullopt);
    ASSERT_TRUE(step.problem);
    EXPECT_EQ(step.problem->tag, 2u);
}

TEST(FkSolverErrors, FselectMissingOutOfRangeOrWithoutChoice) {
    FkSolver solver;
    solver.begin({0.0, 0.0}, std::nullopt);
    EXPECT_TRUE(solver.select(1).problem->atCaller);
    FkElement a = arc(FkRotation::Ccw);
    a.radius = 20.0;
    a.x = abs(20.0);
    a.y = abs(0.0);
    ASSERT_EQ(solver.add(a, 5, std::nullopt).choices, 2u);
    FkStep step = solver.select(3);
    ASSERT_TRUE(step.problem);
    EXPECT_TRUE(step.problem->atCaller);
    EXPECT_EQ(step.problem->args, (std::vector<std::string>{"3", "2"}));
    step = solver.add(line(), 6, std::nullopt);
    ASSERT_TRUE(step.problem);
    EXPECT_EQ(step.problem->tag, 5u);
    EXPECT_NE(std::string(step.problem->messageTemplate).find("FSELECT"), std::string::npos);
    step = solver.finish();
    ASSERT_TRUE(step.problem);
    EXPECT_EQ(step.problem->tag, 5u);
}

TEST(FkSolverErrors, BadReferencesPolarWithoutPoleAndBadValues) {
    FkSolver solver;
    solver.begin({0.0, 0.0}, std::nullopt);
    FkElement a = line();
    a.x = relativeTo(99, 5.0);
    FkStep step = solver.add(a, 1, std::nullopt);
    ASSERT_TRUE(step.problem);
    EXPECT_EQ(step.problem->args, std::vector<std::string>{"99"});

    FkElement b = line();
    b.pr = abs(10.0);
    b.pa = abs(0.0);
    step = solver.add(b, 2, std::nullopt);
    ASSERT_TRUE(step.problem);
    EXPECT_NE(std::string(step.problem->messageTemplate).find("FPOL"), std::string::npos);

    FkElement c = arc(FkRotation::Cw);
    c.radius = -5.0;
    EXPECT_TRUE(solver.add(c, 3, std::nullopt).problem);

    FkElement d = line();
    d.closeEnd = true;
    step = solver.add(d, 4, std::nullopt);
    ASSERT_TRUE(step.problem);
    EXPECT_NE(std::string(step.problem->messageTemplate).find("CLSD+"), std::string::npos);
}

// A tangent line between two arcs given by centre and radius, nothing else. Circle A about
// (0,0) r10 counter-clockwise from (-10,0); circle B about (30,0) r10 counter-clockwise to
// (40,0). Equal radii, same rotation: the line is parallel to the centre line, on the side where
// both run in +X: y = -10, from (0,-10) to (30,-10). A turns 90 degrees to it, B 90 from it.
TEST(FkSolver, TangentLineBetweenTwoArcsWithTheSameRotation) {
    FkSolver solver;
    solver.begin({-10.0, 0.0}, std::nullopt);
    FkElement a = arc(FkRotation::Ccw);
    a.ccx = abs(0.0);
    a.ccy = abs(0.0);
    a.radius = 10.0;
    EXPECT_TRUE(solver.add(a, 1, std::nullopt).resolved.empty());
    FkElement between = line();
    between.kind = FkKind::TangentLine;
    EXPECT_TRUE(solver.add(between, 2, std::nullopt).resolved.empty());
    FkElement b = arc(FkRotation::Ccw);
    b.kind = FkKind::TangentArc;
    b.ccx = abs(30.0);
    b.ccy = abs(0.0);
    b.radius = 10.0;
    b.x = abs(40.0);
    b.y = abs(0.0);
    FkStep step = solver.add(b, 3, std::nullopt);
    ASSERT_FALSE(step.problem) << step.problem->messageTemplate;
    EXPECT_EQ(step.choices, 0u);
    ASSERT_EQ(step.resolved.size(), 3u);
    expectPoint(step.resolved[0].segment.end, 0.0, -10.0);
    EXPECT_NEAR(step.resolved[0].segment.sweep, kPi / 2.0, 1e-9);
    expectPoint(step.resolved[1].segment.start, 0.0, -10.0);
    expectPoint(step.resolved[1].segment.end, 30.0, -10.0);
    expectPoint(step.resolved[2].segment.end, 40.0, 0.0);
    EXPECT_NEAR(step.resolved[2].segment.sweep, kPi / 2.0, 1e-9);
}

// The crossed tangent: A about (0,0) r10 counter-clockwise, B about (40,0) r10 clockwise. A line
// of direction (cos t, sin t) touching both with their directions of travel satisfies
// sin(0 - t) = (-10 - 10) / 40, t = 30 degrees (150 degrees runs backwards). It leaves A at
// (0,0) - 10 (-sin 30, cos 30) = (5, -8.660254) and enters B at (40,0) + 10 (-sin 30, cos 30) =
// (35, 8.660254). A turns from 180 to 300 degrees (+120), B from 120 to 0 degrees (-120) to
// (50,0).
TEST(FkSolver, CrossedTangentLineBetweenArcsOfOppositeRotation) {
    FkSolver solver;
    solver.begin({-10.0, 0.0}, std::nullopt);
    FkElement a = arc(FkRotation::Ccw);
    a.ccx = abs(0.0);
    a.ccy = abs(0.0);
    a.radius = 10.0;
    EXPECT_TRUE(solver.add(a, 1, std::nullopt).resolved.empty());
    FkElement between = line();
    between.kind = FkKind::TangentLine;
    EXPECT_TRUE(solver.add(between, 2, std::nullopt).resolved.empty());
    FkElement b = arc(FkRotation::Cw);
    b.kind = FkKind::TangentArc;
    b.ccx = abs(40.0);
    b.ccy = abs(0.0);
    b.radius = 10.0;
    b.x = abs(50.0);
    b.y = abs(0.0);
    FkStep step = solver.add(b, 3, std::nullopt);
    ASSERT_FALSE(step.problem) << step.problem->messageTemplate;
    EXPECT_EQ(step.choices, 0u);
    ASSERT_EQ(step.resolved.size(), 3u);
    const double h = 10.0 * std::sqrt(3.0) / 2.0;
    expectPoint(step.resolved[0].segment.end, 5.0, -h);
    EXPECT_NEAR(step.resolved[0].segment.sweep, 2.0 * kPi / 3.0, 1e-9);
    expectPoint(step.resolved[1].segment.end, 35.0, h);
    EXPECT_NEAR(step.resolved[1].segment.length(), std::sqrt(1200.0), 1e-9);
    expectPoint(step.resolved[2].segment.end, 50.0, 0.0);
    EXPECT_NEAR(step.resolved[2].segment.sweep, -2.0 * kPi / 3.0, 1e-9);
}

// An arc r10 counter-clockwise from (0,0) whose circle passes 5 from PD (0,25), ending on X+10.
// Its centre lies 10 from the start and 10 + 5 = 15 from PD: x^2 + y^2 = 100 and
// x^2 + (y - 25)^2 = 225 give y = 10, x = 0; inside (5 from PD) there is none (y = 14 > 10). The
// circle about (0,10) meets X 10 at (10,10): a quarter turn.
TEST(FkSolver, ArcFromAPointAtDistanceD) {
    FkSolver solver;
    solver.begin({0.0, 0.0}, std::nullopt);
    FkElement a = arc(FkRotation::Ccw);
    a.radius = 10.0;
    a.pdx = abs(0.0);
    a.pdy = abs(25.0);
    a.distance = 5.0;
    a.x = abs(10.0);
    FkStep step = solver.add(a, 1, std::nullopt);
    ASSERT_FALSE(step.problem) << step.problem->messageTemplate;
    EXPECT_EQ(step.choices, 0u);
    ASSERT_EQ(step.resolved.size(), 1u);
    expectPoint(step.resolved[0].segment.center, 0.0, 10.0);
    expectPoint(step.resolved[0].segment.end, 10.0, 10.0);
    EXPECT_NEAR(step.resolved[0].segment.sweep, kPi / 2.0, 1e-9);
}

}  // namespace
}  // namespace kerf::fk

namespace kerf::fk {
namespace {

// Two FCT in a row known only by their radius: the contour leaves (0,0) along +X, turns left on
// r10 (centre c1 = (0,10)), right on r15, and goes on along y = 45 to (100,45). The second
// centre lies 15 below that line (y = 30) and 10 + 15 = 25 from c1: x = +-sqrt(25^2 - 20^2) =
// +-15. For c2 = (15,30) the arcs touch at c1 + 10 (15,20)/25 = (6,18): the first turns from -90
// to atan2(8,6) = 53.130102 degrees (+143.130102), the second from atan2(-12,-9) = 233.130102
// down to 90 degrees (-143.130102) and ends on the line at (15,45). For c2 = (-15,30) they touch
// at (-6,18) and turn +-216.869898 degrees.
TEST(FkSolver, TwoTangentArcsKnownOnlyByTheirRadius) {
    auto feed = [](FkSolver& solver) {
        solver.begin({0.0, 0.0}, Vec2{1.0, 0.0});
        FkElement first = arc(FkRotation::Ccw);
        first.kind = FkKind::TangentArc;
        first.radius = 10.0;
        EXPECT_TRUE(solver.add(first, 1, std::nullopt).resolved.empty());
        FkElement second = arc(FkRotation::Cw);
        second.kind = FkKind::TangentArc;
        second.radius = 15.0;
        EXPECT_TRUE(solver.add(second, 2, std::nullopt).resolved.empty());
        FkElement out = line();
        out.kind = FkKind::TangentLine;
        out.an = abs(0.0);
        out.x = abs(100.0);
        out.y = abs(45.0);
        return solver.add(out, 3, std::nullopt);
    };
    for (int choice = 1; choice <= 2; ++choice) {
        FkSolver solver;
        FkStep step = feed(solver);
        ASSERT_FALSE(step.problem) << step.problem->messageTemplate;
        ASSERT_EQ(step.choices, 2u);
        ASSERT_EQ(solver.alternatives().size(), 2u);
        const double side =
            solver.alternatives()[static_cast<size_t>(choice - 1)].segment.end.x() > 0.0 ? 1.0
                                                                                         : -1.0;
        step = solver.select(choice);
        ASSERT_FALSE(step.problem) << step.problem->messageTemplate;
        ASSERT_EQ(step.resolved.size(), 3u);
        const PlanarSegment& a = step.resolved[0].segment;
        const PlanarSegment& b = step.resolved[1].segment;
        expectPoint(a.center, 0.0, 10.0);
        expectPoint(a.end, 6.0 * side, 18.0);
        expectPoint(b.center, 15.0 * side, 30.0);
        expectPoint(b.end, 15.0 * side, 45.0);
        const double sweep = side > 0.0 ? 143.130102 : 216.869898;
        EXPECT_NEAR(radToDeg(a.sweep), sweep, 1e-5);
        EXPECT_NEAR(radToDeg(b.sweep), -sweep, 1e-5);
        expectPoint(step.resolved[2].segment.start, 15.0 * side, 45.0);
        expectPoint(step.resolved[2].segment.end, 100.0, 45.0);
    }
}

}  // namespace
}  // namespace kerf::fk

namespace kerf::fk {
namespace {

// As above, but the contour goes on with an arc of its own: FCT DR+ about c3 = (15,50), r5, to
// (20,50). The second centre lies 25 from c1 = (0,10) and 15 + 5 = 20 from c3: one is (15,30)
// (the arcs touch at (6,18) and (15,45)); the other is its mirror image in the line c1 c3.
TEST(FkSolver, TwoTangentArcsKnownOnlyByTheirRadiusBeforeAKnownArc) {
    FkSolver solver;
    solver.begin({0.0, 0.0}, Vec2{1.0, 0.0});
    FkElement first = arc(FkRotation::Ccw);
    first.kind = FkKind::TangentArc;
    first.radius = 10.0;
    EXPECT_TRUE(solver.add(first, 1, std::nullopt).resolved.empty());
    FkElement second = arc(FkRotation::Cw);
    second.kind = FkKind::TangentArc;
    second.radius = 15.0;
    EXPECT_TRUE(solver.add(second, 2, std::nullopt).resolved.empty());
    FkElement third = arc(FkRotation::Ccw);
    third.kind = FkKind::TangentArc;
    third.ccx = abs(15.0);
    third.ccy = abs(50.0);
    third.radius = 5.0;
    third.x = abs(20.0);
    third.y = abs(50.0);
    FkStep step = solver.add(third, 3, std::nullopt);
    ASSERT_FALSE(step.problem) << step.problem->messageTemplate;
    ASSERT_EQ(step.choices, 2u);
    size_t chosen = 0;
    for (size_t i = 0; i < solver.alternatives().size(); ++i) {
        const Vec2 end = solver.alternatives()[i].segment.end;
        if ((end - Vec2{6.0, 18.0}).norm() < kTol) chosen = i + 1;
    }
    ASSERT_NE(chosen, 0u);
    step = solver.select(static_cast<int>(chosen));
    ASSERT_FALSE(step.problem) << step.problem->messageTemplate;
    ASSERT_EQ(step.resolved.size(), 3u);
    expectPoint(step.resolved[1].segment.center, 15.0, 30.0);
    expectPoint(step.resolved[1].segment.end, 15.0, 45.0);
    expectPoint(step.resolved[2].segment.center, 15.0, 50.0);
    // From (15,45), angle -90 about c3, counter-clockwise to 0 degrees.
    EXPECT_NEAR(radToDeg(step.resolved[2].segment.sweep), 90.0, 1e-6);
    expectPoint(step.resolved[2].segment.end, 20.0, 50.0);
}

}  // namespace
}  // namespace kerf::fk
