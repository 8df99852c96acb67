// Measuring cycles 430 MEASURE BOLT HOLE CIRCLE and 431 MEASURE PLANE (spec 4).
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "core/cycles/probing/circle_touches.h"
#include "core/cycles/probing/measurement_status.h"
#include "core/cycles/probing/probing_parameters.h"
#include "core/cycles/probing/probing_registry_entries.h"

namespace kerf::cycles::probing {

namespace {

using namespace parameters;

constexpr ParameterDescriptor kBoltCircleParameters[] = {
    length(273, KERF_TR_NOOP("Nominal centre, main axis")),
    length(274, KERF_TR_NOOP("Nominal centre, secondary axis")),
    length(262, KERF_TR_NOOP("Nominal diameter"), 0.0),
    angle(291, KERF_TR_NOOP("Polar angle of the 1st hole centre"), 360.0),
    angle(292, KERF_TR_NOOP("Polar angle of the 2nd hole centre"), 360.0),
    angle(293, KERF_TR_NOOP("Polar angle of the 3rd hole centre"), 360.0),
    kMeasuringHeight,
    kClearanceHeight,
    length(288, KERF_TR_NOOP("Maximum permitted diameter (0: not monitored)"), 0.0),
    length(289, KERF_TR_NOOP("Minimum permitted diameter"), 0.0),
    length(279, KERF_TR_NOOP("Centre tolerance, main axis (0: not monitored)"), 0.0),
    length(280, KERF_TR_NOOP("Centre tolerance, secondary axis"), 0.0),
    kMeasuringLog,
    kStopOnToleranceError,
    kMonitoredTool};

constexpr ParameterDescriptor kPlaneParameters[] = {
    length(263, KERF_TR_NOOP("1st touch point, main axis")),
    length(264, KERF_TR_NOOP("1st touch point, secondary axis")),
    length(294, KERF_TR_NOOP("1st touch point, nominal surface in the tool axis")),
    length(265, KERF_TR_NOOP("2nd touch point, main axis")),
    length(266, KERF_TR_NOOP("2nd touch point, secondary axis")),
    length(295, KERF_TR_NOOP("2nd touch point, nominal surface in the tool axis")),
    length(296, KERF_TR_NOOP("3rd touch point, main axis")),
    length(297, KERF_TR_NOOP("3rd touch point, secondary axis")),
    length(298, KERF_TR_NOOP("3rd touch point, nominal surface in the tool axis")),
    kSetUpClearance,
    kClearanceHeight,
    kMeasuringLog};

constexpr uint16_t kBoltCircleResults[] = {151, 152, 153, 161, 162, 163, 180, 181, 182};
constexpr uint16_t kPlaneResults[] = {158, 159, 170, 171, 172, 173, 174, 175};

double degrees(double radians) {
    return radians * 180.0 / std::numbers::pi;
}

// 430: each hole's centre from four touches from its nominal centre (G5), then the circle through
// the three centres, compared with the nominal one.
std::optional<CycleError> run430(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    CycleValues holes = v;
    holes.set(320, 0.0);
    holes.set(301, 1.0);
    ProbeSequence sequence(430, holes, probe, machine);
    const Vec2 nominal(v.number(273), v.number(274));
    std::array<Vec2, 3> centres;
    for (size_t h = 0; h < centres.size(); ++h) {
        const double a = v.number(static_cast<uint16_t>(291 + h)) * std::numbers::pi / 180.0;
        const Vec2 hole = nominal + v.number(262) / 2.0 * Vec2(std::cos(a), std::sin(a));
        if (auto e = probeHoleCentre(430, sequence, hole, centres[h])) return e;
        sequence.retract();
    }
    auto circle = fitCircle(centres);
    if (!circle) {
        return probingError(430, "PRB-020",
                            KERF_TR_NOOP("cycle {1}: the hole centres give no circle"));
    }
    const double diameter = 2.0 * circle->radius;
    const Vec2 deviation = circle->centre - nominal;
    results.set(151, circle->centre.x());
    results.set(152, circle->centre.y());
    results.set(153, diameter);
    results.set(161, deviation.x());
    results.set(162, deviation.y());
    results.set(163, diameter - v.number(262));
    MeasurementStatus status(MeasurementStatus::Feature::Pattern);
    status.size(diameter, v.number(288), v.number(289));
    status.position(deviation.x(), v.number(279));
    status.position(deviation.y(), v.number(280));
    status.write(430, v, results);
    results.toolCorrection =
        ToolCorrection{.delta = 0.5 * (diameter - v.number(262)), .breakageOnly = true};
    if (v.integer(281) != 0) {
        results.protocol = circleLog({.nominalCentre = nominal,
                                      .nominalDiameter = v.number(262),
                                      .centreToleranceMain = v.number(279),
                                      .centreToleranceSecondary = v.number(280),
                                      .maxDiameter = v.number(288),
                                      .minDiameter = v.number(289),
                                      .actualCentre = circle->centre,
                                      .actualDiameter = diameter,
                                      .measuringHeight = v.number(261)});
        results.protocolStop = v.integer(281) == 2;
    }
    return std::nullopt;
}

// 431: three touches along -T; the plane's projection angles and its spatial angles A, B, C
// (spec 4, impl. note: R = [x' y' z'] = Rz(C) Ry(B) Rx(A)).
std::optional<CycleError> run431(const CycleValues& v, const ProbeData& probe,
                                 ProbingMachine& machine, ProbingResults& results) {
    ProbeSequence sequence(431, v, probe, machine);
    constexpr uint16_t kPoints[3][3] = {{263, 264, 294}, {265, 266, 295}, {296, 297, 298}};
    std::array<Vec3, 3> p;
    for (size_t i = 0; i < p.size(); ++i) {
        const Vec2 at(v.number(kPoints[i][0]), v.number(kPoints[i][1]));
        double surface = 0.0;
        if (auto e = sequence.touchDown(at, v.number(kPoints[i][2]), surface)) return e;
        p[i] = Vec3(at.x(), at.y(), surface);
    }
    sequence.retract();
    const Vec3 u = p[1] - p[0];
    const Vec3 w = p[2] - p[0];
    const Vec3 normal = u.cross(w);
    if (normal.norm() < 1e-9 * u.norm() * w.norm() || std::fabs(normal.z()) < 1e-12) {
        return probingError(431, "PRB-008",
                            KERF_TR_NOOP("cycle {1}: the three touch points lie on one line"));
    }
    // T = t0 + a M + b S through the three points.
    const double a = -normal.x() / normal.z();
    const double b = -normal.y() / normal.z();
    const Vec3 x = u.normalized();
    const Vec3 z = normal.z() > 0.0 ? normal.normalized() : Vec3(-normal.normalized());
    const Vec3 y = z.cross(x);
    // R's columns are x', y', z'; R31 = x'.z, R32 = y'.z, R33 = z'.z, R21 = x'.y, R11 = x'.x.
    double angleA = 0.0, angleB = 0.0, angleC = 0.0;
    angleB = -std::asin(std::clamp(x.z(), -1.0, 1.0));
    if (std::fabs(std::fabs(x.z()) - 1.0) < 1e-12) {
        angleA = std::atan2(-z.y(), y.y());
    } else {
        angleA = std::atan2(y.z(), z.z());
        angleC = std::atan2(x.y(), x.x());
    }
    results.set(158, degrees(std::atan(b)));
    results.set(159, -degrees(std::atan(a)));
    results.set(170, degrees(angleA));
    results.set(171, degrees(angleB));
    results.set(172, degrees(angleC));
    results.set(173, p[0].z());
    results.set(174, p[1].z());
    results.set(175, p[2].z());
    if (v.integer(281) != 0) {
        results.protocol =
            std::vector<std::string>{"Actual values:",
                                     logLine("  1st point tool axis", p[0].z()),
                                     logLine("  2nd point tool axis", p[1].z()),
                                     logLine("  3rd point tool axis", p[2].z()),
                                     "Angles:",
                                     logLine("  projection angle A", degrees(std::atan(b))),
                                     logLine("  projection angle B", -degrees(std::atan(a))),
                                     logLine("  spatial angle A", degrees(angleA)),
                                     logLine("  spatial angle B", degrees(angleB)),
                                     logLine("  spatial angle C", degrees(angleC))};
        results.protocolStop = v.integer(281) == 2;
    }
    return std::nullopt;
}

}  // namespace

const ProbingCycleDescriptor kProbe430{430, KERF_TR_NOOP("MEASURE BOLT HOLE CIRC"),
                                       kBoltCircleParameters, run430, kBoltCircleResults};
const ProbingCycleDescriptor kProbe431{431, KERF_TR_NOOP("MEASURE PLANE"), kPlaneParameters, run431,
                                       kPlaneResults};

}  // namespace kerf::cycles::probing
