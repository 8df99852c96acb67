#include "core/cycles/tapping/tapping_checks.h"

#include <cmath>
#include <string>

#include "core/base/fixed_format.h"
#include "core/base/translate.h"

namespace kerf::cycles {

std::optional<CycleError> checkToolPitch(int cycle, const ToolInfo& tool, double pitch) {
    if (tool.pitch == 0.0 || std::fabs(std::fabs(tool.pitch) - std::fabs(pitch)) <= 1e-4) {
        return std::nullopt;
    }
    return CycleError{"cycle-tool",
                      KERF_TR_NOOP("cycle {1}: the thread pitch {2} differs from the pitch {3} "
                                   "of the tool in the tool table"),
                      {std::to_string(cycle), formatFixed(std::fabs(pitch), 4),
                       formatFixed(std::fabs(tool.pitch), 4)}};
}

std::optional<CycleError> checkPitchNotZero(int cycle, uint16_t q, double pitch) {
    if (pitch != 0.0) return std::nullopt;
    return CycleError{"cycle-parameter",
                      KERF_TR_NOOP("cycle {1}: the thread pitch Q{2} is 0"),
                      {std::to_string(cycle), std::to_string(q)}};
}

double spindleAngleAfter(double startDeg, double distance, double lead) {
    double angle = std::fmod(startDeg + 360.0 * std::fabs(distance / lead), 360.0);
    if (angle < 0.0) angle += 360.0;
    // Whole revolutions come back to the start angle exactly, not to 359.9999...
    if (std::fabs(angle - 360.0) < 1e-6 || std::fabs(angle) < 1e-6) angle = 0.0;
    return angle;
}

}  // namespace kerf::cycles
