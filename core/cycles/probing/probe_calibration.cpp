// Calibration of the workpiece probe (spec 6): 460 its ball radius (and length) on a sphere, 461
// its length on a ring's top face, 462 its ball radius inside a ring, 463 on a stud. The
// simulated probe runs true and cannot be turned for a reversal measurement, so the centre
// offsets CAL_OF1/CAL_OF2 are not determined.
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
    results.calibration = ProbeCalibration{gauge - v.number(434), std::nullopt};
    return std::nullopt;
}

constexpr ParameterDescriptor k462Parameters[] = {kRingRadius, kSetUpClearance, kPointCount,
                                                  kReferenceAngle};

// 462: from the ring's centre at the measuring height, a coarse pass of four touches finds the
// centre, a fine pass of Q423 touches from there the ball centres' circle: r_b = Q407 - rho.
std::optional<CycleError> run462(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    const int fine = v.integer(423) < 3 ? 4 : v.integer(423);
    ProbeSequence sequence(462, v, probe, machine);
    Vec3 centre = machine.ballCentre();
    FittedCircle circle;
    for (int count : {4, fine}) {
        std::vector<Vec2> balls;
        for (int k = 0; k < count; ++k) {
            const Vec2 d = unit(v.number(380) + 360.0 * k / count);
            Vec3 ball;
            if (auto e = sequence.touchFrom(Vec3(d.x(), d.y(), 0.0), ball)) return e;
            balls.emplace_back(ball.x(), ball.y());
        }
        if (auto e = fitted(462, balls, circle)) return e;
        centre = Vec3(circle.centre.x(), circle.centre.y(), centre.z());
        machine.moveTo(centre);
    }
    results.calibration = ProbeCalibration{std::nullopt, v.number(407) - circle.radius};
    return std::nullopt;
}

constexpr ParameterDescriptor k463Parameters[] = {kRingRadius, kSetUpClearance, kMoveToClearance,
                                                  kPointCount, kReferenceAngle};

// 463: from above the stud's centre (the ball's south pole about SET_UP + Q320 above its top),
// each touch comes from outside at the height where the ball lies r_b below the top; between
// the touches the probe returns to the start height (also with Q301 = 0: the path round the
// stud is not known before the coarse pass). r_b = rho - Q407.
std::optional<CycleError> run463(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    const int fine = v.integer(423) < 3 ? 4 : v.integer(423);
    ProbeSequence sequence(463, v, probe, machine);
    const double clearance = probe.setUp + v.number(320);
    const Vec3 start = machine.ballCentre();
    const double height = start.z() - clearance - 2.0 * probe.ballRadius;
    Vec2 centre(start.x(), start.y());
    FittedCircle circle;
    for (int count : {4, fine}) {
        std::vector<Vec2> balls;
        for (int k = 0; k < count; ++k) {
            const Vec2 d = unit(v.number(380) + 360.0 * k / count);
            const Vec2 from = centre + (v.number(407) + probe.ballRadius + clearance) * d;
            machine.moveTo(Vec3(from.x(), from.y(), start.z()));
            machine.moveTo(Vec3(from.x(), from.y(), height));
            Vec3 ball;
            if (auto e = sequence.touchFrom(Vec3(-d.x(), -d.y(), 0.0), ball)) return e;
            balls.emplace_back(ball.x(), ball.y());
            machine.moveTo(Vec3(from.x(), from.y(), start.z()));
        }
        if (auto e = fitted(463, balls, circle)) return e;
        centre = circle.centre;
    }
    machine.moveTo(Vec3(centre.x(), centre.y(), start.z()));
    results.calibration = ProbeCalibration{std::nullopt, circle.radius - v.number(407)};
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

// Q423 touches round the sphere at ball-centre height `height`, each from outside at r_b +
// SET_UP + Q320 from the nominal radius about `centre`, between them back at the start height
// (the path round the sphere is not known before the first ring): the ball centres' circle.
std::optional<CycleError> sphereRing(const CycleValues& v, const ProbeData& probe,
                                     ProbingMachine& machine, ProbeSequence& sequence,
                                     const Vec2& centre, double height, double startHeight,
                                     FittedCircle& circle) {
    const int count = v.integer(423) < 3 ? 4 : v.integer(423);
    const double standOff = v.number(407) + probe.ballRadius + probe.setUp + v.number(320);
    std::vector<Vec2> balls;
    for (int k = 0; k < count; ++k) {
        const Vec2 d = unit(v.number(380) + 360.0 * k / count);
        const Vec2 from = centre + standOff * d;
        machine.moveTo(Vec3(from.x(), from.y(), startHeight));
        machine.moveTo(Vec3(from.x(), from.y(), height));
        Vec3 ball;
        if (auto e = sequence.touchFrom(Vec3(-d.x(), -d.y(), 0.0), ball)) return e;
        balls.emplace_back(ball.x(), ball.y());
        machine.moveTo(Vec3(from.x(), from.y(), startHeight));
    }
    return fitted(460, balls, circle);
}

// 460 (spec 6, impl. note): from above the sphere, roughly over its centre, a touch along -T
// finds the top; a ring of touches where the equator would be with the table's r_b gives the
// centre in the plane (the circle of a ring is centred over the sphere's centre at any height);
// a touch down over that centre gives the north pole. The ring's radius rho_1 at d below the
// pole's ball centre then gives the ball-centre sphere's radius s = (rho_1^2 + d^2) / (2 d), so
// the equator lies s below the pole, and a fine ring there gives r_b = rho - Q407. Q433 = 1:
// the ball's south pole rested on the sphere's north pole, Q434 + Q407: L = gauge point - that.
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
    if (auto e = sphereRing(v, probe, machine, sequence, Vec2(start.x(), start.y()), rough,
                            start.z(), ring)) {
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
    FittedCircle equator;
    if (auto e = sphereRing(v, probe, machine, sequence, centre, pole.z() - ballSphere, start.z(),
                            equator)) {
        return e;
    }
    machine.moveTo(Vec3(equator.centre.x(), equator.centre.y(), start.z()));
    std::optional<double> length;
    if (v.integer(433) == 1) {
        const double gauge = pole.z() - probe.ballRadius + probe.length;
        length = gauge - (v.number(434) + v.number(407));
    }
    results.calibration = ProbeCalibration{length, equator.radius - v.number(407)};
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
