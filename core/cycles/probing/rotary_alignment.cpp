// Cycles 403, 404, 405 (spec 2): the misalignment compensated by turning a rotary table axis
// (403: two touches on a line, 405: a hole about the C axis), and 404, which sets a basic rotation.
#include <cmath>
#include <numbers>

#include "core/cycles/probing/circle_touches.h"
#include "core/cycles/probing/probing_parameters.h"
#include "core/cycles/probing/probing_registry_entries.h"

namespace kerf::cycles::probing {

namespace {

using namespace parameters;

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

constexpr ParameterDescriptor k403Parameters[] = {
    length(263, KERF_TR_NOOP("1st touch point, main axis")),
    length(264, KERF_TR_NOOP("1st touch point, secondary axis")),
    length(265, KERF_TR_NOOP("2nd touch point, main axis")),
    length(266, KERF_TR_NOOP("2nd touch point, secondary axis")),
    choice(272, KERF_TR_NOOP("Measuring axis: 1 main axis, 2 secondary axis, 3 touch probe axis"),
           1, 3, 1),
    kTraverseDirection,
    kMeasuringHeight,
    kSetUpClearance,
    kClearanceHeight,
    kMoveToClearance,
    choice(312, KERF_TR_NOOP("Axis for the compensation: 0 automatic, 4 A, 5 B, 6 C"), 0, 6, 0),
    choice(337, KERF_TR_NOOP("Set to zero after alignment: 0 no, 1 yes"), 0, 1, 0),
    kTableRow,
    choice(303, KERF_TR_NOOP("Measured-value transfer: 0 datum table, 1 preset table"), 0, 1, 1),
    angle(380, KERF_TR_NOOP("Reference angle the probed line is aligned to"), 360.0)};

constexpr uint16_t kAngleResult[] = {150};

// The rotation a line between two touched points shows, about the axis `about` ('A', 'B', 'C'
// for tool axis Z), positive by the right-hand rule: the part's own turn.
struct MeasuredTurn {
    char about = 'C';
    double angleDeg = 0.0;
};

std::optional<CycleError> measure403(const CycleValues& v, ProbeSequence& sequence,
                                     MeasuredTurn& turn) {
    const Vec2 a(v.number(263), v.number(264));
    const Vec2 b(v.number(265), v.number(266));
    const int axis = v.integer(272) - 1;
    if (axis < 2) {
        Vec2 direction(0.0, 0.0);
        direction[axis] = v.integer(267) < 0 ? -1.0 : 1.0;
        Vec2 p1, p2;
        if (auto e = sequence.touchInPlane(a, direction, p1)) return e;
        if (auto e = sequence.touchInPlane(b, direction, p2)) return e;
        const std::optional<double> angle = lineAngleDeg(p1, p2);
        if (!angle) return coincidentTouches(403);
        turn = {'C', *angle};
        return std::nullopt;
    }
    // Touches along -T: the slope of the surface between the points turns it about the plane
    // axis in which the points do not differ (spec impl. note).
    double w1 = 0.0, w2 = 0.0;
    if (auto e = sequence.touchDown(a, v.number(261), w1)) return e;
    if (auto e = sequence.touchDown(b, v.number(261), w2)) return e;
    const Vec2 d = b - a;
    if (std::fabs(d.x()) >= std::fabs(d.y())) {
        // About +S (B): a turn by beta takes +M towards -T.
        turn = {'B', std::atan2(-(w2 - w1), d.x()) * kDegPerRad};
    } else {
        turn = {'A', std::atan2(w2 - w1, d.y()) * kDegPerRad};
    }
    return std::nullopt;
}

// The table axis Q312 chooses (0: the one nearest to the workpiece), checked against the
// machine and against the turn it must cancel.
std::optional<CycleError> compensatingAxis(int cycle, int choice, const ProbeData& probe,
                                           char needed, char& axis) {
    axis = choice == 0 ? (probe.tableAxes.empty() ? '\0' : probe.tableAxes.front())
                       : static_cast<char>('A' + choice - 4);
    if (choice != 0 && (choice < 4 || choice > 6)) {
        return probingError(cycle, "PRB-011", KERF_TR_NOOP("cycle {1}: Q312 must be 0, 4, 5 or 6"));
    }
    if (axis == '\0' || probe.tableAxes.find(axis) == std::string::npos) {
        return probingError(cycle, "PRB-011",
                            KERF_TR_NOOP("cycle {1}: the machine has no rotary table axis {2} "
                                         "to compensate the misalignment"),
                            {axis == '\0' ? std::string("(none)") : std::string(1, axis)});
    }
    if (axis != needed) {
        return probingError(cycle, "PRB-011",
                            KERF_TR_NOOP("cycle {1}: the rotary axis {2} cannot compensate a "
                                         "misalignment about the axis of {3}"),
                            {std::string(1, axis), std::string(1, needed)});
    }
    return std::nullopt;
}

std::optional<CycleError> run403(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    ProbeSequence sequence(403, v, probe, machine);
    MeasuredTurn turn;
    if (auto e = measure403(v, sequence, turn)) return e;
    char axis = '\0';
    if (auto e = compensatingAxis(403, v.integer(312), probe, turn.about, axis)) return e;
    sequence.retract();
    // A chosen axis takes the line as undirected (-90, 90]; automatic mode keeps the direction
    // from point 1 to point 2 and aligns it to Q380 (spec G2, G7).
    double correction = normalizedDeg(turn.angleDeg);
    if (v.integer(312) == 0 || v.integer(312) == 6) {
        correction = normalizedDeg(turn.angleDeg - v.number(380));
    }
    if (v.integer(312) != 0) {
        if (correction > 90.0) correction -= 180.0;
        if (correction <= -90.0) correction += 180.0;
    }
    results.set(150, correction);
    // A table at angle t turns the workpiece by -t: the axis turns by the part's misalignment.
    RotaryCompensation rotary;
    rotary.axis = axis;
    rotary.turnDeg = correction;
    rotary.zeroDisplay = v.integer(337) == 1;
    results.rotary = rotary;
    // Q305 only with Q337 = 1 and the automatic axis; else the preset active at the call.
    results.tableRow = v.integer(337) == 1 && v.integer(312) == 0 ? v.integer(305) : -1;
    results.transfer = v.integer(303);
    return std::nullopt;
}

constexpr ParameterDescriptor k404Parameters[] = {
    angle(307, KERF_TR_NOOP("Preset rotation angle: the basic rotation to set"), 360.0),
    choice(305, KERF_TR_NOOP("Number in table: -1 the active preset, 0 preset 0 and active"), -1,
           99999, -1)};

std::optional<CycleError> run404(const CycleValues& v, const ProbeData&, ProbingMachine&,
                                 ProbingResults& results) {
    results.basicRotationDeg = normalizedDeg(v.number(307));
    results.tableRow = v.integer(305);
    results.transfer = 1;
    return std::nullopt;
}

constexpr ParameterDescriptor k405Parameters[] = {
    length(321, KERF_TR_NOOP("Hole centre, main axis")),
    length(322, KERF_TR_NOOP("Hole centre, secondary axis: 0 aligns the hole to +Y")),
    length(262, KERF_TR_NOOP("Nominal diameter (enter it on the small side)"), 0.0),
    kStartAngle,
    kStepAngle,
    kMeasuringHeight,
    kSetUpClearance,
    kClearanceHeight,
    kMoveToClearance,
    choice(337, KERF_TR_NOOP("Set to zero after alignment: 0 the C display, n add to datum row n"),
           0, 99999, 0)};

std::optional<CycleError> run405(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    char axis = '\0';
    if (auto e = compensatingAxis(405, 6, probe, 'C', axis)) return e;
    ProbeSequence sequence(405, v, probe, machine);
    CircleTouches touches;
    touches.centre = Vec2(v.number(321), v.number(322));
    touches.nominalDiameter = v.number(262);
    touches.startAngleDeg = v.number(325);
    touches.stepAngleDeg = v.number(247);
    touches.inside = true;
    FittedCircle hole;
    if (auto e = probeCircle(405, sequence, touches, hole)) return e;
    // The probe ends over the measured hole centre (spec 405 step 4).
    machine.moveTo(Vec3(hole.centre.x(), hole.centre.y(), sequence.measuringHeight()));
    sequence.retract();
    const double actual = std::atan2(hole.centre.y(), hole.centre.x()) * kDegPerRad;
    const double nominal =
        v.number(322) == 0.0 ? 90.0 : std::atan2(v.number(322), v.number(321)) * kDegPerRad;
    const double offset = normalizedDeg(nominal - actual);
    results.set(150, offset);
    // The hole must turn by +offset about the C axis: the table turns by -offset.
    RotaryCompensation rotary;
    rotary.axis = 'C';
    rotary.turnDeg = -offset;
    if (v.integer(337) == 0) {
        rotary.zeroDisplay = true;
    } else {
        rotary.datumRow = v.integer(337);
    }
    results.rotary = rotary;
    results.tableRow = -1;
    results.transfer = 1;
    return std::nullopt;
}

}  // namespace

const ProbingCycleDescriptor kProbe403{403,
                                       KERF_TR_NOOP("BASIC ROTATION COMPENSATED VIA ROTARY AXIS"),
                                       k403Parameters, run403, kAngleResult};
const ProbingCycleDescriptor kProbe404{
    404, KERF_TR_NOOP("SET BASIC ROTATION"), k404Parameters, run404, {}};
const ProbingCycleDescriptor kProbe405{405, KERF_TR_NOOP("ROT IN C AXIS"), k405Parameters, run405,
                                       kAngleResult};

}  // namespace kerf::cycles::probing
