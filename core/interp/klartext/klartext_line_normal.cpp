// LN: a straight line with 3D tool compensation, as CAM systems write surface points for the TNC.
// The tool's radius oversize (DR of the tool table and of the TOOL CALL) moves the programmed
// point along the surface normal NX NY NZ, so a tool larger or smaller than the one the CAM system
// computed with stays on the surface; its length oversize DL acts along the tool, as in every
// block. TX TY TZ turn the tool to that direction on the part while TCPM keeps the tip.
#include "core/base/translate.h"
#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::klartext {

void KlartextInterpreter::executeLineNormal(const LineNormalBlock& block) {
    bool rapid = false;
    double feed = 0.0;
    m_currentM = block.words.m;
    if (!resolveFeed(block.words.feed, rapid, feed)) return;
    const CompWord comp = block.words.comp != CompWord::None ? block.words.comp : m_comp;
    if (comp == CompWord::Left || comp == CompWord::Right) {
        fail("ln", KERF_TR_NOOP("LN compensates along the surface normal: switch the radius "
                                "compensation off (R0) first"));
        return;
    }
    if (block.normal.norm() < 1e-9 || (block.tool && block.tool->norm() < 1e-9)) {
        fail("ln", KERF_TR_NOOP("LN: a vector NX NY NZ or TX TY TZ has no length"));
        return;
    }
    if (block.tool && !m_tcpm) {
        fail("ln", KERF_TR_NOOP("LN: the tool direction TX TY TZ needs M128 or FUNCTION TCPM"));
        return;
    }
    m_comp = comp;
    applyMFunctions(block.words.m, true);
    if (m_status == interp::RunStatus::Failed) return;
    auto moved = moveTarget(block.coords);
    if (!moved) return;
    Pose target = *moved;
    const double oversize = m_tool.tableDr + m_tool.callDr;
    target.setXyz(target.xyz() + oversize * block.normal.normalized());
    if (block.tool) {
        // The direction on the part: through the frame's turns (tilt, rotation, mirror).
        Pose ahead = target;
        ahead.setXyz(target.xyz() + block.tool->normalized());
        const Vec3 direction =
            (m_frame.toWorkpiece(ahead).xyz() - m_frame.toWorkpiece(target).xyz()).normalized();
        if (!turnToolTo(direction, target)) {
            fail("ln", KERF_TR_NOOP("LN: the rotary axes of this machine cannot turn the tool "
                                    "along TX TY TZ"));
            return;
        }
    }
    if (!rotaryWithinLimits(target)) return;
    submitMove(ContourElement::line(workingPlane(), m_programmed, target), rapid, feed,
               block.words);
    applyMFunctions(block.words.m, false);
    afterPositioning(block.words.m);
}

}  // namespace kerf::klartext
