// Offsets of the fixed cycles' shapes against areas and points derived by hand.
#include "core/geometry/offset_contour.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace kerf {
namespace {

constexpr double kPi = std::numbers::pi;

size_t countArcs(const ClosedContour& c) {
    size_t n = 0;
    for (const PlanarSegment& s : c.segments)
        n += s.kind == PlanarSegment::Kind::Arc ? 1 : 0;
    return n;
}

void expectClosed(const ClosedContour& c) {
    ASSERT_FALSE(c.empty());
    for (size_t i = 0; i < c.segments.size(); ++i) {
        const PlanarSegment& a = c.segments[i];
        const PlanarSegment& b = c.segments[(i + 1) % c.segments.size()];
        EXPECT_NEAR((a.end - b.start).norm(), 0.0, 1e-9) << "gap after segment " << i;
    }
}

TEST(OffsetContour, RoundedRectangleStartsOnTheRightSideCounterClockwise) {
    const ClosedContour c = roundedRectangle(80, 60, 5);
    expectClosed(c);
    EXPECT_EQ(c.segments.size(), 9u);  // the +u side split at its middle, 4 sides, 4 corners
    EXPECT_EQ(countArcs(c), 4u);
    EXPECT_NEAR(c.segments.front().start.x(), 40.0, 1e-12);
    EXPECT_NEAR(c.segments.front().start.y(), 0.0, 1e-12);
    // 80 x 60 less four corners of (4 - pi) r^2 / 4 each.
    EXPECT_NEAR(c.signedArea(), 4800.0 - (4.0 - kPi) * 25.0, 1e-9);
    EXPECT_NEAR(c.reversed().signedArea(), -c.signedArea(), 1e-9);
}

TEST(OffsetContour, InwardOffsetSharpensCornersSmallerThanTheDistance) {
    const ClosedContour c = roundedRectangle(80, 60, 5);
    // By the corner radius: a sharp 70 x 50 rectangle.
    auto exact = offsetClosed(c, -5.0);
    ASSERT_TRUE(exact);
    expectClosed(*exact);
    EXPECT_EQ(countArcs(*exact), 0u);
    EXPECT_NEAR(exact->signedArea(), 70.0 * 50.0, 1e-9);
    // Beyond it: the lines meet at (32, 22), 64 x 44.
    auto deeper = offsetClosed(c, -8.0);
    ASSERT_TRUE(deeper);
    expectClosed(*deeper);
    EXPECT_EQ(countArcs(*deeper), 0u);
    EXPECT_NEAR(deeper->signedArea(), 64.0 * 44.0, 1e-9);
    EXPECT_NEAR(deeper->segments.front().end.x(), 32.0, 1e-9);
    EXPECT_NEAR(deeper->segments.front().end.y(), 22.0, 1e-9);
    // Less than the radius: arcs of radius 5 - 2 = 3 about the same centres.
    auto shallow = offsetClosed(c, -2.0);
    ASSERT_TRUE(shallow);
    ASSERT_EQ(countArcs(*shallow), 4u);
    EXPECT_NEAR(shallow->segments[1].radius(), 3.0, 1e-12);
    EXPECT_NEAR(shallow->segments[1].center.x(), 35.0, 1e-12);
    EXPECT_NEAR(shallow->segments[1].center.y(), 25.0, 1e-12);
    EXPECT_NEAR(shallow->signedArea(), 76.0 * 56.0 - (4.0 - kPi) * 9.0, 1e-9);
}

TEST(OffsetContour, OutwardOffsetRoundsConvexCornersWithArcs) {
    // A sharp 10 x 6 rectangle grown by 2: A + P d + pi d^2, arcs about the four corners.
    auto grown = offsetClosed(roundedRectangle(10, 6, 0), 2.0);
    ASSERT_TRUE(grown);
    expectClosed(*grown);
    EXPECT_EQ(countArcs(*grown), 4u);
    EXPECT_NEAR(grown->signedArea(), 60.0 + 2.0 * 32.0 + kPi * 4.0, 1e-9);
    for (const PlanarSegment& s : grown->segments) {
        if (s.kind != PlanarSegment::Kind::Arc) continue;
        EXPECT_NEAR(s.radius(), 2.0, 1e-12);
        EXPECT_NEAR(std::fabs(s.center.x()), 5.0, 1e-12);
        EXPECT_NEAR(std::fabs(s.center.y()), 3.0, 1e-12);
        EXPECT_NEAR(s.sweep, kPi / 2.0, 1e-12);
    }
    // A chamfered square (octagon) grown by 1: eight arcs of 45 degrees.
    const ClosedContour octagon = roundedRectangle(20, 20, -4);
    EXPECT_NEAR(octagon.signedArea(), 400.0 - 4.0 * 8.0, 1e-9);
    auto around = offsetClosed(octagon, 1.0);
    ASSERT_TRUE(around);
    expectClosed(*around);
    EXPECT_EQ(countArcs(*around), 8u);
    const double perimeter = 4.0 * 12.0 + 4.0 * 4.0 * std::sqrt(2.0);
    EXPECT_NEAR(around->signedArea(), 368.0 + perimeter + kPi, 1e-9);
}

TEST(OffsetContour, CirclesAndSlotsStayArcs) {
    auto inner = offsetClosed(circleContour(10.0), -3.0);
    ASSERT_TRUE(inner);
    ASSERT_EQ(inner->segments.size(), 1u);
    EXPECT_NEAR(inner->segments[0].radius(), 7.0, 1e-12);
    EXPECT_NEAR(inner->segments[0].sweep, 2.0 * kPi, 1e-12);
    EXPECT_FALSE(offsetClosed(circleContour(10.0), -10.0));
    // A slot 80 x 12: the corner radius takes the whole width; it starts on the end arc.
    const ClosedContour slot = roundedRectangle(80, 12, 6);
    expectClosed(slot);
    EXPECT_EQ(slot.segments.front().kind, PlanarSegment::Kind::Arc);
    EXPECT_NEAR(slot.signedArea(), 68.0 * 12.0 + kPi * 36.0, 1e-9);
    auto narrower = offsetClosed(slot, -4.0);
    ASSERT_TRUE(narrower);
    EXPECT_NEAR(narrower->signedArea(), 68.0 * 4.0 + kPi * 4.0, 1e-9);
}

TEST(OffsetContour, AnOffsetThatVanishesIsEmpty) {
    EXPECT_FALSE(offsetClosed(roundedRectangle(20, 10, 0), -5.0));
    EXPECT_FALSE(offsetClosed(roundedRectangle(20, 10, 0), -6.0));
    EXPECT_FALSE(offsetClosed(roundedRectangle(80, 12, 6), -6.0));
    EXPECT_TRUE(offsetClosed(roundedRectangle(20, 10, 0), -4.9));
    // A clockwise chain offset to its left grows outwards: no area on the left.
    EXPECT_FALSE(offsetClosed(roundedRectangle(20, 10, 2).reversed(), -1.0));
    // A sharp concave corner (an L) is the general engine's job.
    ClosedContour ell;
    const Vec2 p[] = {{0, 0}, {20, 0}, {20, 10}, {10, 10}, {10, 20}, {0, 20}};
    for (size_t i = 0; i < 6; ++i)
        ell.segments.push_back(PlanarSegment::line(p[i], p[(i + 1) % 6]));
    EXPECT_NEAR(ell.signedArea(), 300.0, 1e-9);
    EXPECT_FALSE(offsetClosed(ell, -1.0));
    EXPECT_FALSE(offsetClosed(ell, 1.0));
}

TEST(OffsetContour, CircularSlotKeepsItsConcaveWallTangent) {
    // Pitch radius 40 from 0 to 90 degrees, width 10: a quarter of the annulus 35..45 and two
    // half discs of radius 5.
    const ClosedContour slot = arcSlot(40, 0, kPi / 2.0, 10);
    expectClosed(slot);
    ASSERT_EQ(slot.segments.size(), 5u);
    EXPECT_NEAR(slot.segments.front().start.x(), -5.0, 1e-12);  // the cap at 90 degrees
    EXPECT_NEAR(slot.segments.front().start.y(), 40.0, 1e-12);
    EXPECT_LT(slot.segments[1].sweep, 0.0);  // the inner wall
    EXPECT_NEAR(slot.signedArea(), (45.0 * 45.0 - 35.0 * 35.0) * kPi / 4.0 + kPi * 25.0, 1e-9);
    auto inner = offsetClosed(slot, -3.0);
    ASSERT_TRUE(inner);
    expectClosed(*inner);
    EXPECT_NEAR(inner->segments[1].radius(), 38.0, 1e-12);
    EXPECT_NEAR(inner->segments[3].radius(), 42.0, 1e-12);
    EXPECT_NEAR(inner->segments[2].radius(), 2.0, 1e-12);
    EXPECT_NEAR(inner->signedArea(), 80.0 * kPi + 4.0 * kPi, 1e-9);
    EXPECT_FALSE(offsetClosed(slot, -5.0));  // only the pitch arc is left
}

TEST(OffsetContour, RegularPolygonsWithRoundedOrChamferedCorners) {
    // Hexagon on R10: six equilateral triangles, area 6 x (sqrt(3) / 4) x 100; a side crosses +u
    // at the inradius 10 cos 30.
    auto hexagon = regularPolygon(10, 6, 0);
    ASSERT_TRUE(hexagon);
    expectClosed(*hexagon);
    EXPECT_EQ(hexagon->segments.size(), 7u);
    EXPECT_NEAR(hexagon->segments.front().start.x(), 10 * std::cos(kPi / 6), 1e-12);
    EXPECT_NEAR(hexagon->signedArea(), 6 * std::sqrt(3.0) / 4 * 100, 1e-9);
    // Corners rounded with R2: each corner loses the area between its two tangents and the arc,
    // r^2 (tan(phi/2) - phi/2) with the turn phi = 60 degrees.
    auto rounded = regularPolygon(10, 6, 2);
    ASSERT_TRUE(rounded);
    expectClosed(*rounded);
    const double phi = kPi / 3;
    EXPECT_NEAR(rounded->signedArea(),
                hexagon->signedArea() - 6 * 4 * (std::tan(phi / 2) - phi / 2), 1e-9);
    // Its offset by 1 keeps the arcs' centres: radius 3, and stays tangent-continuous.
    auto grown = offsetClosed(*rounded, 1.0);
    ASSERT_TRUE(grown);
    EXPECT_EQ(grown->segments.size(), rounded->segments.size());
    // Square (4 corners on R sqrt(2)*5, side 10) with chamfers of 2: 100 - 4 x 2.
    auto square = regularPolygon(5 * std::sqrt(2.0), 4, -2);
    ASSERT_TRUE(square);
    EXPECT_NEAR(square->signedArea(), 100.0 - 8.0, 1e-9);
    EXPECT_FALSE(regularPolygon(10, 2, 0));
    EXPECT_FALSE(regularPolygon(10, 6, -6));  // a chamfer longer than half a side (5)
}

TEST(OffsetContour, DistancesAndPlacement) {
    const ClosedContour c = roundedRectangle(80, 60, 5);
    EXPECT_NEAR(c.distanceTo({50, 0}), 10.0, 1e-12);
    EXPECT_NEAR(c.distanceTo({45, 35}), std::sqrt(200.0) - 5.0, 1e-12);
    EXPECT_NEAR(c.distanceTo({0, 0}), 30.0, 1e-12);
    const ClosedContour moved = c.placed({100, 50}, kPi / 2.0);
    EXPECT_NEAR(moved.segments.front().start.x(), 100.0, 1e-12);
    EXPECT_NEAR(moved.segments.front().start.y(), 90.0, 1e-12);
    EXPECT_NEAR(moved.signedArea(), c.signedArea(), 1e-9);
    EXPECT_NEAR(moved.distanceTo({100, 50}), 30.0, 1e-12);
}

}  // namespace
}  // namespace kerf
