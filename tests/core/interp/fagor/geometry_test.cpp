// Tangential entry and exit arcs, work zones and location codes.
#include <cmath>

#include <gtest/gtest.h>

#include "core/interp/fagor/location_codes.h"
#include "core/interp/fagor/tangent_arcs.h"
#include "core/interp/fagor/work_zones.h"

namespace kerf::fagor {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

// Spec part 1 E17, X read as a radius: from (Z60, X20) a G37 R5 line to (Z30, X20), then
// G03 X40 Z10 R20, whose centre is (Z10, X20): it leaves (Z30, X20) towards +X. The entry circle
// right of that direction is centred at (Z35, X20); the tangent from the start touches it where
// cos = 5/25, at (Z36, X20 - 5 sin(acos 0.2)); the arc runs clockwise to 180 degrees.
TEST(FagorTangentArcs, EntryOfTheManualExample) {
    auto arc = tangentialEntry({60, 20}, {30, 20}, {0, 1}, 5.0);
    ASSERT_TRUE(arc.has_value());
    EXPECT_NEAR(arc->center.x(), 35.0, 1e-9);
    EXPECT_NEAR(arc->center.y(), 20.0, 1e-9);
    EXPECT_NEAR(arc->tangentPoint.x(), 36.0, 1e-9);
    EXPECT_NEAR(arc->tangentPoint.y(), 20.0 - 5.0 * std::sqrt(1.0 - 0.04), 1e-9);
    EXPECT_NEAR(arc->sweep * kDeg, -(180.0 - std::acos(0.2) * kDeg), 1e-9);  // -101.537
}

// E18: G02 G38 R5 X30 Z30 R20 from (Z50, X10) ends at (Z30, X30) moving +X (centre (Z50, X30));
// the next line goes to (Z10, X30). The exit circle left of +X is centred at (Z25, X30); the
// line to (Z10, X30), 15 away, touches it at 180 - acos(5/15) degrees.
TEST(FagorTangentArcs, ExitOfTheManualExample) {
    auto arc = tangentialExit({30, 30}, {0, 1}, {10, 30}, 5.0);
    ASSERT_TRUE(arc.has_value());
    EXPECT_NEAR(arc->center.x(), 25.0, 1e-9);
    EXPECT_NEAR(arc->center.y(), 30.0, 1e-9);
    const double a = 180.0 - std::acos(1.0 / 3.0) * kDeg;  // 109.47
    EXPECT_NEAR(arc->sweep * kDeg, a, 1e-9);
    EXPECT_NEAR(arc->tangentPoint.x(), 25.0 + 5.0 * std::cos(a / kDeg), 1e-9);
    EXPECT_NEAR(arc->tangentPoint.y(), 30.0 + 5.0 * std::sin(a / kDeg), 1e-9);
}

TEST(FagorTangentArcs, StartOnBothCircles) {
    // Both entry circles pass through the contour point: no line can lead to them from there.
    EXPECT_FALSE(tangentialEntry({30, 20}, {30, 20}, {0, 1}, 5.0).has_value());
}

TEST(FagorLocationCodes, CornersAreOddSidesEven) {
    EXPECT_DOUBLE_EQ(tipDirection(3).x, -1.0);
    EXPECT_DOUBLE_EQ(tipDirection(3).z, -1.0);
    EXPECT_DOUBLE_EQ(tipDirection(1).x, 1.0);
    EXPECT_DOUBLE_EQ(tipDirection(1).z, -1.0);
    EXPECT_DOUBLE_EQ(tipDirection(6).z, 1.0);
    EXPECT_DOUBLE_EQ(tipDirection(6).x, 0.0);
    EXPECT_DOUBLE_EQ(tipDirection(9).x, 0.0);
    EXPECT_DOUBLE_EQ(tipDirection(0).z, 0.0);
    for (int f = 1; f <= 8; ++f) {
        const TipDirection t = tipDirection(f);
        EXPECT_EQ(t.x != 0.0 && t.z != 0.0, f % 2 == 1) << "F" << f;
    }
}

Pose at(double z, double x) {
    Pose p{};
    p[Axis::Z] = z;
    p[Axis::X] = x;
    return p;
}

TEST(FagorWorkZones, NoEntryLinesAndArcs) {
    WorkZones zones;
    zones.setLower(1, Axis::X, 10);
    zones.setUpper(1, Axis::X, 20);
    zones.setLower(1, Axis::Z, -10);
    zones.setUpper(1, Axis::Z, 0);
    EXPECT_FALSE(zones.violation(ContourElement::line(Plane::ZX, at(-20, 15), at(20, 15))));
    zones.setMode(1, WorkZones::Mode::NoEntry);
    // Straight through the box; along its edge (allowed); past it.
    EXPECT_EQ(zones.violation(ContourElement::line(Plane::ZX, at(-20, 15), at(20, 15))), 1);
    EXPECT_FALSE(zones.violation(ContourElement::line(Plane::ZX, at(-20, 20), at(20, 20))));
    EXPECT_FALSE(zones.violation(ContourElement::line(Plane::ZX, at(5, 30), at(5, 0))));
    // An arc around (Z-5, X25) of radius 6 dips 1 mm into the box between its ends.
    const ContourElement dip =
        ContourElement::arc(Plane::ZX, at(1, 25), at(-11, 25), Vec2(-5, 25), -kPi);
    EXPECT_EQ(zones.violation(dip), 1);
    const ContourElement over =
        ContourElement::arc(Plane::ZX, at(1, 25), at(-11, 25), Vec2(-5, 25), kPi);
    EXPECT_FALSE(zones.violation(over));
}

TEST(FagorWorkZones, NoExitAndUnlimitedAxes) {
    WorkZones zones;
    zones.setUpper(2, Axis::X, 50);  // only X limited
    zones.setMode(2, WorkZones::Mode::NoExit);
    EXPECT_FALSE(zones.violation(ContourElement::line(Plane::ZX, at(-500, 10), at(500, 50))));
    EXPECT_EQ(zones.violation(ContourElement::line(Plane::ZX, at(0, 10), at(0, 51))), 2);
    // A half circle from X40 to X40 through X55 leaves it; through X25 it does not.
    EXPECT_EQ(
        zones.violation(ContourElement::arc(Plane::ZX, at(15, 40), at(-15, 40), Vec2(0, 40), kPi)),
        2);
    EXPECT_FALSE(zones.violation(
        ContourElement::arc(Plane::ZX, at(15, 40), at(-15, 40), Vec2(0, 40), -kPi)));
}

}  // namespace
}  // namespace kerf::fagor
