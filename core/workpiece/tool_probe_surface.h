#pragma once

#include <Eigen/Geometry>

#include "core/canon/commands.h"
#include "core/workpiece/simulated_tool_probe.h"

namespace kerf::workpiece {

// What a simulated machine's probe input touches during a TT cycle's touch under motion
// (docs/probing.md, "Tool measurement with the TT"): the real tool on the stylus of the tool
// touch probe. The drives report the tool tip as the control positions it, with the tool
// table's length; the real tool's end face and side follow from the spindle's gauge point. The
// interpreter builds the surface outside the servo cycle, once per touch; touches() neither
// allocates nor locks.
class ToolProbeSurface final : public canon::ProbeSurface {
public:
    // `gauge`: tool tip (stream coordinates) -> the spindle's gauge point (machine
    // coordinates) is gauge.linear() * tip + gauge.translation().
    ToolProbeSurface(SimulatedToolProbe tt, const Eigen::Affine3d& gauge, RealTool tool)
        : m_tt(tt), m_gauge(gauge), m_tool(tool) {}

    bool touches(const Vec3& tip) const override { return m_tt.touches(m_gauge * tip, m_tool); }

private:
    SimulatedToolProbe m_tt;
    Eigen::Affine3d m_gauge;
    RealTool m_tool;
};

}  // namespace kerf::workpiece
