// The tool/profile analysis of G66/G68/G69 (spec part 2 §1.6): before machining, the profile is
// checked against the active tool's insert (NOSEA and CUTA of the tool table, the nose radius R
// of the tool offset). A valley the insert cannot reach gets a message at the start of the cycle
// and a warning at the cycle's G in the check, and the cycle machines the closest profile the
// insert reaches instead. G84/G85 refuse a hollow arc tighter than the nose.
#include <cmath>
#include <cstdio>
#include <string>

#include "core/base/translate.h"
#include "core/cycles/lathe/reachable_profile.h"
#include "core/cycles/lathe/tool_reach.h"
#include "core/geometry/arc_math.h"
#include "core/interp/fagor/fagor_interpreter.h"

namespace kerf::fagor {

namespace {

std::string degreesText(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

}  // namespace

void FagorInterpreter::checkToolReach(int g, const Vec2& call, const Vec2& start,
                                      std::vector<cycles::lathe::ProfileElement>& profile) {
    if (m_tool.tool <= 0 || profile.empty()) return;
    // Without a tool table only the nose radius of the offset is known.
    const ToolEntry tool = m_toolTable ? m_toolTable->get(m_tool.tool) : ToolEntry{};
    const cycles::lathe::InsertGeometry insert{tool.cuttingAngle, tool.noseAngle,
                                               m_tool.data.radius};
    // G68 feeds along Z, G69 along X, G66 along the profile's longer extent; the material lies
    // on the side away from the call point.
    const Vec2 extent = profile.back().end - start;
    const bool alongZ = g == 68 || (g == 66 && std::fabs(extent.x()) >= std::fabs(extent.y()));
    const auto sign = [](double v) { return v < 0.0 ? -1.0 : 1.0; };
    const Vec2 feed = alongZ ? Vec2(sign(extent.x()), 0.0) : Vec2(0.0, sign(extent.y()));
    const Vec2 outward =
        alongZ ? Vec2(0.0, sign(call.y() - start.y())) : Vec2(sign(call.x() - start.x()), 0.0);
    const auto unreachable =
        cycles::lathe::firstUnreachableElement(start, profile, feed, outward, insert);
    if (!unreachable) return;
    using Kind = cycles::lathe::UnreachableElement::Kind;
    const char* message =
        unreachable->kind == Kind::WallTooSteep
            ? KERF_TR_NOOP(
                  "tool T{1} cannot reach the profile at line {2}: it rises {3}° from the "
                  "passes and the cutting angle CUTA allows {4}°")
        : unreachable->kind == Kind::DescentTooSteep
            ? KERF_TR_NOOP(
                  "tool T{1} cannot reach the profile at line {2}: it descends {3}° into "
                  "the material and CUTA + NOSEA leave {4}°")
            : KERF_TR_NOOP(
                  "tool T{1} cannot reach the profile at line {2}: the arc's radius {3} "
                  "is smaller than the nose radius {4}");
    const std::vector<std::string> args{
        std::to_string(m_tool.tool), std::to_string(profile[unreachable->element].line),
        degreesText(unreachable->needed), degreesText(unreachable->allowed)};
    warn("tool-geometry", message, args);
    emit(canon::Message{canon::MessageKind::Info, substituteArgs(message, args)});
    profile = cycles::lathe::reachableProfile(start, profile, feed, outward, insert);
}

bool FagorInterpreter::arcFitsTheNose(const Vec2& call, const Vec2& start,
                                      const cycles::lathe::ProfileElement& arc) {
    // The section is this one arc: with a nose rounder than a hollow arc there is no
    // neighbouring element to leave the rest against, so G84/G85 refuse it (G66/G68/G69 machine
    // the profile the nose reaches instead). Hollow: the arc bulges away from the call point.
    const double radius = (start - *arc.centre).norm();
    const double nose = m_tool.data.radius;
    if (nose <= radius + 1e-9) return true;
    const Vec2 chord = arc.end - start;
    const double sweep = arcSweep(start, arc.end, *arc.centre, arc.ccw);
    const Vec2 from = start - *arc.centre;
    const Vec2 middle =
        *arc.centre + Vec2(std::cos(sweep / 2.0) * from.x() - std::sin(sweep / 2.0) * from.y(),
                           std::sin(sweep / 2.0) * from.x() + std::cos(sweep / 2.0) * from.y());
    if (cross2(chord, middle - start) * cross2(chord, call - start) >= 0.0) return true;
    fail("tool-geometry",
         KERF_TR_NOOP("the arc's radius {1} is smaller than the tool nose radius {2}: the nose "
                      "cannot follow it"),
         {degreesText(radius), degreesText(nose)});
    return false;
}

}  // namespace kerf::fagor
