// Tool centre point management (M128/M129, FUNCTION TCPM): programmed positions are tool-tip
// positions on the part while the rotary tables turn. The canonical stream holds the machine's
// linear axes, so a move whose tables turn is split into straight pieces of the axes, as many as
// keep the tip within half the path tolerance of the programmed line (the planner blends the
// pieces within the other half).
#include <cmath>

#include "core/base/translate.h"
#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::klartext {

namespace {

// More pieces than this per block: the move turns too far for the tolerance (an error).
constexpr int kMaxTcpmPieces = 1 << 16;

Pose lerp(const Pose& a, const Pose& b, double t) {
    Pose p;
    for (size_t i = 0; i < p.values.size(); ++i)
        p.values[i] = a.values[i] + t * (b.values[i] - a.values[i]);
    return p;
}

}  // namespace

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
    // The stream stays where the axes are; the program now counts in tip positions on the part.
    const Pose at = activePath().toolPosition();
    m_tcpm = on;
    m_programmed = m_frame.toProgram(on ? tipOf(at) : at);
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

void KlartextInterpreter::moveWithTcpm(const Pose& programTarget, bool rapid, double feed) {
    if (m_comp == CompWord::Left || m_comp == CompWord::Right) {
        fail("tcpm", KERF_TR_NOOP("radius compensation RL/RR with TCPM is not supported yet"));
        return;
    }
    const Pose from = m_frame.toWorkpiece(m_programmed);
    const Pose to = m_frame.toWorkpiece(programTarget);
    const double tolerance = 0.5 * std::max(m_settings.machine->pathToleranceMm, 0.001);
    // Doubles the pieces until the tip between the axes' piece ends stays on the line.
    int pieces = 1;
    for (;;) {
        double worst = 0.0;
        Pose start = axesOfTip(from);
        for (int i = 0; i < pieces && worst <= tolerance; ++i) {
            const Pose end = axesOfTip(lerp(from, to, double(i + 1) / pieces));
            const Vec3 tip = tipOf(lerp(start, end, 0.5)).xyz();
            const Vec3 onLine = lerp(from, to, (i + 0.5) / pieces).xyz();
            worst = std::max(worst, (tip - onLine).norm());
            start = end;
        }
        if (worst <= tolerance) break;
        if (pieces >= kMaxTcpmPieces) {
            fail("tcpm", KERF_TR_NOOP("TCPM: the rotary axes turn too far in this block to keep "
                                      "the tool tip on the line; split the block"));
            return;
        }
        pieces *= 2;
    }
    // F is the feed of the tip: each piece of the axes gets the feed that keeps it.
    const double tipPiece = (to.xyz() - from.xyz()).norm() / pieces;
    Pose start = axesOfTip(from);
    for (int i = 0; i < pieces; ++i) {
        const Pose end = axesOfTip(lerp(from, to, double(i + 1) / pieces));
        const double axesPiece = (end.xyz() - start.xyz()).norm();
        const double pieceFeed = tipPiece > 1e-9 ? feed * axesPiece / tipPiece : feed;
        emitStreamMove(start, end, rapid, pieceFeed);
        start = end;
    }
    m_programmed = programTarget;
}

}  // namespace kerf::klartext
