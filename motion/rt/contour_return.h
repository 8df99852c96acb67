#pragma once

#include "motion/path/path_geometry.h"
#include "motion/port/motion_status.h"

// Return to the contour: where a program was interrupted (feed hold at rest, program stop, single
// block) when the operator jogged away, and the order of the way back to it. Plain data and O(axes)
// arithmetic, no allocation: RT thread.
namespace kerf::motion {

class ContourReturn {
public:
    // Remembers the interruption the first time the operator leaves it; later jogs keep it.
    void leave(const AxisVector& point, MotionMode interrupted) noexcept;
    void clear() noexcept { m_interrupted = MotionMode::Idle; }

    bool away() const noexcept { return m_interrupted != MotionMode::Idle; }
    MotionMode interruptedMode() const noexcept { return m_interrupted; }
    const AxisVector& point() const noexcept { return m_point; }

    // The next axis to move back to the point, one at a time, or -1 when all stand on it. The
    // tool axis goes first when it must go up (positive, away from the workpiece) and last when
    // it must go down, so the tool never moves sideways below the height it left.
    int nextAxis(const AxisVector& position, int toolAxis) const noexcept;

private:
    AxisVector m_point{};
    MotionMode m_interrupted = MotionMode::Idle;
};

}  // namespace kerf::motion
