// The probing cycles on a simulated part placed with a known setup error: each result is derived
// by hand from the geometry (shift 1.5 / -0.8 / -0.2 mm, rotation 0.7 degrees about the
// programmed origin).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "core/cycles/probing/probing_14xx.h"
#include "core/cycles/probing/probing_cycle.h"
#include "core/cycles/probing/single_touch.h"
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
    return {.ballRadius = 2.0,
            .probingFeed = 100,
            .maxPath = 20,
            .setUp = 2,
            .track = false,
            .length = 0.0,
            .tableAxes = {}};
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
    const int expected[] = {400, 401, 402, 403, 404, 405, 408, 409, 410, 411, 412, 413,  414, 415,
                            416, 417, 418, 419, 420, 421, 422, 423, 424, 425, 426, 427,  430, 431,
                            441, 444, 460, 461, 462, 463, 480, 481, 482, 483, 484, 1416, 1493};
    auto all = allProbingCycles();
    ASSERT_EQ(all.size(), std::size(expected));
    for (size_t i = 0; i < all.size(); ++i) {
        EXPECT_EQ(all[i]->number, expected[i]);
        EXPECT_EQ(findProbingCycle(expected[i]), all[i]);
        // The TT cycles run through their own interface (tool_measurement.h); 1493 probes nothing
        // (the interpreter hands its parameters to the next 14xx cycle).
        const bool tt = all[i]->number >= 480 && all[i]->number <= 484;
        EXPECT_EQ(all[i]->run == nullptr, tt || all[i]->number == 1493) << all[i]->number;
        EXPECT_EQ(all[i]->toolMeasurement != ToolMeasurementKind::None, tt) << all[i]->number;
    }
    // The old TT cycles 30-33 run as 480-483.
    EXPECT_EQ(findOldToolProbeCycle(31), findProbingCycle(481));
    EXPECT_EQ(findOldToolProbeCycle(34), nullptr);
    EXPECT_EQ(findOldToolProbeCycle(0), nullptr);
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

TEST(ProbingCycles, SlotAndRidgeCentre408And409) {
    // Placed square: a slot 20 wide centred at X 37 has its centre line at 37, the datum Q405.
    SimulatedWorkpiece square;
    square.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    square.add({Box{Vec3(27, 10, -20), Vec3(47, 50, 1)}, false});
    CycleValues v = defaults(408);
    v.set(321, 37), v.set(322, 30), v.set(311, 20), v.set(272, 1), v.set(405, 5);
    CycleRun r = run(408, v, square);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_NEAR(result(r.results, 157), 37.0, kTolerance);
    EXPECT_NEAR(result(r.results, 166), 20.0, kTolerance);
    ASSERT_TRUE(r.results.datum && r.results.datum->measured[0]);
    EXPECT_NEAR(*r.results.datum->measured[0], 37.0, kTolerance);
    EXPECT_FALSE(r.results.datum->measured[1]);
    EXPECT_EQ(r.results.datum->nominal[0], 5.0);

    // Misplaced: along X the turned slot measures 20 / cos a (each touch short of its wall),
    // its centre line crossing Y 30 as for 425.
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    part.add({Box{Vec3(27, 10, -20), Vec3(47, 50, 1)}, false});
    const Vec2 c = placed(Vec2(37, 30));
    r = run(408, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_NEAR(result(r.results, 157), c.x() - (30.0 - c.y()) * std::tan(kAngle), kTolerance);
    EXPECT_NEAR(result(r.results, 166), 20.0 / std::cos(kAngle) - 2 * kCosineError, kTolerance);

    // A slot 6 wide is narrower than 2 (r_b + SET_UP): both touches start from its centre.
    SimulatedWorkpiece narrow;
    narrow.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    narrow.add({Box{Vec3(20, 34, -20), Vec3(80, 40, 1)}, false});
    CycleValues n = defaults(408);
    n.set(321, 50), n.set(322, 37), n.set(311, 6), n.set(272, 2), n.set(301, 1);
    r = run(408, n, narrow);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_NEAR(result(r.results, 157), 37.0, kTolerance);
    EXPECT_NEAR(result(r.results, 166), 6.0, kTolerance);
    EXPECT_TRUE(r.results.datum->measured[1]);

    // A ridge 20 wide along Y at Y 25, misplaced, with the top touched too (Q381).
    SimulatedWorkpiece ridge = misplaced();
    ridge.add({Box{Vec3(10, 15, -20), Vec3(90, 35, 0)}, true});
    CycleValues g = defaults(409);
    g.set(321, 50), g.set(322, 25), g.set(311, 20), g.set(272, 2);
    g.set(381, 1), g.set(382, 50), g.set(383, 25), g.set(384, 0), g.set(333, 1);
    r = run(409, g, ridge);
    ASSERT_FALSE(r.error) << r.error->code;
    const Vec2 m = placed(Vec2(50, 25));
    EXPECT_NEAR(result(r.results, 157), m.y() + (50.0 - m.x()) * std::tan(kAngle), kTolerance);
    EXPECT_NEAR(result(r.results, 166), 20.0 / std::cos(kAngle) + 2 * kCosineError, kTolerance);
    EXPECT_NEAR(*r.results.datum->measured[2], -0.2, kTolerance);
    EXPECT_EQ(r.results.datum->nominal[2], 1.0);

    // Q305 > 0 with Q303 = -1: PRB-004 before anything moves.
    g.set(305, 3), g.set(303, -1);
    r = run(409, g, ridge);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error->code, "PRB-004");
    EXPECT_EQ(r.touches, 0);
}

