#include "motion/rt/contour_return.h"

#include <cmath>

namespace kerf::motion {

namespace {

constexpr double kOnPointMm = 1e-9;

}  // namespace

void ContourReturn::leave(const AxisVector& point, MotionMode interrupted) noexcept {
    if (away()) return;
    m_point = point;
    m_interrupted = interrupted;
}

int ContourReturn::nextAxis(const AxisVector& position, int toolAxis) const noexcept {
    auto off = [&](size_t axis) { return std::fabs(m_point[axis] - position[axis]) > kOnPointMm; };
    const bool toolValid = toolAxis >= 0 && static_cast<size_t>(toolAxis) < kAxisCount;
    const auto tool = static_cast<size_t>(toolValid ? toolAxis : 0);
    if (toolValid && off(tool) && m_point[tool] > position[tool]) return toolAxis;
    for (size_t axis = 0; axis < kAxisCount; ++axis) {
        if ((!toolValid || axis != tool) && off(axis)) return static_cast<int>(axis);
    }
    if (toolValid && off(tool)) return toolAxis;
    return -1;
}

}  // namespace kerf::motion
