// Cycle 400 BASIC ROTATION (spec 2): two touches on a straight edge give its angle.
#include "core/cycles/probing/probe_geometry.h"
#include "core/cycles/probing/probe_sequence.h"
#include "core/cycles/probing/probing_parameters.h"
#include "core/cycles/probing/probing_registry_entries.h"

namespace kerf::cycles::probing {

namespace {

using namespace parameters;

constexpr ParameterDescriptor kParameters[] = {
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
    angle(307, KERF_TR_NOOP("Preset rotation angle: angle of the reference line"), 360.0),
    kTableRow};

std::optional<CycleError> run(const CycleValues& v, const ProbeData& probe, ProbingMachine& machine,
                              ProbingResults& results) {
    ProbeSequence sequence(400, v, probe, machine);
    const int axis = v.integer(272) - 1;
    Vec2 direction(0.0, 0.0);
    direction[axis] = v.integer(267) < 0 ? -1.0 : 1.0;
    Vec2 p1, p2;
    if (auto e = sequence.touchInPlane(Vec2(v.number(263), v.number(264)), direction, p1)) {
        return e;
    }
    if (auto e = sequence.touchInPlane(Vec2(v.number(265), v.number(266)), direction, p2)) {
        return e;
    }
    sequence.retract();
    const std::optional<double> angle = lineAngleDeg(p1, p2);
    if (!angle) return coincidentTouches(400);
    results.basicRotationDeg = normalizedDeg(*angle - v.number(307));
    results.tableRow = v.integer(305);
    results.transfer = 1;
    return std::nullopt;
}

}  // namespace

const ProbingCycleDescriptor kProbe400{400, KERF_TR_NOOP("BASIC ROTATION"), kParameters, run, {}};

}  // namespace kerf::cycles::probing
