#include "core/machine/workpiece_frame.h"

#include <algorithm>
#include <cmath>

namespace kerf::machine {

WorkpieceFrame::WorkpieceFrame(const TableKinematics& kinematics, const Pose& presetInMachine)
    : m_kinematics(kinematics),
      m_preset(presetInMachine.xyz()),
      m_primary(*axisFromLetter(kinematics.primary())),
      m_secondary(*axisFromLetter(kinematics.secondary())) {
    m_primaryPreset = presetInMachine[m_primary];
    if (m_kinematics.twoAxes()) m_secondaryPreset = presetInMachine[m_secondary];
}

std::optional<WorkpieceFrame> WorkpieceFrame::of(const MachineConfig& config,
                                                 const Pose& presetInMachine) {
    const std::optional<TableKinematics> kinematics = TableKinematics::of(config);
    if (!kinematics) return std::nullopt;
    return WorkpieceFrame(*kinematics, presetInMachine);
}

RotaryAngles WorkpieceFrame::anglesOf(const Pose& stream) const {
    RotaryAngles angles;
    angles.primaryDeg = stream[m_primary] + m_primaryPreset;
    if (m_kinematics.twoAxes()) angles.secondaryDeg = stream[m_secondary] + m_secondaryPreset;
    return angles;
}

ToolOnPart WorkpieceFrame::toPart(const Pose& stream) const {
    const RotaryAngles angles = anglesOf(stream);
    ToolOnPart out;
    out.tip = m_kinematics.tipOf(stream.xyz(), angles, m_preset, m_toolLengthMm);
    out.axis = m_kinematics.toolDirection(angles);
    return out;
}

void WorkpieceFrame::sample(const Pose& from, const Pose& to, double maxStepDeg,
                            std::vector<ToolOnPart>& out) const {
    const RotaryAngles a = anglesOf(from);
    const RotaryAngles b = anglesOf(to);
    const double turn =
        std::max(std::abs(b.primaryDeg - a.primaryDeg), std::abs(b.secondaryDeg - a.secondaryDeg));
    constexpr int kMaxSteps = 4096;
    const double steps = maxStepDeg > 0.0 ? std::ceil(turn / maxStepDeg) : 1.0;
    const int count = std::isfinite(steps) ? std::clamp(static_cast<int>(steps), 1, kMaxSteps) : 1;
    for (int i = 1; i <= count; ++i) {
        const double t = static_cast<double>(i) / count;
        Pose at = to;
        for (size_t k = 0; k < at.values.size(); ++k)
            at.values[k] = from.values[k] + (to.values[k] - from.values[k]) * t;
        if (i == count) at = to;
        out.push_back(toPart(at));
    }
}

}  // namespace kerf::machine
