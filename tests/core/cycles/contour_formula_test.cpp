// The contour formula's area level by level (formula_area.h) against areas worked out by hand,
// and the SL cycles fed with a formula instead of cycle 14.
#include <cmath>
#include <numbers>
#include <set>

#include <gtest/gtest.h>

#include "core/cycles/contour/formula_area.h"
#include "core/cycles/cycle_path.h"
#include "core/cycles/cycle_registry.h"

namespace kerf::cycles::contour {
namespace {

constexpr double kPi = std::numbers::pi;
using Kind = FormulaStep::Kind;

ClosedContour square(double u0, double v0, double size) {
    const Vec2 p[] = {{u0, v0}, {u0 + size, v0}, {u0 + size, v0 + size}, {u0, v0 + size}};
    ClosedContour c;
    for (size_t i = 0; i < 4; ++i)
        c.segments.push_back(PlanarSegment::line(p[i], p[(i + 1) % 4]));
    return c;
}

ClosedContour disc(double u, double v, double r) {
    ClosedContour c;
    c.segments.push_back(PlanarSegment::arc({u + r, v}, {u, v}, 2.0 * kPi));
    return c;
}

FormulaStep operand(size_t i) {
    return {Kind::Contour, i};
}
FormulaStep op(Kind k) {
    return {k, 0};
}

// Two unit-free squares 0..10 and 5..15 (overlap 25): union 175, intersection 25, difference
// 75, symmetric difference 150.
TEST(ContourFormula, OperatorsGiveTheAreasOfTheirDefinitions) {
    const std::pair<Kind, double> cases[] = {{Kind::Union, 175.0},
                                             {Kind::Intersection, 25.0},
                                             {Kind::Difference, 75.0},
                                             {Kind::SymmetricDifference, 150.0}};
    for (auto [kind, area] : cases) {
        ContourFormula f;
        f.contours = {{square(0, 0, 10), 0.0, false}, {square(5, 5, 10), 0.0, false}};
        f.steps = {operand(0), operand(1), op(kind)};
        const std::vector<AreaLevel> levels = formulaLevels(f, 7.0);
        ASSERT_EQ(levels.size(), 1u) << static_cast<int>(kind);
        EXPECT_NEAR(levels[0].bottom, 7.0, 1e-12);
        EXPECT_NEAR(levels[0].area.area(), area, 1e-6) << static_cast<int>(kind);
    }
}

// The seed's chapter 9 formula (QC1 | QC2) \ QC3 \ QC4: circles r 25 about (65, 50) and
// (35, 50), the triangle (73,42) (65,58) (58,42) and the square 27..43 x 42..58. Union of the
// circles 2 pi 625 - (1250 acos 0.6 - 600); less 120 and 256.
TEST(ContourFormula, SeedChapter9AreaByHand) {
    ContourFormula f;
    ClosedContour triangle;
    triangle.segments = {PlanarSegment::line({73, 42}, {65, 58}),
                         PlanarSegment::line({65, 58}, {58, 42}),
                         PlanarSegment::line({58, 42}, {73, 42})};
    f.contours = {{disc(65, 50, 25), 0.0, false},
                  {disc(35, 50, 25), 0.0, false},
                  {triangle, 0.0, false},
                  {square(27, 42, 16), 0.0, false}};
    f.steps = {operand(0),           operand(1), op(Kind::Union),     operand(2),
               op(Kind::Difference), operand(3), op(Kind::Difference)};
    const std::vector<AreaLevel> levels = formulaLevels(f, 20.0);
    ASSERT_EQ(levels.size(), 1u);
    const double lens = 1250.0 * std::acos(0.6) - 600.0;
    EXPECT_NEAR(levels[0].area.area(), 2.0 * kPi * 625.0 - lens - 120.0 - 256.0, 1e-6);
    EXPECT_EQ(levels[0].area.boundaries.size(), 3u);  // the outline and two holes
}

// DEPTH: a square 0..60 reaching 5 deep, a disc r 20 reaching 12, a core r 5 to the cycle's
// depth 8, (QC1 | QC2) ^ QC3. Down to 5 the square without the core; to 8 the ring; below 8 the
// disc alone would take in the core, but a level stays inside the one above: the ring to 12.
TEST(ContourFormula, DepthsGiveLevelsEachInsideTheOneAbove) {
    ContourFormula f;
    f.contours = {{square(0, 0, 60), 5.0, false},
                  {disc(30, 30, 20), 12.0, false},
                  {disc(30, 30, 5), 0.0, false}};
    f.steps = {operand(0), operand(1), op(Kind::Union), operand(2), op(Kind::SymmetricDifference)};
    const std::vector<AreaLevel> levels = formulaLevels(f, 8.0);
    ASSERT_EQ(levels.size(), 2u);
    EXPECT_NEAR(levels[0].bottom, 5.0, 1e-12);
    EXPECT_NEAR(levels[0].area.area(), 3600.0 - 25.0 * kPi, 1e-6);
    EXPECT_NEAR(levels[1].bottom, 12.0, 1e-12);
    EXPECT_NEAR(levels[1].area.area(), 375.0 * kPi, 1e-6);
    EXPECT_FALSE(levels[1].area.contains({30.0, 30.0}));
}

// The simple formula's island with DEPTH 4: its top 4 below the surface. Above it the whole
// pocket, below it the pocket less the island; an island with DEPTH 0 reaches the surface.
TEST(ContourFormula, IslandDepthIsItsTopBelowTheSurface) {
    ContourFormula f;
    f.contours = {{disc(0, 0, 30), 0.0, false}, {disc(0, 0, 10), 4.0, true}};
    f.steps = {operand(0), operand(1), op(Kind::Difference)};
    std::vector<AreaLevel> levels = formulaLevels(f, 10.0);
    ASSERT_EQ(levels.size(), 2u);
    EXPECT_NEAR(levels[0].bottom, 4.0, 1e-12);
    EXPECT_NEAR(levels[0].area.area(), 900.0 * kPi, 1e-6);
    EXPECT_NEAR(levels[1].bottom, 10.0, 1e-12);
    EXPECT_NEAR(levels[1].area.area(), 800.0 * kPi, 1e-6);
    f.contours[1].depth = 0.0;
    levels = formulaLevels(f, 10.0);
    ASSERT_EQ(levels.size(), 1u);
    EXPECT_NEAR(levels[0].area.area(), 800.0 * kPi, 1e-6);
}

// Nothing left: two squares apart intersected.
TEST(ContourFormula, EmptyResultHasNoLevels) {
    ContourFormula f;
    f.contours = {{square(0, 0, 10), 0.0, false}, {square(20, 0, 10), 0.0, false}};
    f.steps = {operand(0), operand(1), op(Kind::Intersection)};
    EXPECT_TRUE(formulaLevels(f, 5.0).empty());
}

struct DepthRecorder final : CycleEmitter {
    std::vector<Vec3> ends;
    std::set<double> arcLevels;  // tool-axis coordinates of the arcs, to 1 nm
    void rapid(const Vec3& t) override { ends.push_back(t); }
    void line(const Vec3& t, const Feed&) override { ends.push_back(t); }
    void arc(const Vec3& t, const Vec2&, double, const Feed&) override {
        ends.push_back(t);
        arcLevels.insert(std::round(t.z() * 1e6) / 1e6);
    }
    void threadMove(const Vec3&, double, double) override {}
    void dwell(double) override {}
    void spindle(canon::SpindleDirection, double) override {}
    void orientSpindle(double) override {}
    void miscFunction(int) override {}
};

// Cycle 22 with the island of DEPTH 4 (pocket r 30, depth 10, infeeds of 3, tool R4, no
// allowance): levels 3, 4 (the island's top), 6, 9, 10. Above the top the tool centre comes
// within R of the centre (the core of the disc); below it never nearer than 10 + 4.
TEST(ContourFormula, RoughOutMachinesAboveAnIslandsTopAndAroundItBelow) {
    CycleValues data;
    const std::pair<uint16_t, double> values[] = {{1, -10.0}, {2, 1.0}, {3, 0.0},
                                                  {4, 0.0},   {5, 0.0}, {6, 2.0},
                                                  {7, 50.0},  {8, 0.0}, {9, 1.0}};
    for (auto [q, value] : values)
        data.set(q, value);
    CycleValues v;
    v.set(10, 3.0);
    v.set(11, 100.0);
    v.set(12, 500.0);
    v.set(18, 0.0);
    v.set(19, 0.0);
    v.set(208, 0.0);
    CycleContext ctx;
    ctx.start = {0.0, 0.0, 50.0};
    ctx.tool.radius = 4.0;
    ctx.contourData = &data;
    ContourFormula f;
    f.contours = {{disc(0, 0, 30), 0.0, false}, {disc(0, 0, 10), 4.0, true}};
    f.steps = {operand(0), operand(1), op(Kind::Difference)};
    ctx.formula = f;
    DepthRecorder out;
    CyclePath path(out, ctx.start);
    ASSERT_FALSE(findCycle(22)->expand(v, ctx, path));
    double nearestAbove = 1e9, nearestBelow = 1e9;
    for (const Vec3& p : out.ends) {
        if (p.z() >= 0.0) continue;
        const double r = Vec2(p.x(), p.y()).norm();
        double& nearest = p.z() > -4.0 - 1e-9 ? nearestAbove : nearestBelow;
        nearest = std::min(nearest, r);
        EXPECT_LE(r, 26.0 + 1e-9);
    }
    EXPECT_EQ(out.arcLevels, (std::set<double>{-10.0, -9.0, -6.0, -4.0, -3.0}));
    EXPECT_LT(nearestAbove, 4.0 + 1e-9);
    EXPECT_NEAR(nearestBelow, 14.0, 1e-9);
}

}  // namespace
}  // namespace kerf::cycles::contour