TEST(ProbingCycles, RotationFromTwoHoles401AndTwoStuds402) {
    // Two holes (diameters 10 and 14, unknown to 401) at (20, 15) and (80, 35): the line between
    // their real centres is the programmed line turned by a, so 401 finds atan(20 / 60) + a.
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    part.add({Cylinder{Vec2(20, 15), 5.0, -20, 1}, false});
    part.add({Cylinder{Vec2(80, 35), 7.0, -20, 1}, false});
    const double line = std::atan2(20.0, 60.0) * 180.0 / std::numbers::pi;
    CycleValues v = defaults(401);
    v.set(268, 20), v.set(269, 15), v.set(270, 80), v.set(271, 35), v.set(307, 10);
    CycleRun r = run(401, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_NEAR(*r.results.basicRotationDeg, line + 0.7 - 10.0, 1e-7);
    EXPECT_EQ(r.touches, 8);
    v.set(402, 1);
    r = run(401, v, part);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error->code, "PRB-011");

    // Two studs of diameters 20 and 30, the second 5 lower: 402 at the two measuring heights.
    SimulatedWorkpiece studs = misplaced();
    studs.add({Cylinder{Vec2(20, 15), 10.0, -20, 0}, true});
    studs.add({Cylinder{Vec2(80, 35), 15.0, -20, -5}, true});
    CycleValues s = defaults(402);
    s.set(268, 20), s.set(269, 15), s.set(313, 22), s.set(261, -3);
    s.set(270, 80), s.set(271, 35), s.set(314, 32), s.set(315, -8);
    r = run(402, s, studs);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_NEAR(*r.results.basicRotationDeg, line + 0.7, 1e-7);
    // Measuring stud 2 1 mm above its top finds nothing.
    s.set(315, -2);
    r = run(402, s, studs);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error->code, "PRB-001");
}

