// Datum cycles 414 (outside corner) and 416 (bolt-hole-circle centre), spec 3.
#include <array>
#include <cmath>
#include <numbers>

#include "core/cycles/probing/circle_touches.h"
#include "core/cycles/probing/datum_output.h"
#include "core/cycles/probing/probe_geometry.h"
#include "core/cycles/probing/probing_parameters.h"
#include "core/cycles/probing/probing_registry_entries.h"

namespace kerf::cycles::probing {

namespace {

using namespace parameters;

constexpr ParameterDescriptor kCornerParameters[] = {
    length(263, KERF_TR_NOOP("1st touch point, main axis")),
    length(264, KERF_TR_NOOP("1st touch point, secondary axis")),
    length(326, KERF_TR_NOOP("Spacing of touch points 1 and 2 in the main axis"), 0.0),
    length(296, KERF_TR_NOOP("3rd touch point, main axis")),
    length(297, KERF_TR_NOOP("3rd touch point, secondary axis")),
    length(327, KERF_TR_NOOP("Spacing of touch points 3 and 4 in the secondary axis"), 0.0),
    kMeasuringHeight,
    kSetUpClearance,
    kClearanceHeight,
    kMoveToClearance,
    choice(304, KERF_TR_NOOP("Basic rotation too: 0 no, 1 yes"), 0, 1, 0),
    kTableRow,
    kDatumMain,
    kDatumSecondary,
    kTransfer,
    kProbeToolAxis,
    kToolAxisPointMain,
    kToolAxisPointSecondary,
    kToolAxisSurface,
    kDatumToolAxis};

constexpr ParameterDescriptor kInsideCornerParameters[] = {
    length(263, KERF_TR_NOOP("Corner, main axis")),
    length(264, KERF_TR_NOOP("Corner, secondary axis")),
    length(326, KERF_TR_NOOP("Spacing of touch points 1 and 2 in the main axis"), 0.0),
    length(327, KERF_TR_NOOP("Spacing of touch points 3 and 4 in the secondary axis"), 0.0),
    choice(308, KERF_TR_NOOP("Corner: 1 (-M -S), 2 (+M -S), 3 (+M +S), 4 (-M +S)"), 1, 4, 1),
    kMeasuringHeight,
    kSetUpClearance,
    kClearanceHeight,
    kMoveToClearance,
    choice(304, KERF_TR_NOOP("Basic rotation too: 0 no, 1 yes"), 0, 1, 0),
    kTableRow,
    kDatumMain,
    kDatumSecondary,
    kTransfer,
    kProbeToolAxis,
    kToolAxisPointMain,
    kToolAxisPointSecondary,
    kToolAxisSurface,
    kDatumToolAxis};

constexpr ParameterDescriptor kBoltCircleParameters[] = {
    length(273, KERF_TR_NOOP("Bolt-circle centre, main axis")),
    length(274, KERF_TR_NOOP("Bolt-circle centre, secondary axis")),
    length(262, KERF_TR_NOOP("Nominal bolt-circle diameter"), 0.0),
    angle(291, KERF_TR_NOOP("Polar angle of the 1st hole centre"), 360.0),
    angle(292, KERF_TR_NOOP("Polar angle of the 2nd hole centre"), 360.0),
    angle(293, KERF_TR_NOOP("Polar angle of the 3rd hole centre"), 360.0),
    kMeasuringHeight,
    kClearanceHeight,
    kTableRow,
    kDatumMain,
    kDatumSecondary,
    kTransfer,
    kProbeToolAxis,
    kToolAxisPointMain,
    kToolAxisPointSecondary,
    kToolAxisSurface,
    kDatumToolAxis,
    optionalParameter(kSetUpClearance)};

constexpr uint16_t kCornerResults[] = {151, 152};
constexpr uint16_t kBoltCircleResults[] = {151, 152, 153};

double sign(double value) {
    return value < 0.0 ? -1.0 : 1.0;
}

// The corner where the lines through touches 1, 2 and 3, 4 meet (G3), the misalignment of the
// first line (Q304) and the datum: what 414 and 415 share.
std::optional<CycleError> cornerResults(int cycle, const CycleValues& v,
                                        const std::array<Vec2, 4>& touched, ProbeSequence& sequence,
                                        ProbingResults& results) {
    if (!lineAngleDeg(touched[0], touched[1]) || !lineAngleDeg(touched[2], touched[3])) {
        return coincidentTouches(cycle);
    }
    auto corner = intersect(touched[0], touched[1], touched[2], touched[3]);
    if (!corner) {
        return probingError(cycle, "PRB-019",
                            KERF_TR_NOOP("cycle {1}: the two edges are parallel"));
    }
    results.set(151, corner->x());
    results.set(152, corner->y());
    if (v.integer(304) == 1) {
        // Line 1 runs along the main axis: its angle is the misalignment (either direction).
        double angle = *lineAngleDeg(touched[0], touched[1]);  // apart: checked above
        if (angle > 90.0) angle -= 180.0;
        if (angle <= -90.0) angle += 180.0;
        results.basicRotationDeg = angle;
    }
    DatumResult datum;
    datum.measured = {corner->x(), corner->y(), std::nullopt};
    datum.nominal = {v.number(331), v.number(332), 0.0};
    if (auto e = toolAxisDatum(sequence, v, datum)) return e;
    sequence.retract();
    setDatum(v, results, datum);
    return std::nullopt;
}

// 414: line 1 (touches 1, 2) probed along S toward the level of point 3, line 2 (touches 3, 4)
// along M from point 3 toward point 1; the corner is where the lines meet (G3).
std::optional<CycleError> run414(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    if (auto e = checkTransfer(414, v)) return e;
    ProbeSequence sequence(414, v, probe, machine);
    const Vec2 p1(v.number(263), v.number(264));
    const Vec2 p3(v.number(296), v.number(297));
    // Points 2 and 4 lie further from the corner than points 1 and 3.
    const Vec2 p2 = p1 + Vec2(sign(p1.x() - p3.x()) * v.number(326), 0.0);
    const Vec2 p4 = p3 + Vec2(0.0, sign(p3.y() - p1.y()) * v.number(327));
    const Vec2 alongS(0.0, sign(p3.y() - p1.y()));
    const Vec2 alongM(sign(p1.x() - p3.x()), 0.0);
    std::array<Vec2, 4> touched;
    if (auto e = sequence.touchInPlane(p1, alongS, touched[0])) return e;
    if (auto e = sequence.touchInPlane(p2, alongS, touched[1])) return e;
    if (auto e = sequence.touchInPlane(p3, alongM, touched[2])) return e;
    if (auto e = sequence.touchInPlane(p4, alongM, touched[3])) return e;
    return cornerResults(414, v, touched, sequence, results);
}

// 415 (spec impl. note): (Q263, Q264) is the nominal corner of a pocket, Q308 which one. Line 1
// runs along the wall parallel to the main axis, probed toward it; line 2 along the other wall;
// the touches start clear of the other wall and move away from the corner by Q326, Q327.
std::optional<CycleError> run415(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    if (auto e = checkTransfer(415, v)) return e;
    ProbeSequence sequence(415, v, probe, machine);
    const Vec2 corner(v.number(263), v.number(264));
    const int number = v.integer(308);
    const Vec2 side(number == 2 || number == 3 ? 1.0 : -1.0, number >= 3 ? 1.0 : -1.0);
    const double clear = sequence.standOff();
    const std::array<Vec2, 4> nominal = {
        Vec2(corner.x() - side.x() * clear, corner.y()),
        Vec2(corner.x() - side.x() * (clear + v.number(326)), corner.y()),
        Vec2(corner.x(), corner.y() - side.y() * clear),
        Vec2(corner.x(), corner.y() - side.y() * (clear + v.number(327)))};
    std::array<Vec2, 4> touched;
    for (size_t k = 0; k < touched.size(); ++k) {
        const Vec2 direction = k < 2 ? Vec2(0.0, side.y()) : Vec2(side.x(), 0.0);
        if (auto e = sequence.touchInPlane(nominal[k], direction, touched[k])) return e;
    }
    return cornerResults(415, v, touched, sequence, results);
}

// 416: each hole's centre from four touches outward from its nominal centre (G5), then the
// circle through the three centres.
std::optional<CycleError> run416(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    if (auto e = checkTransfer(416, v)) return e;
    // The hole touches start at the hole centre: only the tool-axis touch keeps Q320 (spec 1.7).
    CycleValues holes = v;
    holes.set(320, 0.0);
    holes.set(301, 1.0);
    ProbeSequence sequence(416, holes, probe, machine);
    const Vec2 centre(v.number(273), v.number(274));
    std::array<Vec2, 3> holeCentres;
    for (size_t h = 0; h < holeCentres.size(); ++h) {
        const double a = v.number(static_cast<uint16_t>(291 + h)) * std::numbers::pi / 180.0;
        const Vec2 nominal = centre + v.number(262) / 2.0 * Vec2(std::cos(a), std::sin(a));
        if (auto e = probeHoleCentre(416, sequence, nominal, holeCentres[h])) return e;
        sequence.retract();
    }
    auto circle = fitCircle(holeCentres);
    if (!circle) {
        return probingError(416, "PRB-020",
                            KERF_TR_NOOP("cycle {1}: the hole centres give no circle"));
    }
    results.set(151, circle->centre.x());
    results.set(152, circle->centre.y());
    results.set(153, 2.0 * circle->radius);
    DatumResult datum;
    datum.measured = {circle->centre.x(), circle->centre.y(), std::nullopt};
    datum.nominal = {v.number(331), v.number(332), 0.0};
    ProbeSequence toolAxis(416, v, probe, machine);
    if (auto e = toolAxisDatum(toolAxis, v, datum)) return e;
    toolAxis.retract();
    setDatum(v, results, datum);
    return std::nullopt;
}

}  // namespace

const ProbingCycleDescriptor kProbe414{414, KERF_TR_NOOP("DATUM OUTSIDE CORNER"), kCornerParameters,
                                       run414, kCornerResults};
const ProbingCycleDescriptor kProbe415{415, KERF_TR_NOOP("DATUM INSIDE CORNER"),
                                       kInsideCornerParameters, run415, kCornerResults};
const ProbingCycleDescriptor kProbe416{416, KERF_TR_NOOP("DATUM CIRCLE CENTER"),
                                       kBoltCircleParameters, run416, kBoltCircleResults};

}  // namespace kerf::cycles::probing
