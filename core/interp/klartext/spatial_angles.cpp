#include "core/interp/klartext/spatial_angles.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/machine/table_kinematics.h"

namespace kerf::klartext {

Eigen::Matrix3d spatialRotation(double spaDeg, double spbDeg, double spcDeg) {
    using machine::principalRotation;
    return principalRotation('C', spcDeg) * principalRotation('B', spbDeg) *
           principalRotation('A', spaDeg);
}

std::array<double, 3> spatialAnglesOf(const Eigen::Matrix3d& r) {
    constexpr double kDegPerRad = 180.0 / std::numbers::pi;
    const double b = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
    if (std::abs(r(2, 0)) > 1.0 - 1e-12)
        return {0.0, b * kDegPerRad, std::atan2(-r(0, 1), r(1, 1)) * kDegPerRad};
    return {std::atan2(r(2, 1), r(2, 2)) * kDegPerRad, b * kDegPerRad,
            std::atan2(r(1, 0), r(0, 0)) * kDegPerRad};
}

}  // namespace kerf::klartext