TEST(ProbingCycles, DatumFromFourHoles418) {
    // Holes at the corners of a rectangle 130 x 60: the diagonals 1-3 and 2-4 cross at its
    // centre (85, 55), which lies at placed(85, 55).
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(0, 0, -40), Vec3(170, 110, 0)}, true});
    const Vec2 holes[] = {{20, 25}, {150, 25}, {150, 85}, {20, 85}};
    for (const Vec2& h : holes)
        part.add({Cylinder{h, 4.0, -20, 1}, false});
    CycleValues v = defaults(418);
    v.set(268, 20), v.set(269, 25), v.set(270, 150), v.set(271, 25);
    v.set(316, 150), v.set(317, 85), v.set(318, 20), v.set(319, 85);
    v.set(331, 1), v.set(332, 2);
    CycleRun r = run(418, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    const Vec2 c = placed(Vec2(85, 55));
    EXPECT_NEAR(result(r.results, 151), c.x(), kTolerance);
    EXPECT_NEAR(result(r.results, 152), c.y(), kTolerance);
    EXPECT_EQ(r.touches, 16);
    ASSERT_TRUE(r.results.datum);
    EXPECT_EQ(r.results.datum->nominal[0], 1.0);
    EXPECT_EQ(r.results.datum->nominal[1], 2.0);
    // Holes 2 and 4 given in the order of 1 and 3: the two lines are parallel.
    v.set(270, 20), v.set(271, 45), v.set(318, 150), v.set(319, 105);
    SimulatedWorkpiece parallel;
    parallel.add({Box{Vec3(0, 0, -40), Vec3(170, 110, 0)}, true});
    for (const Vec2& h : {Vec2(20, 25), Vec2(20, 45), Vec2(150, 85), Vec2(150, 105)})
        parallel.add({Cylinder{h, 4.0, -20, 1}, false});
    r = run(418, v, parallel);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error->code, "PRB-019");
}

TEST(ProbingCycles, MeasureBoltHoleCircle430) {
    // Holes of diameter 8 at 0, 90 and 180 degrees on a circle of diameter 40 about (50, 30).
    const auto partWith = [](SimulatedWorkpiece part) {
        part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
        for (const Vec2& h : {Vec2(70, 30), Vec2(50, 50), Vec2(30, 30)})
            part.add({Cylinder{h, 4.0, -20, 1}, false});
        return part;
    };
    CycleValues v = defaults(430);
    v.set(273, 50), v.set(274, 30), v.set(262, 40), v.set(291, 0), v.set(292, 90);
    v.set(293, 180), v.set(288, 40.1), v.set(289, 39.9), v.set(279, 0.15), v.set(280, 0.15);
    CycleRun r = run(430, v, partWith(SimulatedWorkpiece()));
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_NEAR(result(r.results, 151), 50.0, kTolerance);
    EXPECT_NEAR(result(r.results, 152), 30.0, kTolerance);
    EXPECT_NEAR(result(r.results, 153), 40.0, kTolerance);
    EXPECT_EQ(result(r.results, 180), 1.0);
    // Misplaced, the circle keeps its diameter; its centre is off by more than 0.15: scrap.
    r = run(430, v, partWith(misplaced()));
    ASSERT_FALSE(r.error) << r.error->code;
    const Vec2 c = placed(Vec2(50, 30));
    EXPECT_NEAR(result(r.results, 161), c.x() - 50.0, kTolerance);
    EXPECT_NEAR(result(r.results, 162), c.y() - 30.0, kTolerance);
    EXPECT_NEAR(result(r.results, 163), 0.0, kTolerance);
    EXPECT_EQ(result(r.results, 180), 0.0);
    EXPECT_EQ(result(r.results, 181), 0.0);
    EXPECT_EQ(result(r.results, 182), 1.0);
    // A bolt circle too small is scrap too (not rework, spec 1.13).
    v.set(279, 0), v.set(280, 0), v.set(288, 40.5), v.set(289, 40.2);
    r = run(430, v, partWith(SimulatedWorkpiece()));
    EXPECT_EQ(result(r.results, 182), 1.0);
    EXPECT_EQ(result(r.results, 181), 0.0);
}

// A machine whose only surface is the plane z = t0 + a x + b y: a ball coming down along -z
// touches it where its centre is r sqrt(1 + a^2 + b^2) above the plane.
class PlaneMachine final : public ProbingMachine {
public:
    PlaneMachine(double t0, double a, double b) : m_t0(t0), m_a(a), m_b(b) {}
    Vec3 ballCentre() const override { return m_at; }
    void moveTo(const Vec3& to) override { m_at = to; }
    std::optional<Vec3> touch(const Vec3& direction, double maxPath) override {
        EXPECT_EQ(direction, Vec3(0, 0, -1));
        const double contact = m_t0 + m_a * m_at.x() + m_b * m_at.y() +
                               probe().ballRadius * std::sqrt(1 + m_a * m_a + m_b * m_b);
        if (m_at.z() - contact > maxPath) return std::nullopt;
        return Vec3(m_at.x(), m_at.y(), contact);
    }

private:
    double m_t0, m_a, m_b;
    Vec3 m_at{0.0, 0.0, 50.0};
};

