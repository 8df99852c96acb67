// Tool centre point management (M128/M129, FUNCTION TCPM): programmed positions are tool-tip
// positions on the part while the rotary tables turn. The canonical stream holds the machine's
// linear axes, so while TCPM is on the path (roundings, radius compensation, lines and arcs)
// works on the part and leaves as straight pieces of the axes, as many as keep the tip within
// half the path tolerance (the planner blends the pieces within the other half). The same
// mechanism lets a swivel head's oblique working plane run arcs and radius compensation.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/base/fixed_format.h"
#include "core/base/translate.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/interp/klartext/spatial_angles.h"

namespace kerf::klartext {

void KlartextInterpreter::switchTcpm(const TcpmBlock& mode) {
    if (!checkPathError(activePath().flush())) return;
    if (mode.on && !m_kinematics) {
        fail("tcpm", KERF_TR_NOOP("TCPM needs the rotary axes described in the machine file "
                                  "([kinematics], e.g. --machine mill5)"));
        return;
    }
    m_tcpm = mode.on;
    m_tcpmSpatial = mode.on && mode.spatialAngles;
    m_spatialDeg = {0.0, 0.0, 0.0};
    m_tcpmSpace.feedContour = mode.feedContour;
    m_tcpmSpace.vectorPath = mode.vectorPath;
    // The axes stay where they are; the program now counts in tip positions on the part. In a
    // tilted plane those are the plane's coordinates, whatever angle the tables turn to: the
    // frame loses the tables' turn, which the space's kinematics take over (and back).
    setTableFrame();
    updatePathSpace();
    m_programmed = programOfPath(m_path.toolPosition());
}

void KlartextInterpreter::updatePathSpace() {
    const interp::PathSpace* space = nullptr;
    if (m_tcpm) {
        space = &m_tcpmSpace;
    } else if (m_frame.tilted() && !m_frame.keepsPlane(workingPlane())) {
        // A swivel head turned out of the machine's planes: arcs and radius compensation are
        // worked out in the tilted plane.
        space = &m_tiltedPlaneSpace;
    }
    if (space == nullptr && m_path.space() == nullptr) return;  // the axes' own, as before
    if (!checkPathError(m_path.flush())) return;
    // Where the axes are, through the space that brought them there.
    const Pose at = m_path.machinePosition();
    if (space == &m_tiltedPlaneSpace) m_tiltedPlaneSpace.frame = m_frame;
    if (space == &m_tcpmSpace) {
        m_tcpmSpace.frame = m_frame;
        const double reach =
            m_tool.cuttingLength > 0.0 ? m_tool.cuttingLength : m_tool.effectiveLength();
        m_tcpmSpace.reachMm = std::max(reach, 1.0);
    }
    const double tolerance =
        0.5 * std::max(m_settings.machine ? m_settings.machine->pathToleranceMm : 0.0, 0.001);
    m_path.setSpace(space, tolerance);
    m_path.resetToMachine(at);
}

Pose KlartextInterpreter::pathOfProgram(const Pose& program) const {
    if (pathInTiltedPlane()) return m_frame.toTiltedPlane(program);
    return m_frame.toWorkpiece(program);
}

bool KlartextInterpreter::pathFlipsOrientation(Plane plane) const {
    if (pathInTiltedPlane()) return m_frame.flipsOrientationInTiltedPlane(plane);
    return m_frame.flipsOrientation(plane);
}

bool KlartextInterpreter::pathKeepsArcs(Plane plane) const {
    // TCPM works in the tilted plane's coordinates too: the tilt itself does not turn an arc of
    // the plane out of it (a thread mill's helix after PLANE SPATIAL SPB+30 and M128).
    if (pathInTiltedPlane()) return m_frame.keepsArcsInTiltedPlane(plane);
    return m_frame.keepsArcs(plane);
}

Pose KlartextInterpreter::programOfPath(const Pose& path) const {
    if (pathInTiltedPlane()) return m_frame.fromTiltedPlane(path);
    return m_frame.toProgram(path);
}

machine::RotaryAngles KlartextInterpreter::tableAnglesOf(const Pose& pose) const {
    machine::RotaryAngles a;
    auto angle = [&](char letter) {
        const Axis axis = *axisFromLetter(letter);
        return pose[axis] + m_settings.presetInMachine[axis];
    };
    a.primaryDeg = angle(m_kinematics->primary());
    if (m_kinematics->twoAxes()) a.secondaryDeg = angle(m_kinematics->secondary());
    return a;
}

Pose KlartextInterpreter::axesOfTip(const Pose& tip) const {
    Pose axes = tip;
    const Vec3 preset = m_settings.presetInMachine.xyz() + m_frame.preset().xyz();
    axes.setXyz(
        m_kinematics->axesOf(tip.xyz(), tableAnglesOf(tip), preset, m_tool.effectiveLength()));
    return axes;
}

Pose KlartextInterpreter::tipOf(const Pose& axes) const {
    const Vec3 preset = m_settings.presetInMachine.xyz() + m_frame.preset().xyz();
    Pose tip = axes;
    tip.setXyz(
        m_kinematics->tipOf(axes.xyz(), tableAnglesOf(axes), preset, m_tool.effectiveLength()));
    return tip;
}

std::optional<machine::RotaryAngles> KlartextInterpreter::anglesNear(const Vec3& direction,
                                                                     const Pose& near) const {
    const machine::RotaryAngles at = tableAnglesOf(near);
    const machine::RotarySolutions solutions = m_kinematics->solve(direction, at.secondaryDeg);
    std::optional<machine::RotaryAngles> best;
    double bestTurn = 0.0;
    for (int i = 0; i < solutions.count; ++i) {
        const machine::RotaryAngles& s = solutions.list[static_cast<size_t>(i)];
        // Each angle a whole turn nearer to where the axis stands.
        const machine::RotaryAngles placed{
            at.primaryDeg + std::remainder(s.primaryDeg - at.primaryDeg, 360.0),
            at.secondaryDeg + std::remainder(s.secondaryDeg - at.secondaryDeg, 360.0)};
        const double turn = std::abs(placed.primaryDeg - at.primaryDeg) +
                            std::abs(placed.secondaryDeg - at.secondaryDeg);
        if (!best || turn < bestTurn - 1e-9) {
            best = placed;
            bestTurn = turn;
        }
    }
    return best;
}

std::optional<Pose> KlartextInterpreter::moveTarget(const Coordinates& coords) {
    Pose target = targetOf(coords);
    if (!m_tcpmSpatial) return target;
    // AXIS SPAT: A, B, C are the tool's spatial angles in the working plane (turns about its X,
    // then Y, then Z, as PLANE SPATIAL); an angle not written keeps its value.
    bool written = false;
    for (int i = 0; i < 3; ++i) {
        const Axis axis = static_cast<Axis>(axisIndex(Axis::A) + i);
        const AxisWord& word = coords[axis];
        if (!word.present) continue;
        auto& angle = m_spatialDeg[static_cast<size_t>(i)];
        angle = word.incremental ? angle + word.value : word.value;
        target[axis] = m_programmed[axis];
        written = true;
    }
    if (!written) return target;
    const Vec3 inPlane = spatialRotation(m_spatialDeg[0], m_spatialDeg[1], m_spatialDeg[2]).col(2);
    const Vec3 direction =
        (m_frame.tilted() ? m_frame.tilt() : Eigen::Matrix3d::Identity()) * inPlane;
    if (!turnToolTo(direction, target)) {
        fail("tcpm",
             KERF_TR_NOOP("AXIS SPAT: the rotary axes of this machine cannot turn the tool to the "
                          "spatial angles A {1} B {2} C {3}"),
             {formatFixed(m_spatialDeg[0], 3), formatFixed(m_spatialDeg[1], 3),
              formatFixed(m_spatialDeg[2], 3)});
        return std::nullopt;
    }
    return target;
}

bool KlartextInterpreter::turnToolTo(const Vec3& direction, Pose& target) const {
    const Pose stream = m_frame.toWorkpiece(target);
    const auto angles = anglesNear(direction, stream);
    if (!angles) return false;
    // The program's angle: the machine's less the preset and the frame's offsets (shifts, turns).
    auto set = [&](char letter, double machineDeg) {
        const Axis axis = *axisFromLetter(letter);
        target[axis] += machineDeg - m_settings.presetInMachine[axis] - stream[axis];
    };
    set(m_kinematics->primary(), angles->primaryDeg);
    if (m_kinematics->twoAxes()) set(m_kinematics->secondary(), angles->secondaryDeg);
    return true;
}

Vec3 KlartextInterpreter::TcpmSpace::directionAt(const Pose& tilted) const {
    return m.m_kinematics->toolDirection(m.tableAnglesOf(frame.tiltedPlaneToWorkpiece(tilted)));
}

Pose KlartextInterpreter::TcpmSpace::along(const ContourElement& element, double t) const {
    Pose p = element.poseAt(t);
    if (!vectorPath) return p;
    // PATHCTRL VECTOR: the tool's direction turns at a steady rate in the plane of its start and
    // end directions (so its side sweeps a plane along a line); the axes follow it.
    const Vec3 from = directionAt(element.start), to = directionAt(element.end);
    const double angle = std::acos(std::clamp(from.dot(to), -1.0, 1.0));
    if (angle < 1e-9 || angle > std::numbers::pi - 1e-6) return p;  // no plane to turn in
    const Vec3 direction =
        (std::sin((1.0 - t) * angle) * from + std::sin(t * angle) * to) / std::sin(angle);
    const Pose stream = frame.tiltedPlaneToWorkpiece(p);
    const auto angles = m.anglesNear(direction, stream);
    if (!angles) return p;
    auto set = [&](char letter, double machineDeg) {
        const Axis axis = *axisFromLetter(letter);
        p[axis] += machineDeg - m.m_settings.presetInMachine[axis] - stream[axis];
    };
    set(m.m_kinematics->primary(), angles->primaryDeg);
    if (m.m_kinematics->twoAxes()) set(m.m_kinematics->secondary(), angles->secondaryDeg);
    return p;
}

double KlartextInterpreter::TcpmSpace::deviation(const Pose& passed, const Pose& meant) const {
    const double tip = (passed.xyz() - meant.xyz()).norm();
    if (!vectorPath) return tip;
    // The tool's point `reachMm` up its axis, where its side cuts.
    return tip + reachMm * (directionAt(passed) - directionAt(meant)).norm();
}

}  // namespace kerf::klartext
