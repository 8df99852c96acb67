// Tool centre point management (M128/M129, FUNCTION TCPM): programmed positions are tool-tip
// positions on the part while the rotary tables turn. The canonical stream holds the machine's
// linear axes, so while TCPM is on the path (roundings, radius compensation, lines and arcs)
// works on the part and leaves as straight pieces of the axes, as many as keep the tip within
// half the path tolerance (the planner blends the pieces within the other half). The same
// mechanism lets a swivel head's oblique working plane run arcs and radius compensation.
#include <algorithm>

#include "core/base/translate.h"
#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::klartext {

void KlartextInterpreter::switchTcpm(bool on) {
    if (!checkPathError(activePath().flush())) return;
    if (on && !m_kinematics) {
        fail("tcpm", KERF_TR_NOOP("TCPM needs the rotary axes described in the machine file "
                                  "([kinematics], e.g. --machine mill5)"));
        return;
    }
    if (on && m_tilt.active) {
        fail("not-supported",
             KERF_TR_NOOP("TCPM in a tilted working plane is not supported yet: PLANE RESET "
                          "first"));
        return;
    }
    m_tcpm = on;
    // The axes stay where they are; the program now counts in tip positions on the part.
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
    const double tolerance =
        0.5 * std::max(m_settings.machine ? m_settings.machine->pathToleranceMm : 0.0, 0.001);
    m_path.setSpace(space, tolerance);
    m_path.resetToMachine(at);
}

Pose KlartextInterpreter::pathOfProgram(const Pose& program) const {
    if (activePath().space() == &m_tiltedPlaneSpace) return m_frame.toTiltedPlane(program);
    return m_frame.toWorkpiece(program);
}

bool KlartextInterpreter::pathFlipsOrientation(Plane plane) const {
    if (activePath().space() == &m_tiltedPlaneSpace)
        return m_frame.flipsOrientationInTiltedPlane(plane);
    return m_frame.flipsOrientation(plane);
}

bool KlartextInterpreter::pathKeepsArcs(Plane plane) const {
    if (activePath().space() == &m_tiltedPlaneSpace) return m_frame.keepsArcsInTiltedPlane(plane);
    return m_frame.keepsArcs(plane);
}

Pose KlartextInterpreter::programOfPath(const Pose& path) const {
    if (activePath().space() == &m_tiltedPlaneSpace) return m_frame.fromTiltedPlane(path);
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

}  // namespace kerf::klartext
