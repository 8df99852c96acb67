// Offsets of open chains (the lathe's pattern repeat passes) against points derived by hand.
#include "core/geometry/open_chain_offset.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

namespace kerf {
namespace {

constexpr double kPi = std::numbers::pi;
using Kind = PlanarSegment::Kind;

void expectPoint(const Vec2& p, double u, double v) {
    EXPECT_NEAR(p.x(), u, 1e-9);
    EXPECT_NEAR(p.y(), v, 1e-9);
}

void expectConnected(const std::vector<PlanarSegment>& chain) {
    for (size_t i = 1; i < chain.size(); ++i) {
        EXPECT_NEAR((chain[i - 1].end - chain[i].start).norm(), 0.0, 1e-9) << "gap before " << i;
    }
}

std::vector<PlanarSegment> lines(std::initializer_list<Vec2> points) {
    std::vector<PlanarSegment> chain;
    const Vec2* previous = nullptr;
    for (const Vec2& p : points) {
        if (previous != nullptr) chain.push_back(PlanarSegment::line(*previous, p));
        previous = &p;
    }
    return chain;
}

TEST(OpenChainOffset, ConvexCornerGetsAnArcAboutTheCorner) {
    // A left turn at (10, 0), offset to the right by 2: the corner is on the outside.
    const auto out = offsetOpenChain(lines({{0, 0}, {10, 0}, {10, 10}}), -2.0);
    ASSERT_TRUE(out);
    ASSERT_EQ(out->size(), 3u);
    expectConnected(*out);
    expectPoint((*out)[0].start, 0, -2);
    expectPoint((*out)[0].end, 10, -2);
    ASSERT_EQ((*out)[1].kind, Kind::Arc);
    expectPoint((*out)[1].center, 10, 0);
    EXPECT_NEAR((*out)[1].sweep, kPi / 2.0, 1e-12);
    expectPoint((*out)[2].start, 12, 0);
    expectPoint((*out)[2].end, 12, 10);
}

TEST(OpenChainOffset, ConcaveCornerIsCutWhereTheNeighboursMeet) {
    const auto out = offsetOpenChain(lines({{0, 0}, {10, 0}, {10, 10}}), 2.0);
    ASSERT_TRUE(out);
    ASSERT_EQ(out->size(), 2u);
    expectPoint((*out)[0].start, 0, 2);
    expectPoint((*out)[0].end, 8, 2);
    expectPoint((*out)[1].start, 8, 2);
    expectPoint((*out)[1].end, 8, 10);
}

TEST(OpenChainOffset, ArcsKeepTheirCentreAndChangeTheirRadius) {
    // Quarter circle R10 counter-clockwise: its left is the centre side.
    const std::vector<PlanarSegment> arc{PlanarSegment::arc({10, 0}, {0, 0}, kPi / 2.0)};
    const auto inner = offsetOpenChain(arc, 2.0);
    const auto outer = offsetOpenChain(arc, -2.0);
    ASSERT_TRUE(inner && outer);
    ASSERT_EQ(inner->size(), 1u);
    EXPECT_EQ(inner->front().kind, Kind::Arc);
    EXPECT_NEAR(inner->front().radius(), 8.0, 1e-12);
    expectPoint(inner->front().end, 0, 8);
    EXPECT_NEAR(outer->front().radius(), 12.0, 1e-12);
    EXPECT_NEAR(outer->front().sweep, kPi / 2.0, 1e-12);
}

TEST(OpenChainOffset, GrooveNarrowerThanTwiceTheDistanceIsBridged) {
    // A groove 3 wide and 5 deep under a line; 2 above it the offset bridges it with the arcs
    // about the groove's two upper corners, which meet at u = 11.5, v = sqrt(4 - 1.5^2).
    const auto out =
        offsetOpenChain(lines({{0, 0}, {10, 0}, {10, -5}, {13, -5}, {13, 0}, {23, 0}}), 2.0);
    ASSERT_TRUE(out);
    expectConnected(*out);
    ASSERT_EQ(out->size(), 4u);
    expectPoint((*out)[0].end, 10, 2);
    ASSERT_EQ((*out)[1].kind, Kind::Arc);
    expectPoint((*out)[1].center, 10, 0);
    expectPoint((*out)[1].end, 11.5, std::sqrt(4.0 - 2.25));
    ASSERT_EQ((*out)[2].kind, Kind::Arc);
    expectPoint((*out)[2].center, 13, 0);
    expectPoint((*out)[2].end, 13, 2);
    expectPoint((*out)[3].end, 23, 2);
}

TEST(OpenChainOffset, WideGrooveKeepsItsShape) {
    // 10 wide: the offset goes down into it, 2 from each wall and the floor.
    const auto out =
        offsetOpenChain(lines({{0, 0}, {10, 0}, {10, -5}, {20, -5}, {20, 0}, {30, 0}}), 2.0);
    ASSERT_TRUE(out);
    expectConnected(*out);
    ASSERT_EQ(out->size(), 7u);  // line, corner arc, wall, floor, wall, corner arc, line
    expectPoint((*out)[2].start, 12, 0);
    expectPoint((*out)[2].end, 12, -3);
    expectPoint((*out)[3].end, 18, -3);
    expectPoint((*out)[4].end, 18, 0);
}

TEST(OpenChainOffset, ArcSmallerThanTheDistanceOnItsInnerSideIsSwallowed) {
    // A half-round cove R1 under a line, offset 2 upwards: the arcs about the cove's edges meet
    // above its centre at v = sqrt(2^2 - 1^2).
    std::vector<PlanarSegment> chain = lines({{-10, 0}, {-1, 0}});
    chain.push_back(PlanarSegment::arc({-1, 0}, {0, 0}, kPi));  // down through (0, -1)
    chain.push_back(PlanarSegment::line({1, 0}, {10, 0}));
    const auto out = offsetOpenChain(chain, 2.0);
    ASSERT_TRUE(out);
    expectConnected(*out);
    ASSERT_EQ(out->size(), 4u);
    expectPoint((*out)[1].center, -1, 0);
    expectPoint((*out)[1].end, 0, std::sqrt(3.0));
    expectPoint((*out)[2].center, 1, 0);
    expectPoint((*out)[3].start, 1, 2);
}

TEST(OpenChainOffset, ChainUpToCutsAtTheFirstOutwardCrossing) {
    const auto cut = chainUpTo(lines({{0, 0}, {10, 10}, {20, 10}}), 0, 5.0, 1.0);
    ASSERT_EQ(cut.size(), 1u);
    expectPoint(cut[0].end, 5, 5);
    // A clockwise arc R12 about (-20, 10) from its top, cut at u = -30 going towards -u.
    const std::vector<PlanarSegment> arc{PlanarSegment::arc({-20, 22}, {-20, 10}, kPi / 2.0)};
    const auto arcCut = chainUpTo(arc, 0, -30.0, -1.0);
    ASSERT_EQ(arcCut.size(), 1u);
    expectPoint(arcCut[0].end, -30, 10 + std::sqrt(144.0 - 100.0));
    EXPECT_TRUE(chainUpTo(lines({{0, 0}, {10, 0}}), 0, -1.0, 1.0).empty());
}

TEST(OpenChainOffset, ABoxMovesEachElementByTheCornerItFaces) {
    // A shoulder down along -u: v10 to u-10, down to v5, on to u-20; the material below, the
    // offset on the right of the travel. Box u -1..1, v -0.5..2: the top moves up 2 and is
    // stretched by the box's width (u1 to u-11), the wall faces -u and moves by -1 from v12
    // down, the floor moves up 2 (v7) and meets the wall's copy at u-11: the loop the box leaves
    // in the concave corner is cut away.
    Box2 box;
    box.min = Vec2(-1.0, -0.5);
    box.max = Vec2(1.0, 2.0);
    const auto offset =
        offsetOpenChainByBox(lines({{0, 10}, {-10, 10}, {-10, 5}, {-20, 5}}), box, -1.0);
    ASSERT_TRUE(offset);
    ASSERT_EQ(offset->size(), 3u);
    expectConnected(*offset);
    expectPoint((*offset)[0].start, 1, 12);
    expectPoint((*offset)[0].end, -11, 12);
    expectPoint((*offset)[1].end, -11, 7);
    expectPoint((*offset)[2].end, -21, 7);
}

TEST(OpenChainOffset, ABoxMovesAnArcByTheCornerItsNormalPointsTo) {
    // A convex quarter circle R5 about (0, 0) from (5, 0) to (0, 5), offset outwards (right of
    // its counter-clockwise travel) by the box +-1: its normal points up and right all along,
    // so it moves by (1, 1) as a whole: one arc R5 about (1, 1) from (6, 1) to (1, 6).
    Box2 box;
    box.min = Vec2(-1.0, -1.0);
    box.max = Vec2(1.0, 1.0);
    const std::vector<PlanarSegment> quarter{
        PlanarSegment{Kind::Arc, Vec2(5.0, 0.0), Vec2(0.0, 5.0), Vec2(0.0, 0.0), kPi / 2.0}};
    const auto offset = offsetOpenChainByBox(quarter, box, -1.0);
    ASSERT_TRUE(offset);
    ASSERT_EQ(offset->size(), 1u);
    EXPECT_EQ((*offset)[0].kind, Kind::Arc);
    expectPoint((*offset)[0].start, 6, 1);
    expectPoint((*offset)[0].center, 1, 1);
    expectPoint((*offset)[0].end, 1, 6);
    EXPECT_NEAR((*offset)[0].sweep, kPi / 2.0, 1e-9);
}

}  // namespace
}  // namespace kerf
