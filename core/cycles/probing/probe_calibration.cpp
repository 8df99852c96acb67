// Calibration of the workpiece probe (spec 6): 460 its ball radius (and length) on a sphere, 461
// its length on a ring's top face, 462 its ball radius inside a ring, 463 on a stud. 460, 462
// and 463 also find the centre offset CAL_OF1/CAL_OF2 by a reversal measurement: the same
// circle once more with the probe turned by 180 degrees.
#include <cmath>
#include <numbers>
#include <vector>

#include "core/cycles/probing/probe_geometry.h"
#include "core/cycles/probing/probe_sequence.h"
#include "core/cycles/probing/probing_parameters.h"
#include "core/cycles/probing/probing_registry_entries.h"

namespace kerf::cycles::probing {

namespace {

using namespace parameters;

constexpr ParameterDescriptor kRingRadius =
    length(407, KERF_TR_NOOP("Exact radius of the calibration ring or stud"), 0.0);
constexpr ParameterDescriptor kPointCount =
    choice(423, KERF_TR_NOOP("Number of touch points on the diameter (0: 4)"), 0, 8, 4);
constexpr ParameterDescriptor kReferenceAngle{
    .q = 380,
    .description = KERF_TR_NOOP("Reference angle: main axis to touch point 1"),
    .unit = Unit::Degrees,
    .min = 0.0,
    .max = 360.0};

Vec2 unit(double degrees) {
    const double a = degrees * std::numbers::pi / 180.0;
    return {std::cos(a), std::sin(a)};
}

std::optional<CycleError> fitted(int cycle, const std::vector<Vec2>& balls, FittedCircle& circle) {
    auto c = fitCircle(balls);
    if (!c) {
        return probingError(cycle, "PRB-020",
                            KERF_TR_NOOP("cycle {1}: the touch points give no circle"));
    }
    circle = *c;
    return std::nullopt;
}

// A circle of touches: `pass` fits the ball centres of `count` touches about `centre`.
using CirclePass = std::optional<CycleError> (*)(const CycleValues&, const ProbeData&,
                                                 ProbingMachine&, ProbeSequence&, int count,
                                                 const Vec2& centre, double height,
                                                 FittedCircle& circle);

// The reversal (spec 6, 460/462 impl. notes): with the probe at CAL_ANG its ball lies off the
// spindle by CAL_OF; what CAL_OF misses, e, moves every ball centre the control computes by -e,
// and by +e with the probe turned by 180 degrees. So the circle about the same feature, fitted
// once each way (c_0 at CAL_ANG, c_180 turned), gives e = (c_180 - c_0) / 2 and the new CAL_OF
// = CAL_OF + e. With TRACK the probe faces each probing direction, so the offset is part of the
// effective radius and there is nothing to reverse; a probe that cannot be turned by half a
// turn (its TYPE) gives the radius alone (spec 6, 462). The probe ends at CAL_ANG again.
std::optional<CycleError> reversal(CirclePass pass, const CycleValues& v, const ProbeData& probe,
                                   ProbingMachine& machine, ProbeSequence& sequence,
                                   const FittedCircle& atCalibrationAngle, double height,
                                   ProbingResults& results) {
    if (probe.track || !probe.reversible) return std::nullopt;
    machine.orient(probe.calibrationAngleDeg + 180.0);
    FittedCircle turned;
    if (auto e = pass(v, probe, machine, sequence, 4, atCalibrationAngle.centre, height, turned))
        return e;
    machine.orient(probe.calibrationAngleDeg);
    const Vec2 missed = (turned.centre - atCalibrationAngle.centre) / 2.0;
    results.calibration->centreOffset = probe.centreOffset + missed;
    return std::nullopt;
}

int fineCount(const CycleValues& v) {
    return v.integer(423) < 3 ? 4 : v.integer(423);
}

constexpr ParameterDescriptor k461Parameters[] = {
    length(434, KERF_TR_NOOP("Datum for the length: height of the ring's top face"))};

// 461: from where the probe stands, one touch along -T onto the face at Q434; the gauge point
// at the trigger less Q434 is the effective length (spec 6, impl. note).
std::optional<CycleError> run461(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    ProbeSequence sequence(461, v, probe, machine);
    Vec3 ball;
    if (auto e = sequence.touchFrom(Vec3(0.0, 0.0, -1.0), ball)) return e;
    const double gauge = ball.z() - probe.ballRadius + probe.length;
    results.calibration = ProbeCalibration{gauge - v.number(434), std::nullopt, std::nullopt};
    return std::nullopt;
}

constexpr ParameterDescriptor k462Parameters[] = {kRingRadius, kSetUpClearance, kPointCount,
                                                  kReferenceAngle};

// 462: `count` touches from the ring's centre at the measuring height, the probe then at the
// fitted centre.
std::optional<CycleError> ringPass(const CycleValues& v, const ProbeData&, ProbingMachine& machine,
                                   ProbeSequence& sequence, int count, const Vec2& centre,
                                   double height, FittedCircle& circle) {
    machine.moveTo(Vec3(centre.x(), centre.y(), height));
    std::vector<Vec2> balls;
    for (int k = 0; k < count; ++k) {
        const Vec2 d = unit(v.number(380) + 360.0 * k / count);
        Vec3 ball;
        if (auto e = sequence.touchFrom(Vec3(d.x(), d.y(), 0.0), ball)) return e;
        balls.emplace_back(ball.x(), ball.y());
    }
    if (auto e = fitted(462, balls, circle)) return e;
    machine.moveTo(Vec3(circle.centre.x(), circle.centre.y(), height));
    return std::nullopt;
}

// 462: from the ring's centre at the measuring height, a coarse pass of four touches finds the
// centre, a fine pass of Q423 touches from there the ball centres' circle: r_b = Q407 - rho;
// then the reversal.
std::optional<CycleError> run462(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    ProbeSequence sequence(462, v, probe, machine);
    const Vec3 start = machine.ballCentre();
    FittedCircle coarse;
    if (auto e = ringPass(v, probe, machine, sequence, 4, start.head<2>(), start.z(), coarse))
        return e;
    FittedCircle fine;
    if (auto e =
            ringPass(v, probe, machine, sequence, fineCount(v), coarse.centre, start.z(), fine)) {
        return e;
    }
    results.calibration = ProbeCalibration{std::nullopt, v.number(407) - fine.radius, {}};
    if (auto e = reversal(ringPass, v, probe, machine, sequence, fine, start.z(), results))
        return e;
    machine.moveTo(Vec3(fine.centre.x(), fine.centre.y(), start.z()));
    return std::nullopt;
}

constexpr ParameterDescriptor k463Parameters[] = {kRingRadius, kSetUpClearance, kMoveToClearance,
                                                  kPointCount, kReferenceAngle};

// A ring of `count` touches towards `centre` at ball-centre height `height`, each from
// `standOff` outside it, the probe going up to `travelHeight` between them: the ball centres'
// circle.
struct OutsideRing {
    int cycle;
    double standOff;
    double travelHeight;
};
std::optional<CycleError> touchRingFromOutside(const OutsideRing& ring, const CycleValues& v,
                                               ProbingMachine& machine, ProbeSequence& sequence,
                                               int count, const Vec2& centre, double height,
                                               FittedCircle& circle) {
    std::vector<Vec2> balls;
    for (int k = 0; k < count; ++k) {
        const Vec2 d = unit(v.number(380) + 360.0 * k / count);
        const Vec2 from = centre + ring.standOff * d;
        machine.moveTo(Vec3(from.x(), from.y(), ring.travelHeight));
        machine.moveTo(Vec3(from.x(), from.y(), height));
        Vec3 ball;
        if (auto e = sequence.touchFrom(Vec3(-d.x(), -d.y(), 0.0), ball)) return e;
        balls.emplace_back(ball.x(), ball.y());
        machine.moveTo(Vec3(from.x(), from.y(), ring.travelHeight));
    }
    return fitted(ring.cycle, balls, circle);
}

// 463: `count` touches round the stud about `centre`, each from outside at r_b + SET_UP +
// Q320 from the nominal radius at ball-centre height `height`, between them back at the start
// height (also with Q301 = 0: the path round the stud is not known before the coarse pass).
std::optional<CycleError> studPass(const CycleValues& v, const ProbeData& probe,
                                   ProbingMachine& machine, ProbeSequence& sequence, int count,
                                   const Vec2& centre, double height, FittedCircle& circle) {
    const double clearance = probe.setUp + v.number(320);
    const OutsideRing ring{463, v.number(407) + probe.ballRadius + clearance,
                           height + clearance + 2.0 * probe.ballRadius};
    return touchRingFromOutside(ring, v, machine, sequence, count, centre, height, circle);
}

// 463: from above the stud's centre (the ball's south pole about SET_UP + Q320 above its top),
// touches at the height where the ball lies r_b below the top: a coarse pass, a fine one
// (r_b = rho - Q407), then the reversal.
std::optional<CycleError> run463(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    ProbeSequence sequence(463, v, probe, machine);
    const Vec3 start = machine.ballCentre();
    const double height = start.z() - probe.setUp - v.number(320) - 2.0 * probe.ballRadius;
    FittedCircle coarse;
    if (auto e = studPass(v, probe, machine, sequence, 4, start.head<2>(), height, coarse))
        return e;
    FittedCircle fine;
    if (auto e = studPass(v, probe, machine, sequence, fineCount(v), coarse.centre, height, fine))
        return e;
    results.calibration = ProbeCalibration{std::nullopt, fine.radius - v.number(407), {}};
    if (auto e = reversal(studPass, v, probe, machine, sequence, fine, height, results)) return e;
    machine.moveTo(Vec3(fine.centre.x(), fine.centre.y(), start.z()));
    return std::nullopt;
}

constexpr ParameterDescriptor k460Parameters[] = {
    {.q = 407,
     .description = KERF_TR_NOOP("Exact radius of the calibration sphere"),
     .unit = Unit::Millimetre,
     .min = 0.0001,
     .max = 99.9999},
    kSetUpClearance,
    kMoveToClearance,
    kPointCount,
    kReferenceAngle,
    choice(433, KERF_TR_NOOP("Calibrate the length too: 0 no, 1 yes"), 0, 1, 0),
    length(434, KERF_TR_NOOP("Datum for the length: height of the sphere's centre")),
    choice(455, KERF_TR_NOOP("Number of points for the 3D calibration (0: none)"), 0, 30, 0)};

// `count` touches round the sphere at ball-centre height `height`, each from outside at r_b +
// SET_UP + Q320 from the nominal radius about `centre`, between them back at the height the
// probe started from (the path round the sphere is not known before the first ring): the ball
// centres' circle.
std::optional<CycleError> spherePass(const CycleValues& v, const ProbeData& probe,
                                     ProbingMachine& machine, ProbeSequence& sequence, int count,
                                     const Vec2& centre, double height, FittedCircle& circle) {
    const OutsideRing ring{460, v.number(407) + probe.ballRadius + probe.setUp + v.number(320),
                           machine.ballCentre().z()};
    return touchRingFromOutside(ring, v, machine, sequence, count, centre, height, circle);
}

// 460 (spec 6, impl. note): from above the sphere, roughly over its centre, a touch along -T
// finds the top; a ring of touches where the equator would be with the table's r_b gives the
// centre in the plane (the circle of a ring is centred over the sphere's centre at any height);
// a touch down over that centre gives the north pole. The ring's radius rho_1 at d below the
// pole's ball centre then gives the ball-centre sphere's radius s = (rho_1^2 + d^2) / (2 d), so
// the equator lies s below the pole, and a fine ring there gives r_b = rho - Q407, then the
// reversal at the equator. Q433 = 1: the ball's south pole rested on the sphere's north pole,
// Q434 + Q407: L = gauge point - that.
std::optional<CycleError> run460(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    if (v.integer(455) > 0) {
        return probingError(460, "not-supported",
                            KERF_TR_NOOP("cycle {1}: the 3D calibration (Q455 > 0, option 92) is "
                                         "not available; set Q455 = 0"));
    }
    ProbeSequence sequence(460, v, probe, machine);
    const Vec3 start = machine.ballCentre();
    const Vec3 down(0.0, 0.0, -1.0);
    Vec3 top;
    if (auto e = sequence.touchFrom(down, top)) return e;
    const double rough = top.z() - v.number(407) - probe.ballRadius;
    FittedCircle ring;
    if (auto e =
            spherePass(v, probe, machine, sequence, fineCount(v), start.head<2>(), rough, ring)) {
        return e;
    }
    const Vec2 centre = ring.centre;
    machine.moveTo(Vec3(centre.x(), centre.y(), start.z()));
    Vec3 pole;
    if (auto e = sequence.touchFrom(down, pole)) return e;
    const double d = pole.z() - rough;
    if (d <= 1e-6) {
        return probingError(460, "PRB-020",
                            KERF_TR_NOOP("cycle {1}: the touch points give no circle"));
    }
    const double ballSphere = (ring.radius * ring.radius + d * d) / (2.0 * d);
    const double equatorHeight = pole.z() - ballSphere;
    FittedCircle equator;
    if (auto e =
            spherePass(v, probe, machine, sequence, fineCount(v), centre, equatorHeight, equator)) {
        return e;
    }
    std::optional<double> length;
    if (v.integer(433) == 1) {
        const double gauge = pole.z() - probe.ballRadius + probe.length;
        length = gauge - (v.number(434) + v.number(407));
    }
    results.calibration = ProbeCalibration{length, equator.radius - v.number(407), {}};
    if (auto e =
            reversal(spherePass, v, probe, machine, sequence, equator, equatorHeight, results)) {
        return e;
    }
    machine.moveTo(Vec3(equator.centre.x(), equator.centre.y(), start.z()));
    return std::nullopt;
}

}  // namespace

const ProbingCycleDescriptor kProbe460{
    460, KERF_TR_NOOP("CALIBRATE TS ON SPHERE"), k460Parameters, run460, {}};
const ProbingCycleDescriptor kProbe461{
    461, KERF_TR_NOOP("CALIBRATE TS LENGTH"), k461Parameters, run461, {}};
const ProbingCycleDescriptor kProbe462{
    462, KERF_TR_NOOP("CALIBRATE TS IN RING"), k462Parameters, run462, {}};
const ProbingCycleDescriptor kProbe463{
    463, KERF_TR_NOOP("CALIBRATE TS ON STUD"), k463Parameters, run463, {}};

}  // namespace kerf::cycles::probing
