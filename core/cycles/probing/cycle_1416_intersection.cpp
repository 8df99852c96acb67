// Cycle 1416 PROBING INTERSECTION (spec 8): two touches on each of two edges; the intersection of
// the measured edges, their misalignment and the deviations along the surface normals, in the
// plane Q1139 chooses (seed 004: XY, ZX and YZ). Nominal positions written "nominal@actual" are
// not probed (docs/probing.md says which touches that leaves out); a 1493 before it repeats the
// touch points along a line (Q970-Q972). A nominal position written "?" (semi-automatic mode)
// stops the program before each touch for the operator to position the probe.
#include <array>
#include <cmath>
#include <cstdlib>
#include <numbers>

#include "core/base/fixed_format.h"
#include "core/cycles/probing/probe_geometry.h"
#include "core/cycles/probing/probe_sequence.h"
#include "core/cycles/probing/probing_14xx.h"
#include "core/cycles/probing/probing_parameters.h"
#include "core/cycles/probing/probing_registry_entries.h"

namespace kerf::cycles::probing {

namespace {

using namespace parameters;

constexpr ParameterDescriptor text(uint16_t q, const char* description) {
    return {.q = q, .description = description, .unit = Unit::Text, .optional = true};
}
constexpr ParameterDescriptor distance(uint16_t q, const char* description) {
    return {.q = q,
            .description = description,
            .unit = Unit::Millimetre,
            .min = -999.999,
            .max = 999.999};
}
constexpr ParameterDescriptor direction(uint16_t q, const char* description) {
    return {.q = q,
            .description = description,
            .min = -1.0,
            .max = 1.0,
            .defaultValue = 1.0,
            .integer = true};
}

constexpr ParameterDescriptor kParameters[] = {
    length(1100, KERF_TR_NOOP("Nominal intersection, main axis")),
    length(1101, KERF_TR_NOOP("Nominal intersection, secondary axis")),
    {.q = 1102,
     .description = KERF_TR_NOOP("Nominal position in the tool axis: the measuring height"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = 9999.9999},
    text(400, KERF_TR_NOOP("Tolerance of the 1st edge along its normal, e.g. \"0.1-0.1\"")),
    angle(1130, KERF_TR_NOOP("Nominal angle of the 1st line"), 180.0),
    direction(1131, KERF_TR_NOOP("Probing direction of the 1st line: +1 angle + 90, -1 - 90")),
    distance(1132, KERF_TR_NOOP("Intersection to the 1st touch point of the 1st line")),
    distance(1133, KERF_TR_NOOP("Intersection to the 2nd touch point of the 1st line")),
    text(401, KERF_TR_NOOP("Tolerance of the 2nd edge along its normal")),
    angle(1134, KERF_TR_NOOP("Nominal angle of the 2nd line"), 180.0),
    direction(1135, KERF_TR_NOOP("Probing direction of the 2nd line: +1 angle + 90, -1 - 90")),
    distance(1136, KERF_TR_NOOP("Intersection to the 1st touch point of the 2nd line")),
    distance(1137, KERF_TR_NOOP("Intersection to the 2nd touch point of the 2nd line")),
    choice(1139, KERF_TR_NOOP("Plane of the angles: 1 YZ, 2 ZX, 3 XY"), 1, 3, 3),
    kSetUpClearance,
    kClearanceHeight,
    choice(1125,
           KERF_TR_NOOP("Clearance height: -1 never, 0 cycle, 1 each edge, 2 each touch point"), -1,
           2, 2),
    choice(309, KERF_TR_NOOP("Tolerance error: 0 nothing, 1 stop, 2 stop on scrap only"), 0, 2, 0),
    choice(1126, KERF_TR_NOOP("Align rotary axes: 0 no, 1 MOVE, 2 TURN"), 0, 2, 0),
    choice(1120, KERF_TR_NOOP("Transfer position into the active preset: 0 no, 1 yes"), 0, 1, 0),
    choice(1121, KERF_TR_NOOP("Accept rotation: 0 no, 1/3/5 basic rotation from edge 1/2/mean"), 0,
           6, 0)};

constexpr uint16_t kResults[] = {950, 951, 952, 953, 954, 955, 956, 957, 958, 959,
                                 960, 964, 965, 970, 971, 972, 980, 981, 982, 983,
                                 984, 985, 986, 987, 988, 989, 990, 994, 995};

// A tolerance "upper-lower" (both magnitudes: +upper, -lower) or "t" (±t); empty: none.
struct Tolerance {
    double upper = 0.0;
    double lower = 0.0;
    bool set = false;
};
std::optional<Tolerance> parseTolerance(const std::string& text) {
    if (text.empty()) return Tolerance{};
    char* end = nullptr;
    const double upper = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || !std::isfinite(upper)) return std::nullopt;
    if (*end == '\0') return Tolerance{upper, upper, true};
    if (*end != '-') return std::nullopt;
    const char* rest = end + 1;
    const double lower = std::strtod(rest, &end);
    if (end == rest || *end != '\0' || !std::isfinite(lower)) return std::nullopt;
    return Tolerance{upper, lower, true};
}

Vec2 unit(double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    return {std::cos(a), std::sin(a)};
}

// The plane of Q1139 (spec 8.4): its axes (a, b) in which the angles turn from a towards b, and
// the third axis c that Q1102 sets. Points are kept as (a, b, c).
struct Plane {
    int a, b, c;  // local axis index 0 X, 1 Y, 2 Z
    Vec3 local(const Vec2& ab, double c3) const {
        Vec3 out;
        out[a] = ab.x(), out[b] = ab.y(), out[c] = c3;
        return out;
    }
    Vec2 inPlane(const Vec3& local) const { return {local[a], local[b]}; }
};
Plane planeOf(int q1139) {
    if (q1139 == 1) return {1, 2, 0};  // YZ, third axis X
    if (q1139 == 2) return {2, 0, 1};  // ZX, third axis Y
    return {0, 1, 2};                  // XY, third axis Z
}

// Which edges are not probed because a coordinate of the intersection is given as its actual
// position: an edge probed along the main (secondary) axis measures only that coordinate, so
// Q1100 (Q1101) written "nominal@actual" replaces its touches. An actual that no edge measures
// alone (both edges oblique to that axis) is refused.
std::optional<CycleError> edgesGivenAsActual(const CycleValues& v,
                                             const std::array<Vec2, 2>& directions,
                                             std::array<bool, 2>& given) {
    given = {false, false};
    for (int axis = 0; axis < 2; ++axis) {
        const auto q = static_cast<uint16_t>(1100 + axis);
        if (!actualPosition(v, q)) continue;
        bool used = false;
        for (size_t edge = 0; edge < 2; ++edge) {
            if (std::abs(directions[edge][axis]) > 1.0 - 1e-9) given[edge] = used = true;
        }
        if (!used) {
            return probingError(1416, "cycle-parameter",
                                KERF_TR_NOOP("cycle {1}: Q{2} is given as an actual position, "
                                             "but neither edge is probed along that axis"),
                                {std::to_string(q)});
        }
    }
    return std::nullopt;
}

// One touch point as measured: the surface point in the plane and its deviation from the nominal
// point along the surface normal (against the probing direction); with an extrusion (1493) the
// extremes of that deviation over the point and its repetitions, and the one of largest magnitude,
// signed: the maximum deviation from the ideal line (Q970-Q972).
struct MeasuredPoint {
    Vec2 surface{0.0, 0.0};
    double third = 0.0;  // the touch's coordinate in the third axis c
    double extruded = 0.0;
    double highest = 0.0;
    double lowest = 0.0;
};

// Touches the nominal point `nominal` (local coordinates) along `direction`, then again at each
// step of the extrusion.
std::optional<CycleError> touchPoint(ProbeSequence& sequence, const Plane& plane,
                                     const Vec3& nominal, const Vec3& direction,
                                     const std::optional<Extrusion>& extrusion,
                                     MeasuredPoint& out) {
    const int repeats = extrusion ? extrusion->repeats : 0;
    const Vec3 step = extrusion ? extrusion->step : Vec3::Zero();
    for (int r = 0; r <= repeats; ++r) {
        const Vec3 at = nominal + static_cast<double>(r) * step;
        Vec3 ball;
        if (auto e = sequence.touchFromPoint(at - sequence.standOff() * direction, direction, ball))
            return e;
        const Vec3 surface = ball + sequence.ballRadius() * direction;
        const double deviation = (surface - at).dot(-direction);
        if (r == 0) {
            out.surface = plane.inPlane(surface);
            out.extruded = out.highest = out.lowest = deviation;
            continue;
        }
        if (std::abs(deviation) > std::abs(out.extruded)) out.extruded = deviation;
        out.highest = std::max(out.highest, deviation);
        out.lowest = std::min(out.lowest, deviation);
    }
    return std::nullopt;
}

// The semi-automatic mode: the operator positions the probe before touch point `point` of edge
// `edge`, and it probes from there along `direction` within DIST.
std::optional<CycleError> touchPlaced(ProbeSequence& sequence, ProbingMachine& machine,
                                      const ProbeData& probe, const Plane& plane,
                                      const Vec3& direction, size_t edge, size_t point,
                                      MeasuredPoint& out) {
    const Vec2 inPlane = plane.inPlane(direction);
    const double angle = std::atan2(inPlane.y(), inPlane.x()) * 180.0 / std::numbers::pi;
    machine.waitForOperator(
        {KERF_TR_NOOP("cycle 1416 (semi-automatic mode): position the probe before touch point "
                      "{1} of edge {2}, within {3} mm of the edge, probing at {4} degrees in the "
                      "plane; then NC start"),
         {std::to_string(point + 1), std::to_string(edge + 1), formatForMessage(probe.maxPath, 3),
          formatForMessage(angle, 3)}});
    Vec3 ball;
    if (auto e = sequence.touchFrom(direction, ball)) return e;
    const Vec3 surface = ball + sequence.ballRadius() * direction;
    out.surface = plane.inPlane(surface);
    out.third = surface[plane.c];
    return std::nullopt;
}

std::optional<CycleError> run(const CycleValues& v, const ProbeData& probe, ProbingMachine& machine,
                              ProbingResults& results) {
    const int accept = v.integer(1121);
    if (v.integer(1126) != 0 && accept == 0) {
        return probingError(1416, "PRB-010",
                            KERF_TR_NOOP("cycle {1}: aligning the rotary axes (Q1126) needs the "
                                         "rotation accepted (Q1121)"));
    }
    if (v.integer(1126) != 0 || (accept % 2 == 0 && accept != 0)) {
        return probingError(1416, "PRB-011",
                            KERF_TR_NOOP("cycle {1}: this machine has no rotary table axis to "
                                         "correct the rotation with"));
    }
    if (accept != 0 && v.integer(1139) != 3) {
        // [choice] An edge's misalignment in ZX or YZ is a turn about Y or X, a 3D basic
        // rotation, which Kerf's presets do not hold (only the turn about the tool axis).
        return probingError(1416, "cycle-parameter",
                            KERF_TR_NOOP("cycle {1}: a rotation measured in the ZX or YZ plane "
                                         "(Q1139 = {2}) turns about X or Y; only a basic rotation "
                                         "about the tool axis can be accepted (Q1121 = 0)"),
                            {std::to_string(v.integer(1139))});
    }
    std::array<std::optional<Tolerance>, 2> tolerance = {parseTolerance(v.text(400)),
                                                         parseTolerance(v.text(401))};
    for (size_t i = 0; i < 2; ++i) {
        if (!tolerance[i]) {
            return probingError(1416, "cycle-parameter",
                                KERF_TR_NOOP("cycle {1}: tolerance QS{2} = \"{3}\" is not "
                                             "\"upper-lower\" or a number"),
                                {std::to_string(400 + i), v.text(static_cast<uint16_t>(400 + i))});
        }
    }
    // Q1125: 2 rises between touch points, 1 between the edges, 0 and -1 stay at the height.
    CycleValues moves = v;
    moves.set(301, v.integer(1125) == 2 ? 1.0 : 0.0);
    ProbeSequence sequence(1416, moves, probe, machine);
    const Plane plane = planeOf(v.integer(1139));
    const double height = v.number(1102);
    Vec2 nominal(v.number(1100), v.number(1101));
    const Vec2 actual(actualPosition(v, 1100).value_or(0.0), actualPosition(v, 1101).value_or(0.0));
    const std::array<double, 2> angles = {v.number(1130), v.number(1134)};
    std::array<Vec2, 2> directions;
    for (size_t edge = 0; edge < 2; ++edge) {
        directions[edge] =
            unit(angles[edge] + v.integer(static_cast<uint16_t>(1131 + 4 * edge)) * 90.0);
    }
    std::array<bool, 2> given;
    if (auto e = edgesGivenAsActual(v, directions, given)) return e;
    const std::optional<Extrusion> extrusion = extrusionOf(v);
    // "?": that coordinate of the nominal position is not known (a, b, c).
    const std::array<bool, 3> unknown = {unknownPosition(v, 1100), unknownPosition(v, 1101),
                                         unknownPosition(v, 1102)};
    const bool semiAutomatic = unknown[0] || unknown[1] || unknown[2];
    if (semiAutomatic && extrusion) {
        // [choice] The repetitions of 1493 run from nominal points, which are not known.
        return probingError(1416, "cycle-parameter",
                            KERF_TR_NOOP("cycle {1}: the semi-automatic mode ('?') cannot repeat "
                                         "its touches along an extrusion (cycle 1493)"));
    }
    std::array<Vec2, 4> points, touched;
    std::array<MeasuredPoint, 4> measured;
    // The touches' coordinate in the third axis: the height Q1102 or its actual value; in the
    // semi-automatic mode the one the operator chose, nominal and actual.
    const double actualHeight = actualPosition(v, 1102).value_or(height);
    std::array<double, 4> nominalThird = {height, height, height, height};
    for (size_t edge = 0; edge < 2; ++edge) {
        const auto q = static_cast<uint16_t>(1130 + 4 * edge);
        const Vec2 along = unit(angles[edge]);
        const Vec3 direction = plane.local(directions[edge], 0.0);
        for (size_t k = 0; k < 2; ++k) {
            const size_t i = 2 * edge + k;
            points[i] = nominal + v.number(static_cast<uint16_t>(q + 2 + k)) * along;
            measured[i].third = actualHeight;
            if (given[edge]) {
                // Not probed: the nominal point moved onto the actual coordinate it measures.
                const int axis = std::abs(directions[edge].x()) > 0.5 ? 0 : 1;
                measured[i].surface = points[i];
                measured[i].surface[axis] = actual[axis];
                measured[i].extruded = measured[i].highest = measured[i].lowest =
                    (measured[i].surface - points[i]).dot(-directions[edge]);
            } else if (semiAutomatic) {
                if (auto e = touchPlaced(sequence, machine, probe, plane, direction, edge, k,
                                         measured[i])) {
                    return e;
                }
                // The touch point is where the operator chose it: nominal = actual.
                points[i] = measured[i].surface;
                nominalThird[i] = measured[i].third;
            } else if (auto e = touchPoint(sequence, plane, plane.local(points[i], height),
                                           direction, extrusion, measured[i])) {
                return e;
            }
            touched[i] = measured[i].surface;
        }
        if (v.integer(1125) == 1) sequence.retract();
    }
    if (v.integer(1125) != -1) sequence.retract();
    if (!lineAngleDeg(touched[0], touched[1]) || !lineAngleDeg(touched[2], touched[3])) {
        return coincidentTouches(1416);
    }
    auto corner = intersect(touched[0], touched[1], touched[2], touched[3]);
    if (!corner) {
        return probingError(1416, "PRB-019", KERF_TR_NOOP("cycle {1}: the two edges are parallel"));
    }
    // Three measured points and their deviations in (a, b, c) (the fourth is not exported,
    // spec 8.3); the touches run at the height Q1102, so c deviates by 0 unless Q1102 gives the
    // actual height.
    for (size_t i = 0; i < 3; ++i) {
        const auto at = static_cast<uint16_t>(3 * i);
        const double third = measured[i].third;
        results.set(static_cast<uint16_t>(950 + at), touched[i].x());
        results.set(static_cast<uint16_t>(951 + at), touched[i].y());
        results.set(static_cast<uint16_t>(952 + at), third);
        results.set(static_cast<uint16_t>(980 + at), touched[i].x() - points[i].x());
        results.set(static_cast<uint16_t>(981 + at), touched[i].y() - points[i].y());
        results.set(static_cast<uint16_t>(982 + at), third - nominalThird[i]);
        if (extrusion) results.set(static_cast<uint16_t>(970 + i), measured[i].extruded);
    }
    // An unknown coordinate of the intersection is the measured one.
    if (unknown[0]) nominal.x() = corner->x();
    if (unknown[1]) nominal.y() = corner->y();
    results.set(959, corner->x());
    results.set(960, corner->y());
    results.set(989, corner->x() - nominal.x());
    results.set(990, corner->y() - nominal.y());
    // Misalignment of each edge against its nominal angle, the line undirected (G7).
    std::array<double, 2> misalignment;
    for (size_t edge = 0; edge < 2; ++edge) {
        double delta =
            normalizedDeg(*lineAngleDeg(touched[2 * edge], touched[2 * edge + 1]) - angles[edge]);
        if (delta > 90.0) delta -= 180.0;
        if (delta <= -90.0) delta += 180.0;
        misalignment[edge] = delta;
    }
    const double rotation = accept >= 5   ? (misalignment[0] + misalignment[1]) / 2.0
                            : accept >= 3 ? misalignment[1]
                                          : misalignment[0];
    results.set(964, rotation);
    results.set(994, rotation);
    // Deviation along each surface normal (against the probing direction): above the upper
    // limit material is left (rework), below the lower limit too much is gone (scrap).
    int status = 0;
    for (size_t i = 0; i < 4; ++i) {
        const size_t edge = i / 2;
        if (!tolerance[edge]->set) continue;
        if (measured[i].highest > tolerance[edge]->upper) status = std::max(status, 1);
        if (measured[i].lowest < -tolerance[edge]->lower) status = 2;
    }
    results.set(183, status);
    const int reaction = v.integer(309);
    if ((reaction == 1 && status != 0) || (reaction == 2 && status == 2)) {
        results.toleranceStop =
            probingError(1416, "PRB-006", KERF_TR_NOOP("cycle {1}: tolerance exceeded ({2})"),
                         {status == 2 ? "scrap" : "rework"});
    }
    if (v.integer(1120) == 1) {
        // The intersection's a and b move onto the nominal ones; the third axis keeps its datum.
        DatumResult datum;
        const auto a = static_cast<size_t>(plane.a), b = static_cast<size_t>(plane.b);
        datum.measured[a] = corner->x();
        datum.measured[b] = corner->y();
        datum.nominal[a] = nominal.x();
        datum.nominal[b] = nominal.y();
        results.datum = datum;
        results.transfer = 1;
    }
    if (accept != 0) results.basicRotationDeg = rotation;
    results.tableRow = 0;
    return std::nullopt;
}

}  // namespace

const ProbingCycleDescriptor kProbe1416{1416, KERF_TR_NOOP("PROBING INTERSECTION"), kParameters,
                                        run, kResults};

}  // namespace kerf::cycles::probing
