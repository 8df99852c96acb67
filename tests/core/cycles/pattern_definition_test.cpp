#include "core/cycles/pattern/pattern_definition.h"

#include <gtest/gtest.h>

namespace kerf::cycles {
namespace {

PatternElement::Word w(double v, bool incremental = false) {
    return {v, incremental, true};
}

TEST(PatternDefinition, FrameKeepsOnlyThePerimeter) {
    PatternElement e;
    e.kind = PatternElement::Kind::Frame;
    e.x = w(0.0);
    e.y = w(0.0);
    e.dx = w(10.0);
    e.dy = w(10.0);
    e.numX = w(4.0);
    e.numY = w(3.0);
    std::vector<PatternPoint> p;
    ASSERT_FALSE(patternPoints({e}, p));
    EXPECT_EQ(p.size(), 10u);  // 12 grid points less the 2 inside
}

TEST(PatternDefinition, RotationsOfPat) {
    PatternElement e;
    e.kind = PatternElement::Kind::Pat;
    e.x = w(0.0);
    e.y = w(0.0);
    e.dx = w(10.0);
    e.dy = w(10.0);
    e.numX = w(2.0);
    e.numY = w(2.0);
    e.rot = w(90.0);
    e.rotY = w(-180.0);  // the secondary axis (90° + ROT + ROTY) along +X
    std::vector<PatternPoint> p;
    ASSERT_FALSE(patternPoints({e}, p));
    ASSERT_EQ(p.size(), 4u);
    EXPECT_NEAR(p[1].position.x(), 0.0, 1e-12);  // main axis rotated to +Y
    EXPECT_NEAR(p[1].position.y(), 10.0, 1e-12);
    EXPECT_NEAR(p[2].position.x(), 10.0, 1e-12);
    EXPECT_NEAR(p[2].position.y(), 0.0, 1e-12);
}

TEST(PatternDefinition, CountsAreChecked) {
    PatternElement e;
    e.kind = PatternElement::Kind::Circ;
    e.num = w(0.0);
    std::vector<PatternPoint> p;
    EXPECT_TRUE(patternPoints({e}, p));
    e.num = w(2.5);
    EXPECT_TRUE(patternPoints({e}, p));
    e.num = w(1e12);
    EXPECT_TRUE(patternPoints({e}, p));
}

TEST(PatternDefinition, SurfaceOnlyWhenNotZero) {
    PatternElement a;
    a.kind = PatternElement::Kind::Pos;
    a.x = w(10.0);
    a.y = w(10.0);
    a.z = w(0.0);
    PatternElement b = a;
    b.x = w(5.0, true);
    b.z = w(-3.0, true);
    std::vector<PatternPoint> p;
    ASSERT_FALSE(patternPoints({a, b}, p));
    EXPECT_FALSE(p[0].surface);
    EXPECT_NEAR(p[1].position.x(), 15.0, 1e-12);
    ASSERT_TRUE(p[1].surface);
    EXPECT_DOUBLE_EQ(*p[1].surface, -3.0);
}

}  // namespace
}  // namespace kerf::cycles
