#include "core/cycles/probing/circle_touches.h"

#include <array>
#include <cmath>
#include <numbers>

#include "core/base/translate.h"

namespace kerf::cycles::probing {

std::optional<CycleError> probeCircle(int cycle, ProbeSequence& sequence,
                                      const CircleTouches& touches, FittedCircle& circle) {
    if (std::fabs(touches.stepAngleDeg) < 5.0) {
        return probingError(cycle, "PRB-018",
                            KERF_TR_NOOP("cycle {1}: the stepping angle Q247 must be at least 5 "
                                         "degrees"));
    }
    const double radius = touches.nominalDiameter / 2.0;
    // A hole too small to pre-position near its wall is probed from its centre.
    const bool fromCentre = touches.inside && radius - sequence.standOff() <= 0.0;
    // The ball centres lie on a circle about the real centre, r_b closer to it in a hole and
    // r_b further away on a stud, whichever way each touch went (spec 1.17 G4).
    std::array<Vec2, 4> centres;
    for (int k = 0; k < touches.count; ++k) {
        const double a =
            (touches.startAngleDeg + k * touches.stepAngleDeg) * std::numbers::pi / 180.0;
        const Vec2 outward(std::cos(a), std::sin(a));
        const Vec2 nominal = touches.centre + radius * outward;
        const Vec2 direction = touches.inside ? outward : Vec2(-outward);
        const Vec2* start = fromCentre ? &touches.centre : nullptr;
        Vec2 surface;
        if (auto e = sequence.touchInPlane(nominal, direction, surface, start)) return e;
        centres[static_cast<size_t>(k)] = surface - sequence.ballRadius() * direction;
    }
    auto fitted =
        fitCircle(std::span<const Vec2>(centres.data(), static_cast<size_t>(touches.count)));
    if (!fitted) {
        return probingError(cycle, "PRB-020",
                            KERF_TR_NOOP("cycle {1}: the touch points give no circle"));
    }
    circle = *fitted;
    circle.radius += touches.inside ? sequence.ballRadius() : -sequence.ballRadius();
    return std::nullopt;
}

std::optional<CycleError> probeHoleCentre(int cycle, ProbeSequence& sequence, const Vec2& nominal,
                                          Vec2& centre) {
    std::array<Vec2, 4> balls;
    for (size_t k = 0; k < balls.size(); ++k) {
        const double d = static_cast<double>(k) * std::numbers::pi / 2.0;
        const Vec2 direction(std::cos(d), std::sin(d));
        Vec2 surface;
        if (auto e = sequence.touchInPlane(nominal, direction, surface, &nominal)) return e;
        balls[k] = surface - sequence.ballRadius() * direction;
    }
    auto hole = fitCircle(balls);
    if (!hole) {
        return probingError(cycle, "PRB-020",
                            KERF_TR_NOOP("cycle {1}: the touch points give no circle"));
    }
    centre = hole->centre;
    return std::nullopt;
}

}  // namespace kerf::cycles::probing
