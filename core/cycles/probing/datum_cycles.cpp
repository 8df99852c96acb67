// Datum cycles 410-413, 417 and 419 (spec section 3).
#include <array>
#include <cmath>
#include <numbers>

#include "core/cycles/probing/circle_touches.h"
#include "core/cycles/probing/datum_output.h"
#include "core/cycles/probing/probing_parameters.h"
#include "core/cycles/probing/probing_registry_entries.h"
#include "core/cycles/probing/rectangle_touches.h"

namespace kerf::cycles::probing {

namespace {

using namespace parameters;

constexpr ParameterDescriptor kCentreMain = length(321, KERF_TR_NOOP("Centre in the main axis"));
constexpr ParameterDescriptor kCentreSecondary =
    length(322, KERF_TR_NOOP("Centre in the secondary axis"));
constexpr ParameterDescriptor kSideMain =
    length(323, KERF_TR_NOOP("Side length parallel to the main axis"), 0.0);
constexpr ParameterDescriptor kSideSecondary =
    length(324, KERF_TR_NOOP("Side length parallel to the secondary axis"), 0.0);
constexpr ParameterDescriptor kNominalDiameter = length(262, KERF_TR_NOOP("Nominal diameter"), 0.0);

constexpr ParameterDescriptor kRectangleParameters[] = {
    kCentreMain,      kCentreSecondary,   kSideMain,
    kSideSecondary,   kMeasuringHeight,   kSetUpClearance,
    kClearanceHeight, kMoveToClearance,   kTableRow,
    kDatumMain,       kDatumSecondary,    kTransfer,
    kProbeToolAxis,   kToolAxisPointMain, kToolAxisPointSecondary,
    kToolAxisSurface, kDatumToolAxis};

constexpr ParameterDescriptor kCircleParameters[] = {kCentreMain,
                                                     kCentreSecondary,
                                                     kNominalDiameter,
                                                     kStartAngle,
                                                     kStepAngle,
                                                     kMeasuringHeight,
                                                     kSetUpClearance,
                                                     kClearanceHeight,
                                                     kMoveToClearance,
                                                     kTableRow,
                                                     kDatumMain,
                                                     kDatumSecondary,
                                                     kTransfer,
                                                     kProbeToolAxis,
                                                     kToolAxisPointMain,
                                                     kToolAxisPointSecondary,
                                                     kToolAxisSurface,
                                                     kDatumToolAxis,
                                                     optionalParameter(kProbePoints),
                                                     optionalParameter(kTraverseType)};

constexpr ParameterDescriptor kToolAxisParameters[] = {
    length(263, KERF_TR_NOOP("Touch point, main axis")),
    length(264, KERF_TR_NOOP("Touch point, secondary axis")),
    length(294, KERF_TR_NOOP("Touch point, nominal surface in the tool axis")),
    kSetUpClearance,
    kClearanceHeight,
    kTableRow,
    kDatumToolAxis,
    kTransfer};

constexpr ParameterDescriptor kSingleAxisParameters[] = {
    length(263, KERF_TR_NOOP("Touch point, main axis")),
    length(264, KERF_TR_NOOP("Touch point, secondary axis")),
    kMeasuringHeight,
    kSetUpClearance,
    kClearanceHeight,
    choice(272, KERF_TR_NOOP("Measuring axis: 1 main, 2 secondary, 3 tool axis"), 1, 3, 1),
    kTraverseDirection,
    kTableRow,
    length(333, KERF_TR_NOOP("New datum in the measuring axis")),
    kTransfer};

constexpr uint16_t kRectangleResults[] = {151, 152, 154, 155};
constexpr uint16_t kCircleResults[] = {151, 152, 153};
constexpr uint16_t kCoordinateResults[] = {160};

// 410 (inside, probing outward) and 411 (outside, probing inward), spec 3: touches at the
// middle of each side, -M, +M, -S, +S.
std::optional<CycleError> rectangle(int cycle, bool inside, const CycleValues& v,
                                    const ProbeData& probe, ProbingMachine& machine,
                                    ProbingResults& results) {
    if (auto e = checkTransfer(cycle, v)) return e;
    ProbeSequence sequence(cycle, v, probe, machine);
    MeasuredRectangle measured;
    if (auto e = probeRectangle(sequence, Vec2(v.number(321), v.number(322)),
                                Vec2(v.number(323), v.number(324)), inside, measured)) {
        return e;
    }
    const Vec2 actual = measured.centre;
    results.set(151, actual.x());
    results.set(152, actual.y());
    results.set(154, measured.sides.x());
    results.set(155, measured.sides.y());
    DatumResult datum;
    datum.measured = {actual.x(), actual.y(), std::nullopt};
    datum.nominal = {v.number(331), v.number(332), 0.0};
    if (auto e = toolAxisDatum(sequence, v, datum)) return e;
    sequence.retract();
    setDatum(v, results, datum);
    return std::nullopt;
}

std::optional<CycleError> run410(const CycleValues& v, const ProbeData& p, ProbingMachine& m,
                                 ProbingResults& r) {
    return rectangle(410, true, v, p, m, r);
}
std::optional<CycleError> run411(const CycleValues& v, const ProbeData& p, ProbingMachine& m,
                                 ProbingResults& r) {
    return rectangle(411, false, v, p, m, r);
}

std::optional<CycleError> circle(int cycle, bool inside, const CycleValues& v,
                                 const ProbeData& probe, ProbingMachine& machine,
                                 ProbingResults& results) {
    if (auto e = checkTransfer(cycle, v)) return e;
    ProbeSequence sequence(cycle, v, probe, machine);
    CircleTouches touches{
        Vec2(v.number(321), v.number(322)), v.number(262), v.number(325), v.number(247),
        v.integer(423) == 3 ? 3 : 4,        inside};
    FittedCircle fitted;
    if (auto e = probeCircle(cycle, sequence, touches, fitted)) return e;
    results.set(151, fitted.centre.x());
    results.set(152, fitted.centre.y());
    results.set(153, 2.0 * fitted.radius);
    DatumResult datum;
    datum.measured = {fitted.centre.x(), fitted.centre.y(), std::nullopt};
    datum.nominal = {v.number(331), v.number(332), 0.0};
    if (auto e = toolAxisDatum(sequence, v, datum)) return e;
    sequence.retract();
    setDatum(v, results, datum);
    return std::nullopt;
}

std::optional<CycleError> run412(const CycleValues& v, const ProbeData& p, ProbingMachine& m,
                                 ProbingResults& r) {
    return circle(412, true, v, p, m, r);
}
std::optional<CycleError> run413(const CycleValues& v, const ProbeData& p, ProbingMachine& m,
                                 ProbingResults& r) {
    return circle(413, false, v, p, m, r);
}

// 417: one touch along -T onto the surface Q294 at (Q263, Q264).
std::optional<CycleError> run417(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    if (auto e = checkTransfer(417, v)) return e;
    ProbeSequence sequence(417, v, probe, machine);
    double surface = 0.0;
    if (auto e = sequence.touchDown(Vec2(v.number(263), v.number(264)), v.number(294), surface)) {
        return e;
    }
    sequence.retract();
    results.set(160, surface);
    DatumResult datum;
    datum.measured[2] = surface;
    datum.nominal[2] = v.number(333);
    setDatum(v, results, datum);
    return std::nullopt;
}

// 419: one touch along the measuring axis Q272 in direction Q267; Q272 = 3 touches the tool
// axis at (Q263, Q264) with Q261 as the nominal surface.
std::optional<CycleError> run419(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    if (auto e = checkTransfer(419, v)) return e;
    ProbeSequence sequence(419, v, probe, machine);
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
    DatumResult datum;
    datum.measured[static_cast<size_t>(axis)] = measured;
    datum.nominal[static_cast<size_t>(axis)] = v.number(333);
    setDatum(v, results, datum);
    return std::nullopt;
}

}  // namespace

const ProbingCycleDescriptor kProbe410{410, KERF_TR_NOOP("DATUM INSIDE RECTANGLE"),
                                       kRectangleParameters, run410, kRectangleResults};
const ProbingCycleDescriptor kProbe411{411, KERF_TR_NOOP("DATUM OUTSIDE RECTANGLE"),
                                       kRectangleParameters, run411, kRectangleResults};
const ProbingCycleDescriptor kProbe412{412, KERF_TR_NOOP("DATUM INSIDE CIRCLE"), kCircleParameters,
                                       run412, kCircleResults};
const ProbingCycleDescriptor kProbe413{413, KERF_TR_NOOP("DATUM OUTSIDE CIRCLE"), kCircleParameters,
                                       run413, kCircleResults};
const ProbingCycleDescriptor kProbe417{417, KERF_TR_NOOP("DATUM IN TS AXIS"), kToolAxisParameters,
                                       run417, kCoordinateResults};
const ProbingCycleDescriptor kProbe419{419, KERF_TR_NOOP("DATUM IN ONE AXIS"),
                                       kSingleAxisParameters, run419, kCoordinateResults};

}  // namespace kerf::cycles::probing
