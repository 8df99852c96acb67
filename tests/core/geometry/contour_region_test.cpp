// Booleans and offsets of regions against areas, radii and points derived by hand.
#include "core/geometry/contour_region.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace kerf {
namespace {

constexpr double kPi = std::numbers::pi;

ClosedContour polygon(std::initializer_list<Vec2> points) {
    ClosedContour c;
    const std::vector<Vec2> p(points);
    for (size_t i = 0; i < p.size(); ++i)
        c.segments.push_back(PlanarSegment::line(p[i], p[(i + 1) % p.size()]));
    return c;
}

ClosedContour rectangle(double u0, double v0, double u1, double v1) {
    return polygon({{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}});
}

ClosedContour circle(const Vec2& centre, double r) {
    return circleContour(r).placed(centre, 0.0);
}

void expectClosed(const ClosedContour& c) {
    ASSERT_FALSE(c.empty());
    for (size_t i = 0; i < c.segments.size(); ++i) {
        const PlanarSegment& a = c.segments[i];
        const PlanarSegment& b = c.segments[(i + 1) % c.segments.size()];
        EXPECT_NEAR((a.end - b.start).norm(), 0.0, 1e-9) << "gap after segment " << i;
    }
}

// Every point of every segment of `c` lies at `distance` from the circle or line it was made
// for: checked at the segment ends and middles against `exact` (a distance function).
template <class F>
void expectOn(const ClosedContour& c, F exact, double tolerance) {
    for (const PlanarSegment& s : c.segments) {
        Vec2 middle = (s.start + s.end) / 2.0;
        if (s.kind == PlanarSegment::Kind::Arc) {
            const Vec2 a = s.start - s.center;
            const double h = s.sweep / 2.0;
            middle = s.center + Vec2(std::cos(h) * a.x() - std::sin(h) * a.y(),
                                     std::sin(h) * a.x() + std::cos(h) * a.y());
        }
        for (const Vec2& p : {s.start, middle, s.end})
            EXPECT_NEAR(exact(p), 0.0, tolerance) << p.transpose();
    }
}

// The example: a 60 x 40 pocket about the origin with a 20 mm island in the middle,
// tool R5, side allowance 0.5: the tool centre stays 5.5 from every wall. The island's ring
// (radius 10 + 5 + 0.5 = 15.5) reaches beyond the walls' rings at v = +-14.5, so the first
// clearing ring splits into two regions, each closed by an arc of the island ring from
// u = +-sqrt(15.5^2 - 14.5^2) = +-sqrt(30).
TEST(ContourRegion, PocketWithIslandFirstClearingRingIsTheExactOffset) {
    const Region pocket =
        subtract(regionOf(rectangle(-30, -20, 30, 20)), regionOf(circle({0.0, 0.0}, 10.0)));
    ASSERT_EQ(pocket.boundaries.size(), 2u);
    EXPECT_NEAR(pocket.area(), 2400.0 - kPi * 100.0, 1e-6);

    const Region ring = offsetRegion(pocket, -5.5);
    ASSERT_EQ(ring.boundaries.size(), 2u);
    // Each half: 24.5 x 29 less the part of the circle of 15.5 inside the band |v| <= 14.5.
    const double root30 = std::sqrt(30.0);
    const double half = 24.5 * 29.0 - (14.5 * root30 + 15.5 * 15.5 * std::asin(14.5 / 15.5));
    for (const ClosedContour& c : ring.boundaries) {
        expectClosed(c);
        EXPECT_NEAR(c.signedArea(), half, 1e-6);
        ASSERT_EQ(c.segments.size(), 4u);
        size_t arcs = 0;
        for (const PlanarSegment& s : c.segments) {
            if (s.kind == PlanarSegment::Kind::Arc) {
                ++arcs;
                EXPECT_NEAR(s.radius(), 15.5, 1e-9);
                EXPECT_NEAR(s.center.norm(), 0.0, 1e-9);
                EXPECT_NEAR(std::fabs(s.start.x()), root30, 1e-9);
                EXPECT_NEAR(std::fabs(s.start.y()), 14.5, 1e-9);
                EXPECT_LT(s.sweep, 0.0);  // clockwise about the island
            } else {
                for (const Vec2& p : {s.start, s.end}) {
                    const bool onSide = std::fabs(std::fabs(p.x()) - 24.5) < 1e-9;
                    const bool onTopOrBottom = std::fabs(std::fabs(p.y()) - 14.5) < 1e-9;
                    EXPECT_TRUE(onSide || onTopOrBottom) << p.transpose();
                }
            }
        }
        EXPECT_EQ(arcs, 1u);
    }
    // A smaller island (r 5) keeps one region with a hole of radius 10.5.
    const Region ring2 = offsetRegion(
        subtract(regionOf(rectangle(-30, -20, 30, 20)), regionOf(circle({0.0, 0.0}, 5.0))), -5.5);
    ASSERT_EQ(ring2.boundaries.size(), 2u);
    EXPECT_NEAR(ring2.area(), 49.0 * 29.0 - kPi * 10.5 * 10.5, 1e-6);
    for (const ClosedContour& c : ring2.boundaries) {
        if (c.signedArea() > 0.0) continue;
        ASSERT_EQ(c.segments.size(), 1u);
        EXPECT_NEAR(c.segments[0].radius(), 10.5, 1e-9);
        EXPECT_NEAR(c.segments[0].sweep, -2.0 * kPi, 1e-12);
    }
}

// Two overlapping circles of the seed's chapter 7 example (r 25 about X35 and X65, Y50) meet
// at X50 Y50 +- sqrt(25^2 - 15^2) = +-20.
TEST(ContourRegion, UnionAndIntersectionOfTwoCirclesMeetAtTheExactPoints) {
    const Region a = regionOf(circle({35.0, 50.0}, 25.0));
    const Region b = regionOf(circle({65.0, 50.0}, 25.0));
    const double lens = 2.0 * 625.0 * std::acos(0.6) - 15.0 * 40.0;
    const Region both = unite(a, b);
    ASSERT_EQ(both.boundaries.size(), 1u);
    expectClosed(both.boundaries[0]);
    EXPECT_NEAR(both.area(), 2.0 * kPi * 625.0 - lens, 1e-6);
    ASSERT_EQ(both.boundaries[0].segments.size(), 2u);
    for (const PlanarSegment& s : both.boundaries[0].segments) {
        EXPECT_EQ(s.kind, PlanarSegment::Kind::Arc);
        EXPECT_NEAR(s.radius(), 25.0, 1e-9);
        EXPECT_NEAR(s.start.x(), 50.0, 1e-9);
        EXPECT_NEAR(std::fabs(s.start.y() - 50.0), 20.0, 1e-9);
    }
    const Region common = intersect(a, b);
    ASSERT_EQ(common.boundaries.size(), 1u);
    EXPECT_NEAR(common.area(), lens, 1e-6);
    const Region left = subtract(a, b);
    EXPECT_NEAR(left.area(), kPi * 625.0 - lens, 1e-6);
}

TEST(ContourRegion, OutwardOffsetRoundsConvexCornersWithArcsAboutThem) {
    const Region grown = offsetRegion(regionOf(rectangle(0, 0, 10, 10)), 2.0);
    ASSERT_EQ(grown.boundaries.size(), 1u);
    const ClosedContour& c = grown.boundaries[0];
    expectClosed(c);
    EXPECT_EQ(c.segments.size(), 8u);
    EXPECT_NEAR(c.signedArea(), 100.0 + 4.0 * 10.0 * 2.0 + kPi * 4.0, 1e-6);
    // Every point is exactly 2 from the square.
    const ClosedContour square = rectangle(0, 0, 10, 10);
    expectOn(
        c, [&](const Vec2& p) { return square.distanceTo(p) - 2.0; }, 1e-6);
}

// A pocket narrower than two tool radii in one place: two 20 x 20 rooms joined by a corridor
// 4 wide. The tool centre region for R3 is two 14 x 14 squares, each with a bulge into the
// corridor's mouth bounded by arcs of radius 3 about its corners: 2 x integral from 0 to 2 of
// (3 - sqrt(9 - t^2)) dt = 2 (6 - sqrt(5) - 4.5 asin(2/3)).
TEST(ContourRegion, NarrowPassageSplitsTheOffset) {
    Region room = unite(regionOf(rectangle(0, 0, 20, 20)), regionOf(rectangle(40, 0, 60, 20)));
    room = unite(room, regionOf(rectangle(19, 8, 41, 12)));
    ASSERT_EQ(room.boundaries.size(), 1u);
    EXPECT_NEAR(room.area(), 800.0 + 20.0 * 4.0, 1e-6);
    const Region centre = offsetRegion(room, -3.0);
    ASSERT_EQ(centre.boundaries.size(), 2u);
    for (const ClosedContour& c : centre.boundaries)
        EXPECT_NEAR(c.signedArea(),
                    196.0 + 2.0 * (6.0 - std::sqrt(5.0) - 4.5 * std::asin(2.0 / 3.0)), 1e-6);
    // R1.9: the corridor still holds the tool (4 > 3.8), one region.
    EXPECT_EQ(offsetRegion(room, -1.9).boundaries.size(), 1u);
}

// The inward offset of an arc-and-line shape (a stadium) stays exact: arcs of r - d.
TEST(ContourRegion, InwardOffsetOfArcsIsAnArcOfSmallerRadius) {
    const ClosedContour slot = roundedRectangle(60, 20, 10);
    const Region inner = offsetRegion(regionOf(slot), -4.0);
    ASSERT_EQ(inner.boundaries.size(), 1u);
    size_t arcs = 0;
    for (const PlanarSegment& s : inner.boundaries[0].segments) {
        if (s.kind == PlanarSegment::Kind::Arc) {
            ++arcs;
            EXPECT_NEAR(s.radius(), 6.0, 1e-9);
        }
    }
    EXPECT_GE(arcs, 2u);
    // 52 x 12 with semicircle ends of radius 6: 40 x 12 + pi 36.
    EXPECT_NEAR(inner.area(), 40.0 * 12.0 + kPi * 36.0, 1e-6);
    expectOn(
        inner.boundaries[0], [&](const Vec2& p) { return slot.distanceTo(p) - 4.0; }, 1e-9);
}

TEST(ContourRegion, SelfIntersectionIsFound) {
    EXPECT_TRUE(selfIntersects(polygon({{0, 0}, {10, 10}, {10, 0}, {0, 10}})));  // bow tie
    EXPECT_FALSE(selfIntersects(rectangle(0, 0, 10, 5)));
    EXPECT_FALSE(selfIntersects(circle({3, 4}, 2)));
}

TEST(ContourRegion, ContainsAndStartingNearest) {
    const Region pocket =
        subtract(regionOf(rectangle(-30, -20, 30, 20)), regionOf(circle({0.0, 0.0}, 10.0)));
    EXPECT_TRUE(pocket.contains({20.0, 0.0}));
    EXPECT_FALSE(pocket.contains({0.0, 0.0}));  // in the island
    EXPECT_FALSE(pocket.contains({40.0, 0.0}));
    const ClosedContour r = startingNearest(rectangle(0, 0, 10, 10), {4.0, -3.0});
    expectClosed(r);
    EXPECT_NEAR((r.segments.front().start - Vec2(4.0, 0.0)).norm(), 0.0, 1e-12);
    EXPECT_NEAR(r.signedArea(), 100.0, 1e-9);
    const ClosedContour c = startingNearest(circle({0, 0}, 5), {0.0, 9.0});
    expectClosed(c);
    EXPECT_NEAR((c.segments.front().start - Vec2(0.0, 5.0)).norm(), 0.0, 1e-9);
    EXPECT_NEAR(c.signedArea(), kPi * 25.0, 1e-9);
}

// Three squares 10 x 10 united in one boolean: the first two overlap in 5 x 10 (one boundary of
// 100 + 100 - 50 = 150), the third stands apart (100): 250 in two boundaries.
TEST(ContourRegion, UniteAllJoinsOverlappingAndSeparateRegions) {
    const Region all =
        uniteAll({regionOf(rectangle(0, 0, 10, 10)), regionOf(rectangle(5, 0, 15, 10)),
                  regionOf(rectangle(20, 0, 30, 10))});
    EXPECT_EQ(all.boundaries.size(), 2u);
    EXPECT_NEAR(all.area(), 250.0, 1e-9);
}

// Inside or outside near a large arc: a circle r 100 bulges 100 (1 - cos(pi / 16)) = 1.9 mm
// beyond its coarsest chords, so points 3 µm inside and outside it (beyond the 2 µm that count
// as on the boundary) are told apart only by chords finer than that.
TEST(ContourRegion, ContainsTellsSidesApartJustBesideALargeArc) {
    const Region disc = regionOf(circle({0.0, 0.0}, 100.0));
    for (double angle : {0.1, 0.3, 1.0, 2.5}) {
        const Vec2 direction(std::cos(angle), std::sin(angle));
        EXPECT_TRUE(disc.contains((100.0 - 3e-3) * direction)) << angle;
        EXPECT_FALSE(disc.contains((100.0 + 3e-3) * direction)) << angle;
        EXPECT_TRUE(disc.contains((100.0 - 5.0) * direction)) << angle;
        EXPECT_FALSE(disc.contains((100.0 + 5.0) * direction)) << angle;
    }
}

// A 10 x 10 square with a hole of radius 2 about (5, 5): a line along v = 1 lies inside; along
// v = 3.5 it passes 1.5 from the hole's centre (inside the hole), along v = 2.9 2.1 from it
// (beside it); one leaving the square at u = 0 and one along the square's own side u = 0 (on
// the boundary, which counts as inside); a line whose ends lie inside but which crosses the
// hole from (2.5, 5) to (7.5, 5).
TEST(ContourRegion, ContainsLineFindsCrossingsOfWallsAndHoles) {
    const Region plate = subtract(regionOf(rectangle(0, 0, 10, 10)), regionOf(circle({5, 5}, 2)));
    EXPECT_TRUE(containsLine(plate, {1.0, 1.0}, {9.0, 1.0}));
    EXPECT_FALSE(containsLine(plate, {1.0, 3.5}, {9.0, 3.5}));
    EXPECT_TRUE(containsLine(plate, {1.0, 2.9}, {9.0, 2.9}));
    EXPECT_FALSE(containsLine(plate, {-1.0, 1.0}, {5.0, 1.0}));
    EXPECT_TRUE(containsLine(plate, {0.0, 1.0}, {0.0, 9.0}));
    EXPECT_FALSE(containsLine(plate, {2.5, 5.0}, {7.5, 5.0}));
    EXPECT_TRUE(containsLine(plate, {2.5, 5.0}, {2.5, 6.0}));
}

}  // namespace
}  // namespace kerf
