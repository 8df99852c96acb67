// Measuring cycles 421, 422 (circle), 425, 426 (width) with tolerance monitoring and the
// measuring log (spec 4).
#include <cmath>

#include "core/cycles/probing/circle_touches.h"
#include "core/cycles/probing/measurement_status.h"
#include "core/cycles/probing/probing_parameters.h"
#include "core/cycles/probing/probing_registry_entries.h"

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
    if (v.integer(281) != 0) {
        results.protocol = std::vector<std::string>{
            "Nominal values:",
            logLine("  centre main axis", nominal.x()),
            logLine("  centre secondary axis", nominal.y()),
            logLine("  diameter", v.number(262)),
            "Given limits:",
            logLine("  max. centre main axis", nominal.x() + v.number(279)),
            logLine("  min. centre main axis", nominal.x() - v.number(279)),
            logLine("  max. centre secondary", nominal.y() + v.number(280)),
            logLine("  min. centre secondary", nominal.y() - v.number(280)),
            logLine("  max. diameter", v.number(275)),
            logLine("  min. diameter", v.number(276)),
            "Actual values:",
            logLine("  centre main axis", fitted.centre.x()),
            logLine("  centre secondary axis", fitted.centre.y()),
            logLine("  diameter", diameter),
            "Deviations:",
            logLine("  centre main axis", deviation.x()),
            logLine("  centre secondary axis", deviation.y()),
            logLine("  diameter", diameter - v.number(262)),
            "Further measuring results:",
            logLine("  measuring height", v.number(261))};
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

}  // namespace

const ProbingCycleDescriptor kProbe421{421, KERF_TR_NOOP("MEASURE HOLE"), kCircleParameters, run421,
                                       kCircleResults};
const ProbingCycleDescriptor kProbe422{422, KERF_TR_NOOP("MEASURE CIRCLE OUTSIDE"),
                                       kCircleParameters, run422, kCircleResults};
const ProbingCycleDescriptor kProbe425{425, KERF_TR_NOOP("MEASURE INSIDE WIDTH"), kWidthParameters,
                                       run425, kWidthResults};
const ProbingCycleDescriptor kProbe426{426, KERF_TR_NOOP("MEASURE RIDGE WIDTH"), kWidthParameters,
                                       run426, kWidthResults};

}  // namespace kerf::cycles::probing
