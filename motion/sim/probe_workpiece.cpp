#include "motion/sim/probe_workpiece.h"

#include <array>

namespace kerf::motion {

std::function<bool(const AxisVector& tip)> probeWorkpiece(const machine::MachineConfig& config,
                                                          const AxisVector& workOffset) {
    const machine::ProbeWorkpieceConfig& box = config.probeWorkpiece;
    if (!box.enabled) return {};
    // X, Y, Z are the first three axes of an AxisVector.
    const std::array<double, 3> low{box.xMinMm, box.yMinMm, box.zMinMm};
    const std::array<double, 3> high{box.xMaxMm, box.yMaxMm, box.zMaxMm};
    return [low, high, workOffset](const AxisVector& tip) {
        for (size_t i = 0; i < low.size(); ++i) {
            const double machine = tip[i] + workOffset[i];
            if (machine < low[i] || machine > high[i]) return false;
        }
        return true;
    };
}

}  // namespace kerf::motion
