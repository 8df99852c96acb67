// LN: a straight line with 3D tool compensation, as CAM systems write surface points for the TNC.
// X Y Z is where the tip of the CAM system's cutter goes (radius R, corner radius R2 of the tool
// table); the oversizes DR and DR2 (tool table + TOOL CALL) move the tip so that the actual
// cutter touches the surface where that one did (cutter_oversize.h). Positive oversizes stop the
// run unless M107 permits them. Its length oversize DL acts along the tool, as in every block.
// Under TCPM the tool turns to TX TY TZ, without them to the surface normal, while the tip stays.
#include "core/base/fixed_format.h"
#include "core/base/translate.h"
#include "core/interp/klartext/cutter_oversize.h"
#include "core/interp/klartext/klartext_interpreter.h"

namespace kerf::klartext {

namespace {

constexpr AxisMask kRotaryMask = axisBit(Axis::A) | axisBit(Axis::B) | axisBit(Axis::C);

}  // namespace

bool KlartextInterpreter::cutterFitsLineNormal() {
    const double dr = m_tool.tableDr + m_tool.callDr;
    const double dr2 = m_tool.tableDr2 + m_tool.callDr2;
    if (!m_permitOversize && (dr > 1e-9 || dr2 > 1e-9)) {
        fail("ln",
             KERF_TR_NOOP("LN: the tool is larger than the CAM system's (DR {1}, DR2 {2} from the "
                          "tool table and TOOL CALL): program M107 to permit positive oversizes"),
             {formatFixed(dr / lengthScale(), 4), formatFixed(dr2 / lengthScale(), 4)});
        return false;
    }
    const double radius = m_tool.effectiveRadius();
    const double corner = m_tool.radius2 + dr2;
    if (corner < -1e-9 || corner > radius + 1e-9) {
        fail("ln",
             KERF_TR_NOOP("LN: the corner radius R2+DR2 {1} must lie between 0 (end mill) and the "
                          "radius R+DR {2} (ball cutter)"),
             {formatFixed(corner / lengthScale(), 4), formatFixed(radius / lengthScale(), 4)});
        return false;
    }
    return true;
}

Vec3 KlartextInterpreter::programDirectionOf(const Vec3& onPart, const Pose& at) const {
    // The frame's turns (tilt, rotation, mirror) back: the program's axes as they lie on the part.
    const Vec3 origin = m_frame.toWorkpiece(at).xyz();
    Vec3 program = Vec3::Zero();
    for (int i = 0; i < 3; ++i) {
        Pose ahead = at;
        ahead.values[static_cast<size_t>(i)] += 1.0;
        program[i] = (m_frame.toWorkpiece(ahead).xyz() - origin).dot(onPart);
    }
    return program.normalized();
}

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
    m_comp = comp;
    applyMFunctions(block.words.m, true);  // M107 acts from this block on
    if (m_status == interp::RunStatus::Failed || !cutterFitsLineNormal()) return;
    auto moved = moveTarget(block.coords);
    if (!moved) return;
    Pose target = *moved;
    const Vec3 normal = block.normal.normalized();
    // The tool's direction in the program's coordinates. Without TCPM the tables stand and the
    // TNC ignores TX TY TZ: the tool is along the tool axis. With TCPM it turns to TX TY TZ, or
    // stands perpendicular to the surface, unless the block positions the rotary axes itself.
    Vec3 tool = Vec3::Zero();
    tool[axisIndex(m_toolAxis)] = 1.0;
    if (m_tcpm) {
        const bool axesGiven = (block.coords.present & kRotaryMask) != 0 && !block.tool;
        tool = block.tool ? Vec3(block.tool->normalized()) : normal;
        if (axesGiven) {
            tool = programDirectionOf(
                m_kinematics->toolDirection(tableAnglesOf(m_frame.toWorkpiece(target))), target);
        } else {
            // The direction on the part: through the frame's turns (tilt, rotation, mirror).
            Pose ahead = target;
            ahead.setXyz(target.xyz() + tool);
            const Vec3 direction =
                (m_frame.toWorkpiece(ahead).xyz() - m_frame.toWorkpiece(target).xyz()).normalized();
            if (!turnToolTo(direction, target)) {
                fail("ln", block.tool
                               ? KERF_TR_NOOP("LN: the rotary axes of this machine cannot turn the "
                                              "tool along TX TY TZ")
                               : KERF_TR_NOOP("LN: the rotary axes of this machine cannot turn the "
                                              "tool along the surface normal NX NY NZ"));
                return;
            }
        }
    }
    const double dr = m_tool.tableDr + m_tool.callDr;
    const double dr2 = m_tool.tableDr2 + m_tool.callDr2;
    target.setXyz(target.xyz() + cutterOversizeOffset(normal, tool, dr, dr2));
    if (!rotaryWithinLimits(target)) return;
    submitMove(ContourElement::line(workingPlane(), m_programmed, target), rapid, feed,
               block.words);
    applyMFunctions(block.words.m, false);
    afterPositioning(block.words.m);
}

}  // namespace kerf::klartext
