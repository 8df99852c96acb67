#pragma once

#include <array>
#include <optional>

#include <Eigen/Core>

#include "core/geometry/axes.h"
#include "core/machine/machine_config.h"

// Closed-form kinematics of rotary tables and swivel heads (docs/machine-config.md, "Kinematics":
// table, table-table, head-table, head-head). The maths lives
// in core, not in motion/kinematics, because the interpreter needs the inverse (a tilted working
// plane -> rotary-axis angles) and core must not depend on motion; motion may use it from here.
// Pure functions of value types: O(1), no allocation, safe in any thread.
//
// Conventions (ISO 841): an axis angle says how the tool is turned relative to the workpiece,
// right-handed about X (A), Y (B) or Z (C). A table turns the workpiece the other way, so the
// workpiece-to-machine rotation of a table at angle t is a rotation by -t, while a head at angle
// t turns the tool by +t. In all four kinds the tool on the workpiece points along
// Rot(secondary, s) Rot(primary, p) Z, so the solutions are the same; only how the linear axes
// follow differs.
namespace kerf::machine {

using Rotation = Eigen::Matrix3d;

// Right-handed rotation by `degrees` about X (letter A), Y (B) or Z (C).
Rotation principalRotation(char rotaryLetter, double degrees);

struct RotaryAngles {
    double primaryDeg = 0.0;
    double secondaryDeg = 0.0;
    friend bool operator==(const RotaryAngles&, const RotaryAngles&) = default;
};

// SEQ+ / SEQ-: the solution whose primary-axis angle is positive / negative; Shortest: the
// solution nearest to the current angles.
enum class SolutionChoice : uint8_t { Shortest, PrimaryPositive, PrimaryNegative };

// Both solutions for one tool direction, angles in (-180, 180].
struct RotarySolutions {
    std::array<RotaryAngles, 2> list{};
    int count = 0;
};

class TableKinematics {
public:
    // Nothing when the machine has no kinematics section (type "none").
    static std::optional<TableKinematics> of(const MachineConfig& config);

    bool twoAxes() const { return m_kind != KinematicsType::Table; }
    char primary() const { return m_primary; }
    char secondary() const { return m_secondary; }  // two axes only
    const Vec3& pivot() const { return m_pivot; }
    // A head carries the primary (head-table, head-head) or both axes (head-head).
    bool hasHead() const {
        return m_kind == KinematicsType::HeadTable || m_kind == KinematicsType::HeadHead;
    }
    // The table that carries the workpiece (none on a head-head machine) and, with the axes at
    // `angles`, the machine direction of its axis; the axis runs through the pivot.
    bool hasTable() const { return m_kind != KinematicsType::HeadHead; }
    char innerTable() const { return m_kind == KinematicsType::Table ? m_primary : m_secondary; }
    Vec3 innerTableAxis(const RotaryAngles& angles) const;

    // Takes vectors fixed to the workpiece into machine directions (the tables' turn).
    Rotation workpieceToMachine(const RotaryAngles& angles) const;
    // The head's turn of the tool in machine directions (identity without a head).
    Rotation headTurn(const RotaryAngles& angles) const;
    // The tool's axes (X, Y, Z = from the tip up the tool) in workpiece coordinates.
    Rotation toolFrame(const RotaryAngles& angles) const;
    Vec3 toolDirection(const RotaryAngles& angles) const { return toolFrame(angles).col(2); }
    // Linear-axis coordinates (machine minus preset) of the tool tip at a point given in
    // workpiece coordinates of the preset, the axes turned to `angles`; the preset lies at
    // `presetInMachine` when every rotary axis is at 0. The linear axes count the tool tip as if
    // the head stood at 0 (tool length along Z, as motion adds it): a turned head moves the tip
    // by -(H - I)(head pivot + tool length Z), which the axes make up for.
    Vec3 axesOf(const Vec3& workpiece, const RotaryAngles& angles, const Vec3& presetInMachine,
                double toolLengthMm) const;
    // What a turned head adds to the linear axes: (H - I)(head pivot + tool length Z); zero
    // without a head.
    Vec3 headOffset(const RotaryAngles& angles, double toolLengthMm) const;
    // The inverse: the tool tip in workpiece coordinates at the linear axes `axes`.
    Vec3 tipOf(const Vec3& axes, const RotaryAngles& angles, const Vec3& presetInMachine,
               double toolLengthMm) const;

    // Every pair of angles that turns the tool along the unit vector `direction` (workpiece
    // coordinates). When the direction lies along the secondary axis that axis may take any
    // angle: the solutions then use `freeSecondaryDeg`.
    RotarySolutions solve(const Vec3& direction, double freeSecondaryDeg) const;
    // TABLE ROT: the secondary angle that also brings the tool frame's X onto the workpiece
    // direction `frameX` (for tables: `frameX` onto machine +X) once the primary axis stands at
    // `primaryDeg` (0 when it cannot).
    double alignedSecondaryDeg(const Vec3& frameX, double primaryDeg) const;

    // The solution to take: within the soft limits (an angle may be taken a turn further to get
    // inside them; endless axes nearest to where they stand), by the rule, then the shortest way
    // from `current`. Nothing when no solution qualifies.
    std::optional<RotaryAngles> choose(const RotarySolutions& solutions, SolutionChoice rule,
                                       const RotaryAngles& current) const;

private:
    struct Limits {
        double min = -360.0;
        double max = 360.0;
        bool endless = false;
    };
    // The value of `angle` (turns added or removed) nearest to `current` inside the limits.
    static std::optional<double> placed(double angle, const Limits& limits, double current);

    KinematicsType m_kind = KinematicsType::Table;
    char m_primary = 'B';
    char m_secondary = 'C';
    Vec3 m_pivot{0.0, 0.0, 0.0};
    Vec3 m_headPivot{0.0, 0.0, 0.0};  // from the spindle nose, head at 0
    Limits m_primaryLimits;
    Limits m_secondaryLimits;
};

}  // namespace kerf::machine
