#include "core/workpiece/simulated_tool_probe.h"

#include <algorithm>
#include <cmath>

namespace kerf::workpiece {

double SimulatedToolProbe::distance(const Vec3& gauge, const RealTool& tool) const {
    // In the plane: from the tool's axis to the stylus outline, less the tool radius.
    const double dx = gauge.x() - m_stylus.top.x();
    const double dy = gauge.y() - m_stylus.top.y();
    double outline = 0.0;
    if (m_stylus.cube) {
        const double half = m_stylus.diameter / 2.0;
        const double qx = std::abs(dx) - half;
        const double qy = std::abs(dy) - half;
        outline =
            std::hypot(std::max(qx, 0.0), std::max(qy, 0.0)) + std::min(std::max(qx, qy), 0.0);
    } else {
        outline = std::hypot(dx, dy) - m_stylus.diameter / 2.0;
    }
    const double inPlane = outline - tool.radius;
    // Along the tool axis: from the tool's end face down to the stylus's top.
    const double above = gauge.z() - tool.length - m_stylus.top.z();
    if (inPlane > 0.0 && above > 0.0) return std::hypot(inPlane, above);
    return std::max(inPlane, above);
}

bool SimulatedToolProbe::touches(const Vec3& gauge, const RealTool& tool) const {
    return distance(gauge, tool) <= 0.0;
}

std::optional<Vec3> SimulatedToolProbe::touch(const Vec3& gauge, const Vec3& direction,
                                              double maxPath, const RealTool& tool) const {
    // Sphere tracing as for the workpiece: a face met square on is reached in one step.
    constexpr double kContact = 1e-9;
    constexpr int kMaxSteps = 100000;
    double travelled = 0.0;
    for (int step = 0; step < kMaxSteps && travelled <= maxPath; ++step) {
        const Vec3 at = gauge + travelled * direction;
        const double gap = distance(at, tool);
        if (gap <= kContact) return at;
        travelled += gap;
    }
    return std::nullopt;
}

}  // namespace kerf::workpiece
