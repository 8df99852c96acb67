#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "canon_builders.h"
#include "motion/kinematics/machine_model.h"
#include "motion/planner/planner.h"
#include "tests/motion/motion_test_run.h"

// CAM polylines followed as smooth curves within the tolerance (issue 15 part 2): the curvature
// comes from the fitted curve, not from the rounding of the vertices; real corners stay corners.
namespace kerf::motion::test {
namespace {

using kerf::test::command;
using kerf::test::pose;

constexpr double kToleranceMm = 0.01;  // the built-in mill's path_tolerance

double rounded(double value, int decimals) {
    double scale = std::pow(10.0, decimals);
    return std::round(value * scale) / scale;
}

// gen.py polycircle: the circle of radius r through the origin, centre (0, r), as lines of
// `seg` mm of arc, coordinates written with `decimals` decimals, `length` mm in all.
std::vector<canon::Command> polylineCircle(double r, double seg, int decimals, double length) {
    std::vector<canon::Command> commands;
    int count = static_cast<int>(std::lround(length / seg));
    for (int i = 1; i <= count; ++i) {
        double s = i * seg;
        commands.push_back(
            command(canon::LinearMove{pose(rounded(r * std::sin(s / r), decimals),
                                           rounded(r - r * std::cos(s / r), decimals), 0.0),
                                      6000.0},
                    static_cast<uint32_t>(i)));
    }
    return commands;
}

// gen.py sine (3D finishing): z = sin(2 pi x / 10) over x, vertices every `seg` mm of x.
std::vector<canon::Command> sinePolyline(double seg, int decimals, double length) {
    std::vector<canon::Command> commands;
    int count = static_cast<int>(std::lround(length / seg));
    for (int i = 1; i <= count; ++i) {
        double x = i * seg;
        commands.push_back(command(
            canon::LinearMove{
                pose(rounded(x, decimals), 0.0, rounded(std::sin(2.0 * M_PI * x / 10.0), decimals)),
                6000.0},
            static_cast<uint32_t>(i)));
    }
    return commands;
}

// A curve of radius r1 for `length1` mm followed tangentially by one of radius r2 (same way)
// for `length2` mm, as lines of `seg` mm of arc with vertices on the curve.
std::vector<canon::Command> polylineOfTwoRadii(double r1, double length1, double r2, double length2,
                                               double seg) {
    std::vector<canon::Command> commands;
    double x = 0.0;
    double y = 0.0;
    double heading = 0.0;
    int count1 = static_cast<int>(std::lround(length1 / seg));
    int count = count1 + static_cast<int>(std::lround(length2 / seg));
    for (int i = 1; i <= count; ++i) {
        double r = i <= count1 ? r1 : r2;
        double turn = seg / r;
        double chord = 2.0 * r * std::sin(turn / 2.0);
        x += chord * std::cos(heading + turn / 2.0);
        y += chord * std::sin(heading + turn / 2.0);
        heading += turn;
        commands.push_back(
            command(canon::LinearMove{pose(x, y, 0.0), 6000.0}, static_cast<uint32_t>(i)));
    }
    return commands;
}

std::vector<PathElement> plannedElements(const std::vector<canon::Command>& commands,
                                         const Pose& start = Pose{}) {
    MachineModel model = makeMachineModel(millConfig(), {});
    Planner planner(model);
    planner.setPosition(start.values);
    std::vector<PathElement> elements;
    auto take = [&] {
        while (auto item = planner.next()) {
            if (item->kind == MotionItem::Kind::Element) elements.push_back(item->element);
        }
    };
    for (const canon::Command& c : commands) {
        EXPECT_TRUE(planner.add(c));
        take();
    }
    planner.flush();
    take();
    return elements;
}

double tangentAngle(const PathGeometry& g, double s, const Vec3Array& direction) {
    PathPoint p = pointAt(g, s);
    double dot = 0.0;
    double norm = 0.0;
    for (size_t i = 0; i < 3; ++i) {
        dot += p.tangent[i] * direction[i];
        norm += p.tangent[i] * p.tangent[i];
    }
    return std::acos(std::clamp(dot / std::sqrt(norm), -1.0, 1.0));
}

TEST(PolylineSmoothing, CurvatureOfAFourDecimalCircleIsThatOfTheCircle) {
    // R50 as 0.005 mm lines written with 4 decimals: the rounding (up to 5e-5 mm per
    // coordinate) gives neighbouring vertices a curvature noise of about 2 delta / l^2 = 4 /mm,
    // 200 times the circle's 0.02 /mm. The path followed has the circle's curvature within 2 %
    // (the knots' rounding over 2 mm spans and +-0.5 mm chords: about 1 % at R50) everywhere
    // but in the run's first and last 2 mm span (the tangents at its ends are one-sided).
    for (double radius : {5.0, 50.0}) {
        SCOPED_TRACE("R" + std::to_string(radius));
        std::vector<PathElement> elements = plannedElements(polylineCircle(radius, 0.005, 4, 20.0));
        size_t checked = 0;
        for (const PathElement& e : elements) {
            if (e.sStart < 2.0 || e.sEnd() > 18.0) continue;
            EXPECT_NEAR(e.geometry.curvature(), 1.0 / radius, 0.02 / radius) << "at s " << e.sStart;
            ++checked;
        }
        EXPECT_GE(checked, 2u);
        // A few arcs per 2 mm instead of two elements per 5 µm line.
        EXPECT_LE(elements.size(), 40u);
    }
}

TEST(PolylineSmoothing, FourDecimalCircleRunsNearTheTimeOptimalBound) {
    // 20 mm of R50 at F6000 from rest to rest: the time-optimal bound along the exact circle is
    // 0.2502 s (shared/tools/motion/bounds.py: topp_acc(circle(50), 20, 100) = 0.2482 s, plus
    // A / J = 2 ms for the jerk ramps). The issue's target is 1.10x of it; as 4-decimal lines
    // each corner was a blend of about 0.25 mm radius and the run took 5.9x.
    TestRun run = runCommands(millConfig(), polylineCircle(50.0, 0.005, 4, 20.0), Pose{});
    SCOPED_TRACE(run.checker->limitSummary());
    EXPECT_FALSE(run.report.refused);
    EXPECT_LE(run.report.feedTimeS, 1.10 * 0.2502);
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
    EXPECT_LE(run.checker->maxDeviation(), kToleranceMm * 1.01);
}

TEST(PolylineSmoothing, AHalfMillimetrePolylineOfR5IsFollowedAsTheCircle) {
    // R5 as 0.5 mm lines: each segment's sagitta is l^2 / 8R = 0.00625 mm, more than the 0.005 mm
    // (half the tolerance) a fitted curve may deviate, so a curve through the vertices cannot
    // follow it (it stayed lines with blended corners: 1.20x of the bound). A curve between the
    // vertices and the segments' midpoints deviates half of it: the circle's curvature, and
    // 100 mm from rest to rest within 1.10x of the bound along the exact circle (1.0491 s:
    // bounds.py topp_acc(circle(5), 100, 100) = 1.0471 s, plus A / J = 2 ms).
    const std::vector<canon::Command> commands = polylineCircle(5.0, 0.5, 4, 100.0);
    size_t checked = 0;
    for (const PathElement& e : plannedElements(commands)) {
        if (e.sStart < 2.0 || e.sEnd() > 98.0) continue;
        EXPECT_NEAR(e.geometry.curvature(), 1.0 / 5.0, 0.02 / 5.0) << "at s " << e.sStart;
        ++checked;
    }
    EXPECT_GE(checked, 10u);
    TestRun run = runCommands(millConfig(), commands, Pose{});
    SCOPED_TRACE(run.checker->limitSummary());
    EXPECT_FALSE(run.report.refused);
    EXPECT_LE(run.report.feedTimeS, 1.10 * 1.0491);
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
    EXPECT_LE(run.checker->maxDeviation(), kToleranceMm * 1.01);
}

TEST(PolylineSmoothing, ASineAsHalfMillimetreLinesIsFollowedAcrossItsCrests) {
    // The sine of gen.py as 0.5 mm lines: at each crest (curvature 0.39 /mm) the vertices turn
    // 10.3-11.2 deg, beyond the 10 deg that end a run, and one segment's sagitta is 0.012 mm:
    // each crest was a blended corner between two runs (2.506 s, 1.88x of the bound). A turn
    // that long segments make into a curve of R >= 2 mm continues the run, and a single segment
    // may be fitted within 1.3 times half the tolerance (the filter keeps the rest). 100 mm of x
    // within 1.15x of the bound along the exact sine (1.330 s: bounds.py topp_acc of
    // sine_xz(1, 10, 100) at 100 mm/s, plus A / J = 2 ms), within the limits and the tolerance.
    TestRun run = runCommands(millConfig(), sinePolyline(0.5, 4, 100.0), Pose{});
    SCOPED_TRACE(run.checker->limitSummary());
    EXPECT_FALSE(run.report.refused);
    EXPECT_LE(run.report.feedTimeS, 1.15 * 1.330);
    EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
    EXPECT_LE(run.checker->maxDeviation(), kToleranceMm * 1.01);
}

TEST(PolylineSmoothing, ASineLeavesAndEntersItsCrestsAtTheSharesThatCrossThemSoonest) {
    // The crests of the sine (71 mm/s, curvature 0.39 /mm) are fitted with arcs of 0.25 mm
    // (0.5 mm lines) or a few mm (0.1 mm lines) whose limits rise away from the crest. Leaving a
    // crest, each arc took the share of the highest limit (10 %, 200 mm/s^2) because the
    // crossing-time choice counted the cap of the arc before as its entry velocity and needed
    // 2.5 jerk ramps for a change: 1.503 s and 1.468 s, 1.13x and 1.104x. 100 mm of x within
    // 1.10x of the bound along the exact sine (1.3298 s: bounds.py topp_acc of sine_xz(1, 10,
    // 100) at 100 mm/s, 1.3278 s, plus A / J = 2 ms), within the limits and the tolerance.
    for (double seg : {0.1, 0.5}) {
        TestRun run = runCommands(millConfig(), sinePolyline(seg, 4, 100.0), Pose{});
        SCOPED_TRACE("seg " + std::to_string(seg) + ": " + run.checker->limitSummary());
        EXPECT_FALSE(run.report.refused);
        EXPECT_LE(run.report.feedTimeS, 1.10 * 1.3298);
        EXPECT_GE(run.report.feedTimeS, 1.3298);
        EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
        EXPECT_LE(run.checker->maxDeviation(), kToleranceMm * 1.01);
    }
}

TEST(PolylineSmoothing, SmoothedPolylinesKeepTheLimitsAndTheTolerance) {
    struct Case {
        std::string name;
        std::vector<canon::Command> commands;
        Pose start;
    };
    std::vector<Case> cases;
    for (double radius : {5.0, 50.0}) {
        for (double seg : {0.005, 0.02, 0.2}) {
            cases.push_back({"R" + std::to_string(radius) + " seg " + std::to_string(seg),
                             polylineCircle(radius, seg, 4, 15.0), Pose{}});
        }
    }
    cases.push_back({"sine 0.02", sinePolyline(0.02, 4, 15.0), Pose{}});
    cases.push_back({"sine 0.2", sinePolyline(0.2, 4, 15.0), Pose{}});
    cases.push_back({"sine 0.5", sinePolyline(0.5, 4, 15.0), Pose{}});
    cases.push_back({"R5 0.5", polylineCircle(5.0, 0.5, 4, 15.0), Pose{}});
    // 0.5 mm lines of R3 (sagitta 0.0104 mm) do not fit even between the vertices and the
    // midpoints: they stay lines, the first one starting where the fitted R5 before ended,
    // beside its vertex.
    cases.push_back({"R5 then R3, 0.5", polylineOfTwoRadii(5.0, 10.0, 3.0, 5.0, 0.5), Pose{}});
    for (const Case& c : cases) {
        TestRun run = runCommands(millConfig(), c.commands, c.start);
        SCOPED_TRACE(c.name + ": " + run.checker->limitSummary());
        EXPECT_FALSE(run.report.refused);
        EXPECT_LE(run.checker->worstLimitRatio(), 1.01);
        EXPECT_LE(run.checker->maxDeviation(), kToleranceMm * 1.01);
        const auto& last = std::get<canon::LinearMove>(c.commands.back().body).target;
        for (Axis axis : {Axis::X, Axis::Y, Axis::Z}) {
            EXPECT_NEAR(run.report.finalPosition[static_cast<size_t>(axis)], last[axis], 1e-6);
        }
    }
}

TEST(PolylineSmoothing, AKinkInARunOfShortSegmentsStaysACorner) {
    // 3 mm of 0.02 mm lines along X, a 20 degree turn, 3 mm more: a real corner. Blended, it
    // turns within half a segment on either side of the vertex; a fitted curve would spread the
    // turn over millimetres.
    const double turn = 20.0 * M_PI / 180.0;
    std::vector<canon::Command> commands;
    uint32_t line = 1;
    for (int i = 1; i <= 150; ++i)
        commands.push_back(command(canon::LinearMove{pose(0.02 * i, 0.0, 0.0), 6000.0}, line++));
    for (int i = 1; i <= 150; ++i) {
        double d = 0.02 * i;
        commands.push_back(command(
            canon::LinearMove{pose(3.0 + d * std::cos(turn), d * std::sin(turn), 0.0), 6000.0},
            line++));
    }
    std::vector<PathElement> elements = plannedElements(commands);
    const Vec3Array along{1.0, 0.0, 0.0};
    const Vec3Array after{std::cos(turn), std::sin(turn), 0.0};
    for (const PathElement& e : elements) {
        for (double f : {0.0, 0.5, 1.0}) {
            double s = e.sStart + f * e.geometry.length;
            if (s < 3.0 - 0.02) {
                EXPECT_LT(tangentAngle(e.geometry, f * e.geometry.length, along), 1e-3) << s;
            } else if (s > 3.0 + 0.02) {
                EXPECT_LT(tangentAngle(e.geometry, f * e.geometry.length, after), 1e-3) << s;
            }
        }
    }
}

TEST(PolylineSmoothing, AKinkOfAFewDegreesBetweenLongSegmentsStaysABlendedCorner) {
    // 2 mm lines turning 5 degrees at each vertex (a polygon, not a curve): each corner is an
    // arc within half the tolerance, r = (tol / 2) / (1 - cos(2.5 deg)) = 5.25 mm, between
    // straight lines; a curve through the vertices would have a radius of 2 / 0.0873 = 22.9 mm.
    const double step = 5.0 * M_PI / 180.0;
    std::vector<canon::Command> commands;
    double x = 0.0;
    double y = 0.0;
    for (int i = 0; i < 8; ++i) {
        x += 2.0 * std::cos(i * step);
        y += 2.0 * std::sin(i * step);
        commands.push_back(
            command(canon::LinearMove{pose(x, y, 0.0), 6000.0}, static_cast<uint32_t>(i + 1)));
    }
    std::vector<PathElement> elements = plannedElements(commands);
    const double blendRadius = kToleranceMm / 2.0 / (1.0 - std::cos(step / 2.0));
    size_t arcs = 0;
    size_t lines = 0;
    bool onArc = false;
    for (const PathElement& e : elements) {
        if (e.geometry.curved()) {
            EXPECT_NEAR(1.0 / e.geometry.curvature(), blendRadius, 0.01 * blendRadius);
            // A corner's arc near the start may be cut where the share ladder steps
            // (share_ladder.h): its pieces are one arc.
            if (!onArc) ++arcs;
            onArc = true;
        } else {
            onArc = false;
            EXPECT_GT(e.geometry.length, 1.0);
            ++lines;
        }
    }
    EXPECT_EQ(arcs, 7u);
    EXPECT_EQ(lines, 8u);
}

}  // namespace
}  // namespace kerf::motion::test
