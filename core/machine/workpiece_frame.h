#pragma once

#include <optional>
#include <vector>

#include "core/geometry/axes.h"
#include "core/machine/table_kinematics.h"

namespace kerf::machine {

// Where the tool is on the workpiece: its tip and the unit direction from the tip up the tool.
struct ToolOnPart {
    Vec3 tip{0.0, 0.0, 0.0};
    Vec3 axis{0.0, 0.0, 1.0};
};

// The canonical stream of a machine with rotary axes holds the machine's linear axes (relative
// to the preset) and the axis angles (docs/klartext.md, "What the stream holds"). The graphics and
// the stock simulation draw and cut on the workpiece, which the tables turn and on which a swivel
// head turns the tool: this maps a stream position back through the kinematics. Pure and O(1);
// any thread.
class WorkpieceFrame {
public:
    // `presetInMachine`: the workpiece origin in machine coordinates (linear axes) and the
    // rotary axes' preset values, as the interpreter was given them.
    WorkpieceFrame(const TableKinematics& kinematics, const Pose& presetInMachine);
    // Nothing for a machine without rotary tables (the stream is then already on the workpiece).
    static std::optional<WorkpieceFrame> of(const MachineConfig& config,
                                            const Pose& presetInMachine);

    // A swivel head turns the tip about its pivot by the tool's length: the tool in the spindle
    // (L + DL, as the canonical tool change carries it).
    void setToolLength(double lengthMm) { m_toolLengthMm = lengthMm; }

    RotaryAngles anglesOf(const Pose& stream) const;
    ToolOnPart toPart(const Pose& stream) const;
    // A straight move of the stream in workpiece coordinates: points at equal steps of the move
    // (the end included, the start not) so that no table turns more than `maxStepDeg` between
    // two of them; one point when the tables do not turn (the path is then straight on the part).
    void sample(const Pose& from, const Pose& to, double maxStepDeg,
                std::vector<ToolOnPart>& out) const;

private:
    TableKinematics m_kinematics;
    Vec3 m_preset;
    double m_toolLengthMm = 0.0;
    double m_primaryPreset = 0.0;
    double m_secondaryPreset = 0.0;
    Axis m_primary = Axis::B;
    Axis m_secondary = Axis::C;
};

}  // namespace kerf::machine
