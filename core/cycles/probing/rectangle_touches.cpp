#include "core/cycles/probing/rectangle_touches.h"

#include <array>
#include <cmath>

namespace kerf::cycles::probing {

std::optional<CycleError> probeRectangle(ProbeSequence& sequence, const Vec2& centre,
                                         const Vec2& sides, bool inside,
                                         MeasuredRectangle& measured) {
    const Vec2 half = sides / 2.0;
    // Too small to pre-position near the walls: probe every side from the centre.
    const bool fromCentre = inside && half.minCoeff() - sequence.standOff() < 0.0;
    std::array<Vec2, 4> touched;
    for (size_t k = 0; k < touched.size(); ++k) {
        const auto axis = static_cast<Eigen::Index>(k / 2);
        Vec2 outward(0.0, 0.0);
        outward[axis] = k % 2 == 0 ? -1.0 : 1.0;
        const Vec2 nominal = centre + half[axis] * outward;
        const Vec2 direction = inside ? outward : Vec2(-outward);
        if (auto e = sequence.touchInPlane(nominal, direction, touched[k],
                                           fromCentre ? &centre : nullptr)) {
            return e;
        }
    }
    measured.centre =
        Vec2((touched[0].x() + touched[1].x()) / 2.0, (touched[2].y() + touched[3].y()) / 2.0);
    measured.sides = Vec2(std::fabs(touched[1].x() - touched[0].x()),
                          std::fabs(touched[3].y() - touched[2].y()));
    return std::nullopt;
}

}  // namespace kerf::cycles::probing