TEST(ProbingCycles, MeasurePlane431GivesProjectionAndSpatialAngles) {
    CycleValues v = defaults(431);
    v.set(263, 20), v.set(264, 20), v.set(294, 3);
    v.set(265, 50), v.set(266, 20), v.set(295, 4);
    v.set(296, 20), v.set(297, 50), v.set(298, 3);
    const double deg = std::numbers::pi / 180.0;
    // Rising by 3 degrees along the main axis: turned about S, B = -3.
    PlaneMachine alongMain(2.0, std::tan(3 * deg), 0.0);
    ProbingResults r;
    ASSERT_FALSE(findProbingCycle(431)->run(v, probe(), alongMain, r));
    EXPECT_NEAR(result(r, 158), 0.0, 1e-9);
    EXPECT_NEAR(result(r, 159), -3.0, 1e-9);
    EXPECT_NEAR(result(r, 170), 0.0, 1e-9);
    EXPECT_NEAR(result(r, 171), -3.0, 1e-9);
    EXPECT_NEAR(result(r, 172), 0.0, 1e-9);
    // The surface heights at the points, less the ball's cosine error r (1 / cos 3deg - 1).
    const double lift = 2.0 * (1.0 / std::cos(3 * deg) - 1.0);
    EXPECT_NEAR(result(r, 173), 2.0 + 20 * std::tan(3 * deg) + lift, 1e-9);
    EXPECT_NEAR(result(r, 174), 2.0 + 50 * std::tan(3 * deg) + lift, 1e-9);
    // Rising by 4 degrees along the secondary axis: turned about M, A = +4.
    PlaneMachine alongSecondary(2.0, 0.0, std::tan(4 * deg));
    r = {};
    ASSERT_FALSE(findProbingCycle(431)->run(v, probe(), alongSecondary, r));
    EXPECT_NEAR(result(r, 158), 4.0, 1e-9);
    EXPECT_NEAR(result(r, 159), 0.0, 1e-9);
    EXPECT_NEAR(result(r, 170), 4.0, 1e-9);
    EXPECT_NEAR(result(r, 171), 0.0, 1e-9);
    EXPECT_NEAR(result(r, 172), 0.0, 1e-9);
    // Three points on one line: PRB-008.
    v.set(296, 80), v.set(297, 20);
    r = {};
    auto error = findProbingCycle(431)->run(v, probe(), alongSecondary, r);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "PRB-008");
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
    // Q330: a slot too wide means the tool cut too large: DR grows by half the excess.
    ASSERT_TRUE(r.results.toolCorrection);
    EXPECT_NEAR(r.results.toolCorrection->delta, (slot - 20.0) / 2.0, kTolerance);
    EXPECT_FALSE(r.results.toolCorrection->length);
    EXPECT_EQ(result(r.results, 180), 1.0);

    SimulatedWorkpiece ridge = misplaced();
    ridge.add({Box{Vec3(40, 10, -20), Vec3(60, 50, 0)}, true});
    r = run(426, v, ridge);
    ASSERT_FALSE(r.error) << r.error->code;
    const double width = 20.0 / std::cos(kAngle) + 2 * kCosineError;
    EXPECT_NEAR(result(r.results, 156), width, kTolerance);
    // A ridge too wide: the tool cut too small, DR shrinks.
    EXPECT_NEAR(r.results.toolCorrection->delta, -(width - 20.0) / 2.0, kTolerance);
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
    // strtod reads these as numbers; a tolerance that no deviation can exceed is refused too.
    for (const char* notFinite : {"nan", "inf", "1-inf", "1e999"}) {
        v.setText(400, notFinite);
        const CycleRun refused = run(1416, v, part);
        ASSERT_TRUE(refused.error) << notFinite;
        EXPECT_EQ(refused.error->code, "cycle-parameter") << notFinite;
    }
}

