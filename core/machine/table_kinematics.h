#pragma once

#include <array>
#include <optional>

#include <Eigen/Core>

#include "core/geometry/axes.h"
#include "core/machine/machine_config.h"

// Closed-form kinematics of rotary tables (docs/machine-config.md, "Kinematics"). The maths lives
// in core, not in motion/kinematics, because the interpreter needs the inverse (a tilted working
// plane -> rotary-axis angles) and core must not depend on motion; motion may use it from here.
// Pure functions of value types: O(1), no allocation, safe in any thread.
//
// Conventions (ISO 841): an axis angle says how the tool is turned relative to the workpiece,
// right-handed about X (A), Y (B) or Z (C). A table turns the workpiece the other way, so the
// workpiece-to-machine rotation of a table at angle t is a rotation by -t.
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

    bool twoTables() const { return m_two; }
    char primary() const { return m_primary; }
    char secondary() const { return m_secondary; }  // table-table only
    const Vec3& pivot() const { return m_pivot; }
    // The table that carries the workpiece (the secondary of a table-table) and, with the
    // tables at `angles`, the machine direction of its axis; the axis runs through the pivot.
    char innerTable() const { return m_two ? m_secondary : m_primary; }
    Vec3 innerTableAxis(const RotaryAngles& angles) const;

    // Takes vectors fixed to the workpiece into machine directions.
    Rotation workpieceToMachine(const RotaryAngles& angles) const;
    // Machine +Z (the tool) in workpiece coordinates.
    Vec3 toolDirection(const RotaryAngles& angles) const;
    // Linear-axis coordinates (machine minus preset) of a point given in workpiece coordinates of
    // the preset, the tables turned to `angles`; the preset lies at `presetInMachine` when every
    // rotary axis is at 0.
    Vec3 axesOf(const Vec3& workpiece, const RotaryAngles& angles,
                const Vec3& presetInMachine) const;

    // Every pair of angles that turns the tool along the unit vector `direction` (workpiece
    // coordinates). When the direction lies along the secondary axis that axis may take any
    // angle: the solutions then use `freeSecondaryDeg`.
    RotarySolutions solve(const Vec3& direction, double freeSecondaryDeg) const;
    // TABLE ROT: the secondary angle that also brings the workpiece direction `frameX` onto
    // machine +X once the primary axis stands at `primaryDeg` (0 when it cannot).
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

    bool m_two = false;
    char m_primary = 'B';
    char m_secondary = 'C';
    Vec3 m_pivot{0.0, 0.0, 0.0};
    Limits m_primaryLimits;
    Limits m_secondaryLimits;
};

}  // namespace kerf::machine
