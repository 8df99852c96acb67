// Measuring cycles 421, 422 (circle), 425, 426 (width) with tolerance monitoring and the
// measuring log (spec 4).
#include <cmath>

#include "core/cycles/probing/circle_touches.h"
#include "core/cycles/probing/measurement_status.h"
#include "core/cycles/probing/probe_geometry.h"
#include "core/cycles/probing/probing_parameters.h"
#include "core/cycles/probing/probing_registry_entries.h"
#include "core/cycles/probing/rectangle_touches.h"

namespace kerf::cycles::probing {

namespace {

using namespace parameters;

constexpr ParameterDescriptor kCircleParameters[] = {
    length(273, KERF_TR_NOOP("Nominal centre, main axis")),
    length(274, KERF_TR_NOOP("Nominal centre, secondary axis")),
    length(262, KERF_TR_NOOP("Nominal diameter"), 0.0),
    kStartAngle,
    kStepAngle,
    kMeasuringHeight,
    kSetUpClearance,
    kClearanceHeight,
    kMoveToClearance,
    length(275, KERF_TR_NOOP("Maximum permitted diameter (0: not monitored)"), 0.0),
    length(276, KERF_TR_NOOP("Minimum permitted diameter"), 0.0),
    length(279, KERF_TR_NOOP("Centre tolerance, main axis (0: not monitored)"), 0.0),
    length(280, KERF_TR_NOOP("Centre tolerance, secondary axis"), 0.0),
    kMeasuringLog,
    kStopOnToleranceError,
    kMonitoredTool,
    optionalParameter(kProbePoints),
    optionalParameter(kTraverseType),
    optionalParameter(choice(498, KERF_TR_NOOP("Compatibility only, no effect"), 0, 1, 0)),
    optionalParameter(choice(531, KERF_TR_NOOP("Compatibility only, no effect"), 0, 1, 0))};

constexpr ParameterDescriptor kWidthParameters[] = {
    length(328, KERF_TR_NOOP("Starting point, main axis")),
    length(329, KERF_TR_NOOP("Starting point, secondary axis")),
    length(310, KERF_TR_NOOP("Offset before the second measurement (0: none)")),
    kMeasuringAxis,
    kMeasuringHeight,
    kClearanceHeight,
    length(311, KERF_TR_NOOP("Nominal length"), 0.0),
    length(288, KERF_TR_NOOP("Maximum permitted length (0: not monitored)"), 0.0),
    length(289, KERF_TR_NOOP("Minimum permitted length"), 0.0),
    kMeasuringLog,
    kStopOnToleranceError,
    kMonitoredTool,
    optionalParameter(kSetUpClearance),
    optionalParameter(kMoveToClearance)};

constexpr ParameterDescriptor kAngleParameters[] = {
    length(263, KERF_TR_NOOP("1st touch point, main axis")),
    length(264, KERF_TR_NOOP("1st touch point, secondary axis")),
    length(265, KERF_TR_NOOP("2nd touch point, main axis")),
    length(266, KERF_TR_NOOP("2nd touch point, secondary axis")),
    kMeasuringAxis,
    kTraverseDirection,
    kMeasuringHeight,
    kSetUpClearance,
    kClearanceHeight,
    kMoveToClearance,
    kMeasuringLog};

constexpr ParameterDescriptor kRectangleParameters[] = {
    length(273, KERF_TR_NOOP("Nominal centre, main axis")),
    length(274, KERF_TR_NOOP("Nominal centre, secondary axis")),
    length(282, KERF_TR_NOOP("Nominal side length parallel to the main axis"), 0.0),
    length(283, KERF_TR_NOOP("Nominal side length parallel to the secondary axis"), 0.0),
    kMeasuringHeight,
    kSetUpClearance,
    kClearanceHeight,
    kMoveToClearance,
    length(284, KERF_TR_NOOP("Maximum length of side 1 (0: not monitored)"), 0.0),
    length(285, KERF_TR_NOOP("Minimum length of side 1"), 0.0),
    length(286, KERF_TR_NOOP("Maximum length of side 2 (0: not monitored)"), 0.0),
    length(287, KERF_TR_NOOP("Minimum length of side 2"), 0.0),
    length(279, KERF_TR_NOOP("Centre tolerance, main axis (0: not monitored)"), 0.0),
    length(280, KERF_TR_NOOP("Centre tolerance, secondary axis"), 0.0),
    kMeasuringLog,
    kStopOnToleranceError,
    kMonitoredTool};

constexpr ParameterDescriptor kCoordinateParameters[] = {
    length(263, KERF_TR_NOOP("Touch point, main axis")),
    length(264, KERF_TR_NOOP("Touch point, secondary axis")),
    kMeasuringHeight,
    kSetUpClearance,
    choice(272, KERF_TR_NOOP("Measuring axis: 1 main, 2 secondary, 3 tool axis"), 1, 3, 1),
    kTraverseDirection,
    kClearanceHeight,
    kMeasuringLog,
    length(288, KERF_TR_NOOP("Maximum permitted value (0 with Q289 = 0: not monitored)")),
    length(289, KERF_TR_NOOP("Minimum permitted value")),
    kStopOnToleranceError,
    kMonitoredTool,
    optionalParameter(choice(498, KERF_TR_NOOP("Compatibility only, no effect"), 0, 1, 0)),
    optionalParameter(choice(531, KERF_TR_NOOP("Compatibility only, no effect"), 0, 1, 0))};

constexpr uint16_t kAngleResults[] = {150};
constexpr uint16_t kRectangleResults[] = {151, 152, 154, 155, 161, 162, 164, 165, 180, 181, 182};
constexpr uint16_t kCoordinateResults[] = {160, 180, 181, 182};
constexpr uint16_t kCircleResults[] = {151, 152, 153, 161, 162, 163, 180, 181, 182};
constexpr uint16_t kWidthResults[] = {156, 157, 166, 180, 181, 182};

std::optional<CycleError> measureCircle(int cycle, bool inside, const CycleValues& v,
                                        const ProbeData& probe, ProbingMachine& machine,
                                        ProbingResults& results) {
    ProbeSequence sequence(cycle, v, probe, machine);
    const Vec2 nominal(v.number(273), v.number(274));
    CircleTouches touches{
        nominal, v.number(262), v.number(325), v.number(247), v.integer(423) == 3 ? 3 : 4, inside};
    FittedCircle fitted;
    if (auto e = probeCircle(cycle, sequence, touches, fitted)) return e;
    sequence.retract();
    const double diameter = 2.0 * fitted.radius;
    const Vec2 deviation = fitted.centre - nominal;
    results.set(151, fitted.centre.x());
    results.set(152, fitted.centre.y());
    results.set(153, diameter);
    results.set(161, deviation.x());
    results.set(162, deviation.y());
    results.set(163, diameter - v.number(262));
    MeasurementStatus status(inside ? MeasurementStatus::Feature::Inside
                                    : MeasurementStatus::Feature::Outside);
    status.size(diameter, v.number(275), v.number(276));
    status.position(deviation.x(), v.number(279));
    status.position(deviation.y(), v.number(280));
    status.write(cycle, v, results);
    // A hole too large: the tool cut larger than its radius says (spec 1.14).
    const double diameterDeviation = diameter - v.number(262);
    results.toolCorrection = ToolCorrection{.delta = (inside ? 0.5 : -0.5) * diameterDeviation};
    if (v.integer(281) != 0) {
        results.protocol = circleLog({.nominalCentre = nominal,
                                      .nominalDiameter = v.number(262),
                                      .centreToleranceMain = v.number(279),
                                      .centreToleranceSecondary = v.number(280),
                                      .maxDiameter = v.number(275),
                                      .minDiameter = v.number(276),
                                      .actualCentre = fitted.centre,
                                      .actualDiameter = diameter,
                                      .measuringHeight = v.number(261)});
        results.protocolStop = v.integer(281) == 2;
    }
    return std::nullopt;
}

std::optional<CycleError> run421(const CycleValues& v, const ProbeData& p, ProbingMachine& m,
                                 ProbingResults& r) {
    return measureCircle(421, true, v, p, m, r);
}
std::optional<CycleError> run422(const CycleValues& v, const ProbeData& p, ProbingMachine& m,
                                 ProbingResults& r) {
    return measureCircle(422, false, v, p, m, r);
}

// 425 (slot, touches outward) and 426 (ridge, touches inward): touch 1 along +e from the
// starting point (425) or from outside the nominal width (426), touch 2 opposite it, shifted by
// Q310 across the measuring axis.
std::optional<CycleError> measureWidth(int cycle, bool inside, const CycleValues& v,
                                       const ProbeData& probe, ProbingMachine& machine,
                                       ProbingResults& results) {
    ProbeSequence sequence(cycle, v, probe, machine);
    const int axis = v.integer(272) - 1;
    Vec2 e(0.0, 0.0), across(0.0, 0.0);
    e[axis] = 1.0;
    across[1 - axis] = 1.0;
    const Vec2 start(v.number(328), v.number(329));
    const double width = v.number(311);
    const double standOff = sequence.standOff();
    Vec2 plus, minus;
    if (inside) {
        // Touch 1 from the starting point toward +e; touch 2 toward -e, pre-positioned in front
        // of the other wall as the nominal width puts it (spec 4, cycle 425).
        if (auto err = sequence.touchInPlane(start, e, plus, &start)) return err;
        const Vec2 nominal2 = plus - width * e + v.number(310) * across;
        const Vec2 pre2 = nominal2 + standOff * e;
        if (auto err = sequence.touchInPlane(nominal2, -e, minus, &pre2)) return err;
    } else {
        if (auto err = sequence.touchInPlane(start - width / 2.0 * e, e, minus)) return err;
        const Vec2 nominal2 = minus + width * e + v.number(310) * across;
        if (auto err = sequence.touchInPlane(nominal2, -e, plus)) return err;
    }
    sequence.retract();
    const double measured = std::fabs(plus.dot(e) - minus.dot(e));
    results.set(156, measured);
    results.set(157, (plus.dot(e) + minus.dot(e)) / 2.0);
    results.set(166, measured - width);
    MeasurementStatus status(inside ? MeasurementStatus::Feature::Inside
                                    : MeasurementStatus::Feature::Outside);
    status.size(measured, v.number(288), v.number(289));
    status.write(cycle, v, results);
    results.toolCorrection = ToolCorrection{.delta = (inside ? 0.5 : -0.5) * (measured - width)};
    if (v.integer(281) != 0) {
        results.protocol =
            std::vector<std::string>{"Nominal values:",
                                     logLine("  length", width),
                                     "Given limits:",
                                     logLine("  max. length", v.number(288)),
                                     logLine("  min. length", v.number(289)),
                                     "Actual values:",
                                     logLine("  length", measured),
                                     logLine("  centre line", (plus.dot(e) + minus.dot(e)) / 2.0),
                                     "Deviations:",
                                     logLine("  length", measured - width),
                                     "Further measuring results:",
                                     logLine("  measuring height", v.number(261))};
        results.protocolStop = v.integer(281) == 2;
    }
    return std::nullopt;
}

std::optional<CycleError> run425(const CycleValues& v, const ProbeData& p, ProbingMachine& m,
                                 ProbingResults& r) {
    return measureWidth(425, true, v, p, m, r);
}
std::optional<CycleError> run426(const CycleValues& v, const ProbeData& p, ProbingMachine& m,
                                 ProbingResults& r) {
    return measureWidth(426, false, v, p, m, r);
}

// 420: two touches along the measuring axis; the angle of the line through them (G2).
std::optional<CycleError> run420(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    ProbeSequence sequence(420, v, probe, machine);
    Vec2 direction(0.0, 0.0);
    direction[v.integer(272) - 1] = v.integer(267) < 0 ? -1.0 : 1.0;
    Vec2 p1, p2;
    if (auto e = sequence.touchInPlane(Vec2(v.number(263), v.number(264)), direction, p1)) {
        return e;
    }
    if (auto e = sequence.touchInPlane(Vec2(v.number(265), v.number(266)), direction, p2)) {
        return e;
    }
    sequence.retract();
    const std::optional<double> measured = lineAngleDeg(p1, p2);
    if (!measured) return coincidentTouches(420);
    const double angle = *measured;
    results.set(150, angle);
    if (v.integer(281) != 0) {
        results.protocol = std::vector<std::string>{
            "Actual values:", logLine("  angle", angle),
            "Further measuring results:", logLine("  measuring height", v.number(261))};
        results.protocolStop = v.integer(281) == 2;
    }
    return std::nullopt;
}

// 423 (pocket) and 424 (stud): the touches of 410/411 with nominal sizes and tolerances.
std::optional<CycleError> measureRectangle(int cycle, bool inside, const CycleValues& v,
                                           const ProbeData& probe, ProbingMachine& machine,
                                           ProbingResults& results) {
    ProbeSequence sequence(cycle, v, probe, machine);
    const Vec2 nominal(v.number(273), v.number(274));
    const Vec2 sides(v.number(282), v.number(283));
    MeasuredRectangle measured;
    if (auto e = probeRectangle(sequence, nominal, sides, inside, measured)) return e;
    sequence.retract();
    const Vec2 deviation = measured.centre - nominal;
    const Vec2 sideDeviation = measured.sides - sides;
    results.set(151, measured.centre.x());
    results.set(152, measured.centre.y());
    results.set(154, measured.sides.x());
    results.set(155, measured.sides.y());
    results.set(161, deviation.x());
    results.set(162, deviation.y());
    results.set(164, sideDeviation.x());
    results.set(165, sideDeviation.y());
    MeasurementStatus status(inside ? MeasurementStatus::Feature::Inside
                                    : MeasurementStatus::Feature::Outside);
    status.size(measured.sides.x(), v.number(284), v.number(285));
    status.size(measured.sides.y(), v.number(286), v.number(287));
    status.position(deviation.x(), v.number(279));
    status.position(deviation.y(), v.number(280));
    status.write(cycle, v, results);
    // The side with the larger deviation (spec 1.14 leaves the choice open).
    const double side = std::fabs(sideDeviation.x()) >= std::fabs(sideDeviation.y())
                            ? sideDeviation.x()
                            : sideDeviation.y();
    results.toolCorrection = ToolCorrection{.delta = (inside ? 0.5 : -0.5) * side};
    if (v.integer(281) != 0) {
        results.protocol =
            std::vector<std::string>{"Nominal values:",
                                     logLine("  centre main axis", nominal.x()),
                                     logLine("  centre secondary axis", nominal.y()),
                                     logLine("  side length main axis", sides.x()),
                                     logLine("  side length secondary", sides.y()),
                                     "Actual values:",
                                     logLine("  centre main axis", measured.centre.x()),
                                     logLine("  centre secondary axis", measured.centre.y()),
                                     logLine("  side length main axis", measured.sides.x()),
                                     logLine("  side length secondary", measured.sides.y()),
                                     "Deviations:",
                                     logLine("  centre main axis", deviation.x()),
                                     logLine("  centre secondary axis", deviation.y()),
                                     logLine("  side length main axis", sideDeviation.x()),
                                     logLine("  side length secondary", sideDeviation.y()),
                                     "Further measuring results:",
                                     logLine("  measuring height", v.number(261))};
        results.protocolStop = v.integer(281) == 2;
    }
    return std::nullopt;
}

std::optional<CycleError> run423(const CycleValues& v, const ProbeData& p, ProbingMachine& m,
                                 ProbingResults& r) {
    return measureRectangle(423, true, v, p, m, r);
}
std::optional<CycleError> run424(const CycleValues& v, const ProbeData& p, ProbingMachine& m,
                                 ProbingResults& r) {
    return measureRectangle(424, false, v, p, m, r);
}

// 427: one coordinate, along Q272 in direction Q267 (Q272 = 3: down onto Q261 as the nominal
// surface); an outside dimension for the status unless the limits say otherwise (spec 1.13).
std::optional<CycleError> run427(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    ProbeSequence sequence(427, v, probe, machine);
    const Vec2 point(v.number(263), v.number(264));
    const int axis = v.integer(272) - 1;
    double measured = 0.0;
    if (axis == 2) {
        if (auto e = sequence.touchDown(point, v.number(261), measured)) return e;
    } else {
        Vec2 direction(0.0, 0.0);
        direction[axis] = v.integer(267) < 0 ? -1.0 : 1.0;
        Vec2 surface;
        if (auto e = sequence.touchInPlane(point, direction, surface)) return e;
        measured = surface[axis];
    }
    sequence.retract();
    results.set(160, measured);
    MeasurementStatus status(MeasurementStatus::Feature::Outside);
    status.size(measured, v.number(288), v.number(289));
    status.write(427, v, results);
    // Against the middle of the limits (spec 1.14, open point); material left outward of the
    // touched face (its normal -Q267 along the axis, +T in the tool axis) means the tool was
    // effectively smaller or shorter.
    const double outward = (measured - (v.number(288) + v.number(289)) / 2.0) *
                           (axis == 2 ? 1.0 : -static_cast<double>(v.integer(267)));
    results.toolCorrection = ToolCorrection{.length = axis == 2, .delta = -outward};
    if (v.integer(281) != 0) {
        results.protocol = std::vector<std::string>{"Given limits:",
                                                    logLine("  max. value", v.number(288)),
                                                    logLine("  min. value", v.number(289)),
                                                    "Actual values:",
                                                    logLine("  coordinate", measured),
                                                    "Further measuring results:",
                                                    logLine("  measuring height", v.number(261))};
        results.protocolStop = v.integer(281) == 2;
    }
    return std::nullopt;
}

}  // namespace

const ProbingCycleDescriptor kProbe420{420, KERF_TR_NOOP("MEASURE ANGLE"), kAngleParameters, run420,
                                       kAngleResults};
const ProbingCycleDescriptor kProbe423{423, KERF_TR_NOOP("MEASURE RECTANGLE INSIDE"),
                                       kRectangleParameters, run423, kRectangleResults};
const ProbingCycleDescriptor kProbe424{424, KERF_TR_NOOP("MEASURE RECTANGLE OUTSIDE"),
                                       kRectangleParameters, run424, kRectangleResults};
const ProbingCycleDescriptor kProbe427{427, KERF_TR_NOOP("MEASURE COORDINATE"),
                                       kCoordinateParameters, run427, kCoordinateResults};
const ProbingCycleDescriptor kProbe421{421, KERF_TR_NOOP("MEASURE HOLE"), kCircleParameters, run421,
                                       kCircleResults};
const ProbingCycleDescriptor kProbe422{422, KERF_TR_NOOP("MEASURE CIRCLE OUTSIDE"),
                                       kCircleParameters, run422, kCircleResults};
const ProbingCycleDescriptor kProbe425{425, KERF_TR_NOOP("MEASURE INSIDE WIDTH"), kWidthParameters,
                                       run425, kWidthResults};
const ProbingCycleDescriptor kProbe426{426, KERF_TR_NOOP("MEASURE RIDGE WIDTH"), kWidthParameters,
                                       run426, kWidthResults};

}  // namespace kerf::cycles::probing