TEST(ProbingCycles, Intersection1416InTheYzPlaneFindsTheTopFrontEdge) {
    // Q1139 = 1: angles from Y towards Z, Q1102 the X of the touches. Edge 1 the top face
    // (0 degrees, probed at -90: along -Z), edge 2 the front face (90 degrees, probed at 0:
    // along +Y). The blank turned by 0.7 about Z keeps its top at Z -0.2; at X 50 its front face
    // lies at Y = (50 - 1.5) tan a - 0.8, and the ball stops the cosine error short of it.
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    CycleValues v = defaults(1416);
    v.set(1139, 1), v.set(1100, 0), v.set(1101, 0), v.set(1102, 50);
    v.set(1130, 0), v.set(1131, -1), v.set(1132, 10), v.set(1133, 40);
    v.set(1134, 90), v.set(1135, -1), v.set(1136, -10), v.set(1137, -30);
    v.set(1120, 1);
    CycleRun r = run(1416, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    const double front = 48.5 * std::tan(kAngle) - 0.8 - kCosineError;
    EXPECT_NEAR(result(r.results, 959), front, kTolerance);
    EXPECT_NEAR(result(r.results, 960), -0.2, kTolerance);
    EXPECT_NEAR(result(r.results, 989), front, kTolerance);
    EXPECT_NEAR(result(r.results, 990), -0.2, kTolerance);
    // Point 1 (Y 10, Z 0) is found 0.2 lower; point 3 (Y 0, Z -10) at the front face.
    EXPECT_NEAR(result(r.results, 950), 10.0, kTolerance);
    EXPECT_NEAR(result(r.results, 951), -0.2, kTolerance);
    EXPECT_NEAR(result(r.results, 952), 50.0, kTolerance);
    EXPECT_NEAR(result(r.results, 981), -0.2, kTolerance);
    EXPECT_NEAR(result(r.results, 986), front, kTolerance);
    EXPECT_NEAR(result(r.results, 987), 0.0, kTolerance);
    // Both edges lie parallel to their nominal lines.
    EXPECT_NEAR(result(r.results, 964), 0.0, 1e-7);
    // The preset moves in Y and Z; X is not measured.
    ASSERT_TRUE(r.results.datum);
    EXPECT_FALSE(r.results.datum->measured[0]);
    EXPECT_NEAR(r.results.datum->measured[1].value_or(1e9), front, kTolerance);
    EXPECT_NEAR(r.results.datum->measured[2].value_or(1e9), -0.2, kTolerance);
    EXPECT_EQ(r.touches, 4);
    // A turn about X is no basic rotation about the tool axis: refused.
    v.set(1121, 1);
    ASSERT_TRUE(run(1416, v, part).error);
    EXPECT_EQ(run(1416, v, part).error->code, "cycle-parameter");
}

TEST(ProbingCycles, Intersection1416InTheZxPlaneFindsTheTopRightEdge) {
    // Q1139 = 2: angles from Z towards X, Q1102 the Y of the touches. Edge 1 the top face
    // (90 degrees: along X, probed at 180: along -Z), edge 2 the right face (0 degrees: along
    // Z, probed at -90: along -X), nominal corner Z 0, X 100, at Y 30. The right face turned by
    // a about Z passes Y 30 at X = 100 cos a - y sin a + 1.5 with y = (30.8 - 100 sin a) / cos a;
    // the ball touching it along -X stops the cosine error beyond it.
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    CycleValues v = defaults(1416);
    v.set(1139, 2), v.set(1100, 0), v.set(1101, 100), v.set(1102, 30);
    v.set(1130, 90), v.set(1131, 1), v.set(1132, -10), v.set(1133, -40);
    v.set(1134, 0), v.set(1135, -1), v.set(1136, -10), v.set(1137, -30);
    CycleRun r = run(1416, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    const double s = std::sin(kAngle), c = std::cos(kAngle);
    const double y = (30.8 - 100.0 * s) / c;
    const double right = 100.0 * c - y * s + 1.5 + kCosineError;
    EXPECT_NEAR(result(r.results, 959), -0.2, kTolerance);
    EXPECT_NEAR(result(r.results, 960), right, kTolerance);
    EXPECT_NEAR(result(r.results, 990), right - 100.0, kTolerance);
    // Point 1 (Z 0, X 90) on the top face.
    EXPECT_NEAR(result(r.results, 950), -0.2, kTolerance);
    EXPECT_NEAR(result(r.results, 951), 90.0, kTolerance);
    EXPECT_NEAR(result(r.results, 952), 30.0, kTolerance);
    EXPECT_EQ(r.touches, 4);
}

// The front-left corner of the turned blank as in Intersection1416FindsTheCornerOfTheTurnedBlank.
CycleValues frontLeftCorner() {
    CycleValues v = defaults(1416);
    v.set(1100, 0), v.set(1101, 0), v.set(1102, -5);
    v.set(1130, 0), v.set(1131, 1), v.set(1132, 10), v.set(1133, 40);
    v.set(1134, 90), v.set(1135, -1), v.set(1136, 10), v.set(1137, 40);
    return v;
}

TEST(ProbingCycles, Intersection1416TakesAnActualPositionInsteadOfProbingThatEdge) {
    // Q1100 = 0@1.5: the left face (edge 2, probed along X) is known to lie at X 1.5 and is not
    // probed; edge 1 (the front face, probed along Y) is. The measured front face at x runs at
    // y = -0.8 + (x - 1.5) tan a less the cosine error, so it meets X 1.5 at Y -0.8 - e.
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    CycleValues v = frontLeftCorner();
    setActualPosition(v, 1100, 1.5);
    v.set(1121, 5);
    CycleRun r = run(1416, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_EQ(r.touches, 2);
    const double e = kCosineError;
    EXPECT_NEAR(result(r.results, 959), 1.5, kTolerance);
    EXPECT_NEAR(result(r.results, 960), -0.8 - e, kTolerance);
    EXPECT_NEAR(result(r.results, 989), 1.5, kTolerance);
    EXPECT_NEAR(result(r.results, 990), -0.8 - e, kTolerance);
    // Point 3 (edge 2 at Y 10) is its nominal point moved onto X 1.5.
    EXPECT_NEAR(result(r.results, 956), 1.5, kTolerance);
    EXPECT_NEAR(result(r.results, 957), 10.0, kTolerance);
    EXPECT_NEAR(result(r.results, 986), 1.5, kTolerance);
    EXPECT_NEAR(result(r.results, 987), 0.0, kTolerance);
    // Edge 2 lies at its nominal angle, edge 1 turned by 0.7: their mean is 0.35.
    EXPECT_NEAR(result(r.results, 964), 0.35, 1e-7);

    // Both coordinates known: nothing is probed, the corner is the actual position.
    setActualPosition(v, 1101, -0.8);
    r = run(1416, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_EQ(r.touches, 0);
    EXPECT_NEAR(result(r.results, 959), 1.5, kTolerance);
    EXPECT_NEAR(result(r.results, 960), -0.8, kTolerance);
    EXPECT_NEAR(result(r.results, 964), 0.0, 1e-9);
}

TEST(ProbingCycles, Intersection1416TakesTheActualHeightForItsResults) {
    // Q1102 = -5@-5.2: the touches still run at Z -5, the results give the points at -5.2.
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    CycleValues v = frontLeftCorner();
    setActualPosition(v, 1102, -5.2);
    CycleRun r = run(1416, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_EQ(r.touches, 4);
    for (const uint16_t q : {uint16_t{952}, uint16_t{955}, uint16_t{958}})
        EXPECT_NEAR(result(r.results, q), -5.2, 1e-12) << q;
    for (const uint16_t q : {uint16_t{982}, uint16_t{985}, uint16_t{988}})
        EXPECT_NEAR(result(r.results, q), -0.2, 1e-12) << q;
    EXPECT_NEAR(result(r.results, 951), -0.8 + 8.5 * std::tan(kAngle) - kCosineError, kTolerance);
}

TEST(ProbingCycles, Intersection1416RefusesAnActualNoEdgeMeasuresAlone) {
    // Edges at 45 and 135 degrees are probed obliquely: neither gives X alone.
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    CycleValues v = frontLeftCorner();
    v.set(1130, 45), v.set(1134, 135);
    setActualPosition(v, 1100, 1.5);
    const CycleRun r = run(1416, v, part);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error->code, "cycle-parameter");
    EXPECT_EQ(r.touches, 0);
}

TEST(ProbingCycles, Extrusion1493RepeatsTheTouchesAlongTheTopFrontEdge) {
    // In the YZ plane at X 50 (as Intersection1416InTheYzPlaneFindsTheTopFrontEdge) with the
    // extrusion along the main axis X, +40 in 2 steps: each touch point again at X 70 and X 90.
    // Q970-Q972 are each touch point's largest deviation from its ideal line (the nominal point
    // moved along X). The top face lies at Z -0.2 everywhere (Q970 = Q971 = -0.2); the front face
    // turned by 0.7 degrees lies at Y = (x - 1.5) tan a - 0.8, so its deviation along the surface
    // normal (-Y) is 0.8 - (x - 1.5) tan a + e: +0.208 at X 50, -0.037 at X 70, -0.281 at X 90
    // (Q972, the largest).
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    CycleValues v = defaults(1416);
    v.set(1139, 1), v.set(1100, 0), v.set(1101, 0), v.set(1102, 50);
    v.set(1130, 0), v.set(1131, -1), v.set(1132, 10), v.set(1133, 40);
    v.set(1134, 90), v.set(1135, -1), v.set(1136, -10), v.set(1137, -30);
    // Within +0.5 / -0.25 at X 50: the front face's deviation there is 0.8 - 48.5 tan a + e.
    v.setText(401, "0.5-0.25");
    CycleRun r = run(1416, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_EQ(r.touches, 4);
    EXPECT_EQ(result(r.results, 183), 0.0);

    v.set(1140, 1), v.set(1145, 40), v.set(1146, 2);
    r = run(1416, v, part);
    ASSERT_FALSE(r.error) << r.error->code;
    EXPECT_EQ(r.touches, 12);
    const double t = std::tan(kAngle);
    EXPECT_NEAR(result(r.results, 970), -0.2, kTolerance);
    EXPECT_NEAR(result(r.results, 971), -0.2, kTolerance);
    EXPECT_NEAR(result(r.results, 972), 0.8 - 88.5 * t + kCosineError, kTolerance);
    // The edge itself is still measured from the touches at X 50.
    const double front = 48.5 * t - 0.8 - kCosineError;
    EXPECT_NEAR(result(r.results, 959), front, kTolerance);
    // At X 90 the deviation is 0.8 - 88.5 tan a + e = -0.281: below -0.25, scrap.
    EXPECT_EQ(result(r.results, 183), 2.0);
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

// Two touches at one spot give no line: atan2(0, 0) made it a basic rotation of 0 degrees
// (cycles 400, 420, 401 ran with exit code 0), and 1416 computed an infinite corner that only the
// preset table refused ("column X cannot hold an infinite number").
TEST(ProbingCycles, TouchPointsThatCoincideDefineNoLine) {
    SimulatedWorkpiece part = misplaced();
    part.add({Box{Vec3(0, 0, -40), Vec3(100, 60, 0)}, true});
    CycleValues v = defaults(400);
    v.set(263, 10), v.set(264, 0), v.set(265, 10), v.set(266, 0), v.set(272, 2), v.set(267, 1);
    CycleRun r = run(400, v, part);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error->code, "cycle-parameter");
    EXPECT_FALSE(r.results.basicRotationDeg);
    // 420: the same two points on the front face.
    CycleValues a = defaults(420);
    a.set(263, 30), a.set(264, 0), a.set(265, 30), a.set(266, 0), a.set(272, 2), a.set(267, 1);
    r = run(420, a, part);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error->code, "cycle-parameter");
    // 1416: both touches of the first edge 40 mm from the nominal corner.
    CycleValues i = defaults(1416);
    i.set(1100, 0), i.set(1101, 0), i.set(1102, -5);
    i.set(1130, 0), i.set(1131, 1), i.set(1132, 40), i.set(1133, 40);
    i.set(1134, 90), i.set(1135, -1), i.set(1136, 10), i.set(1137, 40);
    i.set(1120, 1), i.set(1121, 5);
    i.setText(400, "2"), i.setText(401, "2");
    r = run(1416, i, part);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error->code, "cycle-parameter");
    EXPECT_FALSE(r.results.datum);
    // 401: both holes programmed at one place (the same hole measured twice).
    part.add({Cylinder{Vec2(20, 15), 5.0, -20, 1}, false});
    CycleValues h = defaults(401);
    h.set(268, 20), h.set(269, 15), h.set(270, 20), h.set(271, 15);
    r = run(401, h, part);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error->code, "cycle-parameter");
    EXPECT_FALSE(r.results.basicRotationDeg);
}

TEST(ProbingCycles, PolarDirectionTurnsFromTheAxisTowardsTheNextOfItsPlane) {
    // Cycles 1 and 3 (spec 4): X turns towards Y, Y towards Z, Z towards X.
    const double c = std::cos(std::numbers::pi / 6.0);
    EXPECT_TRUE(polarDirection(0, 30.0).isApprox(Vec3(c, 0.5, 0.0), 1e-12));
    EXPECT_TRUE(polarDirection(1, 30.0).isApprox(Vec3(0.0, c, 0.5), 1e-12));
    EXPECT_TRUE(polarDirection(2, 30.0).isApprox(Vec3(0.5, 0.0, c), 1e-12));
    EXPECT_TRUE(polarDirection(0, -90.0).isApprox(Vec3(0.0, -1.0, 0.0), 1e-12));
}

TEST(ProbingCycles, SingleTouchRetractsByMbButNeverBeyondItsStart) {
    // A face at x = 10 (box from x 10): the ball of radius 2 from x 0 along +X stops at 8.
    SimulatedWorkpiece part;
    part.add({Box{Vec3(10, -50, -50), Vec3(60, 50, 50)}, true});
    PartMachine machine(part, 2.0);
    machine.moveTo(Vec3(0, 0, 0));
    SingleTouch touch;
    touch.direction = Vec3(1, 0, 0);
    touch.maxPath = 20.0;
    touch.retract = 3.0;
    touch.missIsError = false;
    SingleTouchResult r;
    ASSERT_FALSE(runSingleTouch(3, touch, probe(), machine, r));
    EXPECT_TRUE(r.valid);
    EXPECT_NEAR(r.ball.x(), 8.0, 1e-9);
    EXPECT_NEAR(machine.ballCentre().x(), 5.0, 1e-9);
    // MB 50 from 8 mm away: back to the start only.
    machine.moveTo(Vec3(0, 0, 0));
    touch.retract = 50.0;
    ASSERT_FALSE(runSingleTouch(3, touch, probe(), machine, r));
    EXPECT_NEAR(machine.ballCentre().x(), 0.0, 1e-9);
    // Nothing within 5 mm: invalid, no error, 3 back from where the path ended.
    touch.maxPath = 5.0;
    touch.retract = 3.0;
    ASSERT_FALSE(runSingleTouch(3, touch, probe(), machine, r));
    EXPECT_FALSE(r.valid);
    EXPECT_NEAR(machine.ballCentre().x(), 2.0, 1e-9);
    // Cycles 0 and 1: a miss within the probe table's DIST (20) is PRB-001.
    machine.moveTo(Vec3(-30, 0, 0));
    touch.maxPath.reset();
    touch.retract.reset();
    touch.missIsError = true;
    auto error = runSingleTouch(0, touch, probe(), machine, r);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "PRB-001");
}

}  // namespace
}  // namespace kerf::cycles::probing
