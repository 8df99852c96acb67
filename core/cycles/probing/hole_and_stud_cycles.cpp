// Cycles from the centres of holes and studs (spec 2 and 3): 401 BASIC ROTATION FROM TWO HOLES,
// 402 BASIC ROTATION FROM TWO STUDS and 418 DATUM FROM FOUR HOLES.
#include "core/cycles/probing/circle_touches.h"
#include "core/cycles/probing/datum_output.h"
#include "core/cycles/probing/probing_parameters.h"
#include "core/cycles/probing/probing_registry_entries.h"

namespace kerf::cycles::probing {

namespace {

using namespace parameters;

constexpr ParameterDescriptor kCentre1Main = length(268, KERF_TR_NOOP("1st centre, main axis"));
constexpr ParameterDescriptor kCentre1Secondary =
    length(269, KERF_TR_NOOP("1st centre, secondary axis"));
constexpr ParameterDescriptor kCentre2Main = length(270, KERF_TR_NOOP("2nd centre, main axis"));
constexpr ParameterDescriptor kCentre2Secondary =
    length(271, KERF_TR_NOOP("2nd centre, secondary axis"));
constexpr ParameterDescriptor kPresetRotation =
    angle(307, KERF_TR_NOOP("Preset rotation angle: angle of the reference line"), 360.0);
constexpr ParameterDescriptor kCompensation =
    choice(402, KERF_TR_NOOP("Compensation: 0 basic rotation, 1 rotary table"), 0, 1, 0);
constexpr ParameterDescriptor kZeroAfterAlignment = choice(
    337, KERF_TR_NOOP("Set the rotary axis display to 0 after alignment: 0 no, 1 yes"), 0, 1, 0);

constexpr ParameterDescriptor kTwoHolesParameters[] = {
    kCentre1Main,     kCentre1Secondary, kCentre2Main, kCentre2Secondary, kMeasuringHeight,
    kClearanceHeight, kPresetRotation,   kTableRow,    kCompensation,     kZeroAfterAlignment};

constexpr ParameterDescriptor kTwoStudsParameters[] = {
    kCentre1Main,
    kCentre1Secondary,
    length(313, KERF_TR_NOOP("Diameter of stud 1 (rather too large)"), 0.0),
    kMeasuringHeight,
    kCentre2Main,
    kCentre2Secondary,
    length(314, KERF_TR_NOOP("Diameter of stud 2 (rather too large)"), 0.0),
    length(315, KERF_TR_NOOP("Measuring height at stud 2: ball centre in the tool axis")),
    kSetUpClearance,
    kClearanceHeight,
    kMoveToClearance,
    kPresetRotation,
    kTableRow,
    kCompensation,
    kZeroAfterAlignment};

constexpr ParameterDescriptor kFourHolesParameters[] = {
    kCentre1Main,
    kCentre1Secondary,
    kCentre2Main,
    kCentre2Secondary,
    length(316, KERF_TR_NOOP("3rd centre, main axis")),
    length(317, KERF_TR_NOOP("3rd centre, secondary axis")),
    length(318, KERF_TR_NOOP("4th centre, main axis")),
    length(319, KERF_TR_NOOP("4th centre, secondary axis")),
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
    kDatumToolAxis};

constexpr uint16_t kFourHolesResults[] = {151, 152};

// Q402 = 1 turns the rotary table about the tool axis (C for Z), which the machine must have.
std::optional<CycleError> checkCompensation(int cycle, const CycleValues& v,
                                            const ProbeData& probe) {
    if (v.integer(402) == 1 && probe.tableAxes.find('C') == std::string::npos) {
        return probingError(cycle, "PRB-011",
                            KERF_TR_NOOP("cycle {1}: this machine has no rotary table axis to "
                                         "correct the rotation with"));
    }
    return std::nullopt;
}

// The line from centre 1 to centre 2 (G2) less Q307: Q402 = 0 a basic rotation; Q402 = 1 the C
// table turns by it (as 403: a table at angle t turns the part by -t), Q337 = 1 then zeroes
// the C display in row Q305, Q337 = 0 leaves the display (the preset active at the call).
std::optional<CycleError> setRotation(int cycle, const CycleValues& v, const Vec2& first,
                                      const Vec2& second, ProbingResults& results) {
    const std::optional<double> line = lineAngleDeg(first, second);
    if (!line) return coincidentTouches(cycle);
    const double rotation = normalizedDeg(*line - v.number(307));
    results.transfer = 1;
    if (v.integer(402) == 1) {
        RotaryCompensation rotary;
        rotary.axis = 'C';
        rotary.turnDeg = rotation;
        rotary.zeroDisplay = v.integer(337) == 1;
        results.rotary = rotary;
        results.tableRow = rotary.zeroDisplay ? v.integer(305) : -1;
        return std::nullopt;
    }
    results.basicRotationDeg = rotation;
    results.tableRow = v.integer(305);
    return std::nullopt;
}

// The hole touches start at each hole's centre and rise between the holes; 401 and 418 have
// no Q320 and no Q301.
CycleValues holeValues(const CycleValues& v) {
    CycleValues holes = v;
    holes.set(320, 0.0);
    holes.set(301, 1.0);
    return holes;
}

std::optional<CycleError> run401(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    if (auto e = checkCompensation(401, v, probe)) return e;
    const CycleValues holes = holeValues(v);
    ProbeSequence sequence(401, holes, probe, machine);
    Vec2 first, second;
    if (auto e = probeHoleCentre(401, sequence, Vec2(v.number(268), v.number(269)), first)) {
        return e;
    }
    sequence.retract();
    if (auto e = probeHoleCentre(401, sequence, Vec2(v.number(270), v.number(271)), second)) {
        return e;
    }
    sequence.retract();
    return setRotation(401, v, first, second, results);
}

// 402: four touches at 0, 90, 180 and 270 degrees inward on each stud (spec impl. note), stud 2
// at its own measuring height Q315.
std::optional<CycleError> run402(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    if (auto e = checkCompensation(402, v, probe)) return e;
    ProbeSequence sequence1(402, v, probe, machine);
    FittedCircle stud1, stud2;
    const CircleTouches touches1{
        Vec2(v.number(268), v.number(269)), v.number(313), 0.0, 90.0, 4, false};
    if (auto e = probeCircle(402, sequence1, touches1, stud1)) return e;
    sequence1.retract();
    CycleValues second = v;
    second.set(261, v.number(315));
    ProbeSequence sequence2(402, second, probe, machine);
    const CircleTouches touches2{
        Vec2(v.number(270), v.number(271)), v.number(314), 0.0, 90.0, 4, false};
    if (auto e = probeCircle(402, sequence2, touches2, stud2)) return e;
    sequence2.retract();
    return setRotation(402, v, stud1.centre, stud2.centre, results);
}

// 418: the datum is where the line from hole 1 to hole 3 crosses the line from hole 2 to hole 4.
std::optional<CycleError> run418(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    if (auto e = checkTransfer(418, v)) return e;
    const CycleValues holes = holeValues(v);
    ProbeSequence sequence(418, holes, probe, machine);
    constexpr uint16_t kCentres[4][2] = {{268, 269}, {270, 271}, {316, 317}, {318, 319}};
    Vec2 centres[4];
    for (size_t h = 0; h < 4; ++h) {
        const Vec2 nominal(v.number(kCentres[h][0]), v.number(kCentres[h][1]));
        if (auto e = probeHoleCentre(418, sequence, nominal, centres[h])) return e;
        sequence.retract();
    }
    auto crossing = intersect(centres[0], centres[2], centres[1], centres[3]);
    if (!crossing) {
        return probingError(418, "PRB-019", KERF_TR_NOOP("cycle {1}: the two edges are parallel"));
    }
    results.set(151, crossing->x());
    results.set(152, crossing->y());
    DatumResult datum;
    datum.measured = {crossing->x(), crossing->y(), std::nullopt};
    datum.nominal = {v.number(331), v.number(332), 0.0};
    if (auto e = toolAxisDatum(sequence, holes, datum)) return e;
    sequence.retract();
    setDatum(v, results, datum);
    return std::nullopt;
}

}  // namespace

const ProbingCycleDescriptor kProbe401{
    401, KERF_TR_NOOP("ROT 2 HOLES"), kTwoHolesParameters, run401, {}};
const ProbingCycleDescriptor kProbe402{
    402, KERF_TR_NOOP("ROT 2 STUDS"), kTwoStudsParameters, run402, {}};
const ProbingCycleDescriptor kProbe418{418, KERF_TR_NOOP("DATUM FROM 4 HOLES"),
                                       kFourHolesParameters, run418, kFourHolesResults};

}  // namespace kerf::cycles::probing
