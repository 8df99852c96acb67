// The probing cycles on a simulated part placed with a known setup error: each result is derived
// by hand from the geometry (shift 1.5 / -0.8 / -0.2 mm, rotation 0.7 degrees about the
// programmed origin).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/cycles/probing/probing_cycle.h"
#include "core/workpiece/simulated_workpiece.h"

namespace kerf::cycles::probing {
namespace {

using workpiece::Box;
using workpiece::Cylinder;
using workpiece::SimulatedWorkpiece;

constexpr double kTolerance = 1e-6;  // 1 nm: the touches are exact, the allowance is 1 um
const double kAngle = 0.7 * std::numbers::pi / 180.0;
const Vec3 kShift(1.5, -0.8, -0.2);

// A ball touching a face turned by a, axis-parallel: its centre stops r / cos a from the face
// along the touch, so the compensated point B + r d stays this much short of the face.
const double kCosineError = 2.0 * (1.0 / std::cos(kAngle) - 1.0);

// The real position of a programmed point of the part.
Vec2 placed(const Vec2& programmed) {
    return Vec2(programmed.x() * std::cos(kAngle) - programmed.y() * std::sin(kAngle),
                programmed.x() * std::sin(kAngle) + programmed.y() * std::cos(kAngle)) +
           kShift.head<2>();
}

// The machine of the tests: the ball touches the simulated part; program = machine coordinates.
class PartMachine final : public ProbingMachine {
public:
    PartMachine(const SimulatedWorkpiece& part, double radius) : m_part(part), m_radius(radius) {}
    Vec3 ballCentre() const override { return m_at; }
    void moveTo(const Vec3& to) override {
        m_at = to;
        ++moves;
    }
    std::optional<Vec3> touch(const Vec3& direction, double maxPath) override {
        ++touches;
        return m_part.touch(m_at, direction, maxPath, m_radius);
    }
    bool deflected() const override { return m_part.touches(m_at, m_radius); }
    int moves = 0;
    int touches = 0;

private:
    const SimulatedWorkpiece& m_part;
    double m_radius;
    Vec3 m_at{0.0, 0.0, 50.0};
};

ProbeData probe() {
    return {.ballRadius = 2.0, .probingFeed = 100, .maxPath = 20, .setUp = 2};
}

SimulatedWorkpiece misplaced() {
    return SimulatedWorkpiece({kShift, 0.7});
}

CycleValues defaults(int cycle) {
    CycleValues v;
    for (const ParameterDescriptor& d : findProbingCycle(cycle)->parameters)
        v.set(d.q, d.defaultValue);
    v.set(261, -5.0);
    v.set(260, 20.0);
    return v;
}

double result(const ProbingResults& r, uint16_t q) {
    for (auto it = r.parameters.rbegin(); it != r.parameters.rend(); ++it)
        if (it->first == q) return it->second;
    ADD_FAILURE() << "Q" << q << " not written";
    return 0.0;
}

struct CycleRun {
    std::optional<CycleError> error;
    ProbingResults results;
    int touches = 0;
};

CycleRun run(int cycle, const CycleValues& v, const SimulatedWorkpiece& part) {
    PartMachine machine(part, probe().ballRadius);
    CycleRun r;
    r.error = findProbingCycle(cycle)->run(v, probe(), machine, r.results);
    r.touches = machine.touches;
    // Every cycle ends at the clearance height.
    if (!r.error) {
        EXPECT_GE(machine.ballCentre().z(), v.number(260) + probe().ballRadius - 1e-9);
    }
    return r;
}

TEST(ProbingCycles, RegistryHoldsEachCycleOnceInNumberOrder) {
    const int expected[] = {400, 410, 411, 412, 413, 414, 415, 416, 417, 419,
                            420, 421, 422, 423, 424, 425, 426, 427, 1416};
    auto all = allProbingCycles();
    ASSERT_EQ(all.size(), std::size(expected));
    for (size_t i = 0; i < all.size(); ++i) {
        EXPECT_EQ(all[i]->number, expected[i]);
        EXPECT_EQ(findProbingCycle(expected[i]), all[i]);
        EXPECT_NE(all[i]->run, nullptr);
    }
}

TEST(ProbingCycles, BasicRotation400MeasuresTheTurnOfAnEdge) {
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    CycleValues v = defaults(400);
    v.set(263, 10), v.set(264, 0), v.set(265, 60), v.set(266, 0);
    v.set(272, 2), v.set(267, 1);
    CycleRun r = run(400, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    ASSERT_TRUE(r.results.basicRotationDeg);
    EXPECT_NEAR(*r.results.basicRotationDeg, 0.7, 1e-7);
    EXPECT_EQ(r.touches, 2);
    // The reference line's angle Q307 is subtracted.
    v.set(307, 2.0);
    EXPECT_NEAR(*run(400, v, part).results.basicRotationDeg, -1.3, 1e-7);
}

TEST(ProbingCycles, DatumOutsideCircle413FindsTheShiftedStudAndItsTop) {
    SimulatedWorkpiece part = misplaced();
    part.add({Cylinder{Vec2(0, 0), 25.0, -30.0, 0.0}, true});
    CycleValues v = defaults(413);
    v.set(262, 52), v.set(325, 0), v.set(247, 90), v.set(381, 1);
    v.set(382, 0), v.set(383, 0), v.set(384, 0), v.set(305, 0);
    CycleRun r = run(413, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_NEAR(result(r.results, 151), 1.5, kTolerance);
    EXPECT_NEAR(result(r.results, 152), -0.8, kTolerance);
    EXPECT_NEAR(result(r.results, 153), 50.0, kTolerance);
    ASSERT_TRUE(r.results.datum);
    EXPECT_NEAR(*r.results.datum->measured[0], 1.5, kTolerance);
    EXPECT_NEAR(*r.results.datum->measured[1], -0.8, kTolerance);
    EXPECT_NEAR(*r.results.datum->measured[2], -0.2, kTolerance);
    EXPECT_EQ(r.touches, 5);
}

TEST(ProbingCycles, DatumInsideCircle412AndMeasureHole421FindTheTurnedHole) {
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    part.add({Cylinder{Vec2(50, 30), 15.0, -30.0, 1.0}, false});
    const Vec2 centre = placed(Vec2(50, 30));
    CycleValues v = defaults(412);
    v.set(321, 50), v.set(322, 30), v.set(262, 29), v.set(325, 10), v.set(247, 120);
    v.set(423, 3);
    CycleRun r = run(412, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_NEAR(result(r.results, 151), centre.x(), kTolerance);
    EXPECT_NEAR(result(r.results, 152), centre.y(), kTolerance);
    EXPECT_NEAR(result(r.results, 153), 30.0, kTolerance);
    EXPECT_EQ(r.touches, 3);

    CycleValues m = defaults(421);
    m.set(273, 50), m.set(274, 30), m.set(262, 30), m.set(247, 90);
    m.set(275, 30.01), m.set(276, 29.99), m.set(279, 2.0), m.set(280, 2.0), m.set(281, 1);
    r = run(421, m, part);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_NEAR(result(r.results, 161), centre.x() - 50.0, kTolerance);
    EXPECT_NEAR(result(r.results, 162), centre.y() - 30.0, kTolerance);
    EXPECT_NEAR(result(r.results, 163), 0.0, kTolerance);
    EXPECT_EQ(result(r.results, 180), 1.0);  // within every tolerance
    EXPECT_EQ(result(r.results, 181), 0.0);
    EXPECT_EQ(result(r.results, 182), 0.0);
    ASSERT_TRUE(r.results.protocol);
    EXPECT_NE(std::find(r.results.protocol->begin(), r.results.protocol->end(),
                        "  diameter                  +30.0000"),
              r.results.protocol->end());
}

TEST(ProbingCycles, ToleranceMonitoringSortsReworkAndScrapAndStopsWithQ309) {
    SimulatedWorkpiece part;
    part.add({Box{Vec3(-40, -40, -40), Vec3(40, 40, 0)}, true});
    part.add({Cylinder{Vec2(0, 0), 15.025, -30.0, 1.0}, false});  // a hole 0.05 too large
    CycleValues m = defaults(421);
    m.set(262, 30), m.set(275, 30.02), m.set(276, 29.98), m.set(309, 1);
    CycleRun r = run(421, m, part);
    ASSERT_FALSE(r.error);
    EXPECT_NEAR(result(r.results, 163), 0.05, kTolerance);
    // An oversize hole cannot be saved: scrap (spec 1.13).
    EXPECT_EQ(result(r.results, 180), 0.0);
    EXPECT_EQ(result(r.results, 181), 0.0);
    EXPECT_EQ(result(r.results, 182), 1.0);
    ASSERT_TRUE(r.results.toleranceStop);
    EXPECT_EQ(r.results.toleranceStop->code, "PRB-006");
    // The same hole measured against a centre tolerance it meets and a larger size: rework is
    // for an undersize hole.
    m.set(275, 30.2), m.set(276, 30.1), m.set(309, 0);
    r = run(421, m, part);
    EXPECT_EQ(result(r.results, 181), 1.0);
    EXPECT_EQ(result(r.results, 182), 0.0);
    EXPECT_FALSE(r.results.toleranceStop);
}

TEST(ProbingCycles, DatumRectangle410And411FollowTheTurnedWalls) {
    // Axis-parallel touches at the nominal middle of the sides of a turned rectangle: the mean
    // of two opposite touches lies on the rectangle's centre line, which passes through the real
    // centre c turned by the angle a. Touching along x at y0: x = c.x - (y0 - c.y) tan a.
    SimulatedWorkpiece pocket = misplaced();
    pocket.add({Box{Vec3(-10, -10, -40), Vec3(110, 70, 0)}, true});
    pocket.add({Box{Vec3(20, 10, -20), Vec3(80, 50, 1)}, false});
    const Vec2 c = placed(Vec2(50, 30));
    CycleValues v = defaults(410);
    v.set(321, 50), v.set(322, 30), v.set(323, 58), v.set(324, 38), v.set(301, 0);
    CycleRun r = run(410, v, pocket);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_NEAR(result(r.results, 151), c.x() - (30.0 - c.y()) * std::tan(kAngle), kTolerance);
    EXPECT_NEAR(result(r.results, 152), c.y() + (50.0 - c.x()) * std::tan(kAngle), kTolerance);
    // Each inside touch stops short of its wall.
    EXPECT_NEAR(result(r.results, 154), 60.0 / std::cos(kAngle) - 2 * kCosineError, kTolerance);
    EXPECT_NEAR(result(r.results, 155), 40.0 / std::cos(kAngle) - 2 * kCosineError, kTolerance);

    SimulatedWorkpiece stud = misplaced();
    stud.add({Box{Vec3(20, 10, -20), Vec3(80, 50, 0)}, true});
    v.set(323, 62), v.set(324, 42), v.set(301, 1);
    r = run(411, v, stud);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_NEAR(result(r.results, 151), c.x() - (30.0 - c.y()) * std::tan(kAngle), kTolerance);
    EXPECT_NEAR(result(r.results, 154), 60.0 / std::cos(kAngle) + 2 * kCosineError, kTolerance);
}

TEST(ProbingCycles, DatumInToolAxis417AndSingleAxis419) {
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    CycleValues v = defaults(417);
    v.set(263, 50), v.set(264, 30), v.set(294, 0), v.set(333, 5);
    CycleRun r = run(417, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_NEAR(result(r.results, 160), -0.2, kTolerance);
    EXPECT_NEAR(r.results.datum->nominal[2], 5.0, 0.0);

    // The left face x = 0, turned and shifted, crosses y = 30 at x = 1.5 - 30.8 tan a.
    CycleValues s = defaults(419);
    s.set(263, 0), s.set(264, 30), s.set(272, 1), s.set(267, 1);
    r = run(419, s, part);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_NEAR(result(r.results, 160), 1.5 - 30.8 * std::tan(kAngle) - kCosineError, kTolerance);
    EXPECT_TRUE(r.results.datum->measured[0]);
    EXPECT_FALSE(r.results.datum->measured[1]);
    s.set(263, 50), s.set(272, 3), s.set(261, 0);
    r = run(419, s, part);
    EXPECT_NEAR(result(r.results, 160), -0.2, kTolerance);
}

TEST(ProbingCycles, MeasureWidth425And426) {
    // A slot 20 wide along x, turned: along x it measures 20 / cos a, its centre line as 410.
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    part.add({Box{Vec3(40, 10, -20), Vec3(60, 50, 1)}, false});
    const Vec2 c = placed(Vec2(50, 30));
    CycleValues v = defaults(425);
    v.set(328, 50), v.set(329, 30), v.set(311, 20), v.set(272, 1);
    v.set(288, 20.1), v.set(289, 19.9);
    CycleRun r = run(425, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    const double slot = 20.0 / std::cos(kAngle) - 2 * kCosineError;
    EXPECT_NEAR(result(r.results, 156), slot, kTolerance);
    EXPECT_NEAR(result(r.results, 157), c.x() - (30.0 - c.y()) * std::tan(kAngle), kTolerance);
    EXPECT_NEAR(result(r.results, 166), slot - 20.0, kTolerance);
    EXPECT_EQ(result(r.results, 180), 1.0);

    SimulatedWorkpiece ridge = misplaced();
    ridge.add({Box{Vec3(40, 10, -20), Vec3(60, 50, 0)}, true});
    r = run(426, v, ridge);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_NEAR(result(r.results, 156), 20.0 / std::cos(kAngle) + 2 * kCosineError, kTolerance);
}

TEST(ProbingCycles, DatumOutsideCorner414FindsTheRealCorner) {
    // Corner A (-X, -Y) of the blank, at the shift in reality. Each measured line is parallel to
    // its turned face, the cosine error e in front of it: the front line moved by -e in y, the
    // left line by -e in x. Intersecting them: corner + e (sin a - cos a) (cos a, sin a)
    // + (0, -e).
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    CycleValues v = defaults(414);
    v.set(263, 20), v.set(264, 0), v.set(326, 30), v.set(296, 0), v.set(297, 20), v.set(327, 25);
    v.set(304, 1);
    CycleRun r = run(414, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    const double e = kCosineError, c = std::cos(kAngle), s = std::sin(kAngle);
    EXPECT_NEAR(result(r.results, 151), 1.5 + e * (s - c) * c, kTolerance);
    EXPECT_NEAR(result(r.results, 152), -0.8 + e * (s - c) * s - e, kTolerance);
    ASSERT_TRUE(r.results.basicRotationDeg);
    EXPECT_NEAR(*r.results.basicRotationDeg, 0.7, 1e-7);
    EXPECT_EQ(r.touches, 4);
}

TEST(ProbingCycles, DatumInsideCorner415FindsThePocketCorner) {
    // Corner 1 (-X, -Y) of a pocket; each measured line lies e in front of its wall, inside the
    // pocket: the 414 result with the offsets reversed, K - e (sin a - cos a) (cos a, sin a)
    // + (0, e).
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(-10, -10, -40), Vec3(110, 70, 0)}, true});
    part.add({Box{Vec3(20, 10, -20), Vec3(80, 50, 1)}, false});
    CycleValues v = defaults(415);
    v.set(263, 20), v.set(264, 10), v.set(326, 20), v.set(327, 15), v.set(308, 1);
    CycleRun r = run(415, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    const double e = kCosineError, c = std::cos(kAngle), s = std::sin(kAngle);
    const Vec2 k = placed(Vec2(20, 10));
    EXPECT_NEAR(result(r.results, 151), k.x() - e * (s - c) * c, kTolerance);
    EXPECT_NEAR(result(r.results, 152), k.y() - e * (s - c) * s + e, kTolerance);
}

TEST(ProbingCycles, BoltCircle416FindsTheTurnedCircleOfHoles) {
    // Three holes of 10 mm on a 60 mm circle about (50, 30) at 0, 120 and 240 degrees.
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(0, -10, -40), Vec3(100, 70, 0)}, true});
    for (double deg : {0.0, 120.0, 240.0}) {
        const double a = deg * std::numbers::pi / 180.0;
        part.add(
            {Cylinder{Vec2(50 + 30 * std::cos(a), 30 + 30 * std::sin(a)), 5.0, -30.0, 1.0}, false});
    }
    CycleValues v = defaults(416);
    v.set(273, 50), v.set(274, 30), v.set(262, 60), v.set(291, 0), v.set(292, 120), v.set(293, 240);
    CycleRun r = run(416, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    const Vec2 c = placed(Vec2(50, 30));
    EXPECT_NEAR(result(r.results, 151), c.x(), kTolerance);
    EXPECT_NEAR(result(r.results, 152), c.y(), kTolerance);
    EXPECT_NEAR(result(r.results, 153), 60.0, kTolerance);
    EXPECT_EQ(r.touches, 12);
}

TEST(ProbingCycles, Intersection1416FindsTheCornerOfTheTurnedBlank) {
    // Edge 1 the front face (0 degrees, probed at +90), edge 2 the left face (90 degrees, probed
    // at -90): the same measured lines as 414, so the same corner; both edges turned by 0.7.
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    CycleValues v = defaults(1416);
    v.set(1100, 0), v.set(1101, 0), v.set(1102, -5);
    v.set(1130, 0), v.set(1131, 1), v.set(1132, 10), v.set(1133, 40);
    v.set(1134, 90), v.set(1135, -1), v.set(1136, 10), v.set(1137, 40);
    v.set(1120, 1), v.set(1121, 5);
    v.setText(400, "0.5-0.5");
    v.setText(401, "0.5-0.5");
    CycleRun r = run(1416, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    const double e = kCosineError, c = std::cos(kAngle), s = std::sin(kAngle);
    EXPECT_NEAR(result(r.results, 959), 1.5 + e * (s - c) * c, kTolerance);
    EXPECT_NEAR(result(r.results, 960), -0.8 + e * (s - c) * s - e, kTolerance);
    EXPECT_NEAR(result(r.results, 989), 1.5 + e * (s - c) * c, kTolerance);
    EXPECT_NEAR(result(r.results, 964), 0.7, 1e-7);
    // Touch 1 of edge 1 at x = 10 meets the front face at y = -0.8 + 8.5 tan a, and stops the
    // cosine error in front of it.
    EXPECT_NEAR(result(r.results, 951), -0.8 + 8.5 * std::tan(kAngle) - e, kTolerance);
    EXPECT_NEAR(result(r.results, 981), -0.8 + 8.5 * std::tan(kAngle) - e, kTolerance);
    // Along the surface normals: the front face lies about 0.7 mm outside its nominal place
    // (material left: rework), the left face 1.1 to 1.5 mm inside it (scrap): scrap overall.
    EXPECT_EQ(result(r.results, 183), 2.0);
    ASSERT_TRUE(r.results.datum);
    ASSERT_TRUE(r.results.basicRotationDeg);
    EXPECT_NEAR(*r.results.basicRotationDeg, 0.7, 1e-7);
    // Within a tolerance of 2 mm the part is good; Q1126 without Q1121 is PRB-010.
    v.setText(400, "2"), v.setText(401, "2"), v.set(309, 2);
    r = run(1416, v, part);
    EXPECT_EQ(result(r.results, 183), 0.0);
    v.set(1121, 0), v.set(1126, 1);
    EXPECT_EQ(run(1416, v, part).error->code, "PRB-010");
    v.set(1126, 0), v.setText(400, "abc");
    EXPECT_EQ(run(1416, v, part).error->code, "cycle-parameter");
}

TEST(ProbingCycles, MeasureAngle420RectanglesAndCoordinate427) {
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(-10, -10, -40), Vec3(110, 70, 0)}, true});
    part.add({Box{Vec3(20, 10, -20), Vec3(80, 50, 1)}, false});
    // 420 on the pocket's front wall from inside, probing -Y: the wall's angle.
    CycleValues a = defaults(420);
    a.set(263, 30), a.set(264, 10), a.set(265, 70), a.set(266, 10), a.set(272, 2), a.set(267, -1);
    CycleRun r = run(420, a, part);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_NEAR(result(r.results, 150), 0.7, 1e-7);
    // 423 on the pocket: as 410, compared with the nominal 60 x 40; 0.1 mm of side tolerance
    // hold the 4.5 um a turned wall adds.
    const Vec2 c = placed(Vec2(50, 30));
    CycleValues m = defaults(423);
    m.set(273, 50), m.set(274, 30), m.set(282, 60), m.set(283, 40);
    m.set(284, 60.1), m.set(285, 59.9), m.set(286, 40.1), m.set(287, 39.9);
    m.set(279, 0.5), m.set(280, 0.5);
    r = run(423, m, part);
    ASSERT_FALSE(r.error) << r.error->code;
    const double length = 60.0 / std::cos(kAngle) - 2 * kCosineError;
    EXPECT_NEAR(result(r.results, 154), length, kTolerance);
    EXPECT_NEAR(result(r.results, 164), length - 60.0, kTolerance);
    EXPECT_NEAR(result(r.results, 161), c.x() - (30.0 - c.y()) * std::tan(kAngle) - 50.0,
                kTolerance);
    // The centre is 1.1 mm off in X, beyond its 0.5 mm tolerance: scrap.
    EXPECT_EQ(result(r.results, 182), 1.0);
    // 424 on a stud of the same size: the turned walls add the cosine error outward.
    SimulatedWorkpiece stud = misplaced();
    stud.add({Box{Vec3(20, 10, -20), Vec3(80, 50, 0)}, true});
    m.set(282, 62), m.set(283, 42), m.set(279, 0), m.set(280, 0);
    m.set(284, 0), m.set(285, 0), m.set(286, 0), m.set(287, 0);
    r = run(424, m, stud);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_NEAR(result(r.results, 155), 40.0 / std::cos(kAngle) + 2 * kCosineError, kTolerance);
    EXPECT_EQ(result(r.results, 180), 1.0);  // nothing monitored
    // 427 down onto the top: -0.2; within -0.3 ... -0.1 good, below 0 ... 0.1 scrap.
    CycleValues z = defaults(427);
    z.set(263, 50), z.set(264, 30), z.set(272, 3), z.set(261, 0), z.set(288, -0.1),
        z.set(289, -0.3);
    r = run(427, z, stud);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_NEAR(result(r.results, 160), -0.2, kTolerance);
    EXPECT_EQ(result(r.results, 180), 1.0);
    z.set(288, 0.1), z.set(289, 0.0);
    EXPECT_EQ(result(run(427, z, stud).results, 182), 1.0);
}

TEST(ProbingCycles, ErrorsOfTheManual) {
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    // Nothing within DIST: the edge is programmed 30 mm away from where it is.
    CycleValues v = defaults(400);
    v.set(263, 10), v.set(264, -30), v.set(265, 60), v.set(266, -30), v.set(272, 2), v.set(267, -1);
    CycleRun r = run(400, v, part);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error->code, "PRB-001");
    // A datum for a table row without a transfer mode.
    CycleValues d = defaults(417);
    d.set(305, 3), d.set(303, -1);
    r = run(417, d, part);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error->code, "PRB-004");
    EXPECT_EQ(r.touches, 0);
    // A stepping angle below 5 degrees.
    CycleValues c = defaults(413);
    c.set(262, 50), c.set(247, 4);
    EXPECT_EQ(run(413, c, part).error->code, "PRB-018");
    EXPECT_EQ(findProbingCycle(999), nullptr);
}

}  // namespace
}  // namespace kerf::cycles::probing
