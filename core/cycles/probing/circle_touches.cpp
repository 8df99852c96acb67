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
    std::array<Vec2, 4> surface;
    for (int k = 0; k < touches.count; ++k) {
        const double a =
            (touches.startAngleDeg + k * touches.stepAngleDeg) * std::numbers::pi / 180.0;
        const Vec2 outward(std::cos(a), std::sin(a));
        const Vec2 nominal = touches.centre + radius * outward;
        const Vec2 direction = touches.inside ? outward : Vec2(-outward);
        const Vec2* start = fromCentre ? &touches.centre : nullptr;
        if (auto e =
                sequence.touchInPlane(nominal, direction, surface[static_cast<size_t>(k)], start)) {
            return e;
        }
    }
    auto fitted =
        fitCircle(std::span<const Vec2>(surface.data(), static_cast<size_t>(touches.count)));
    if (!fitted) {
        return probingError(cycle, "PRB-020",
                            KERF_TR_NOOP("cycle {1}: the touch points give no circle"));
    }
    circle = *fitted;
    return std::nullopt;
}

}  // namespace kerf::cycles::probing
