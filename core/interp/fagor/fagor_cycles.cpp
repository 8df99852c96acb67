// Canned cycles G81-G89 (spec part 2 §1-§2): the block's parameters in mm with X as a radius,
// in the plane's abscissa/ordinate (G16 remaps, §1.3), expanded by core/cycles/lathe and
// submitted like programmed moves, so transformations and the output stage apply alike.
#include <cmath>

#include "core/base/translate.h"
#include "core/cycles/lathe/axial_drilling.h"
#include "core/cycles/lathe/grooving.h"
#include "core/cycles/lathe/pattern_repeat.h"
#include "core/cycles/lathe/raw_outline.h"
#include "core/cycles/lathe/section_turning.h"
#include "core/cycles/lathe/threading.h"
#include "core/interp/fagor/fagor_interpreter.h"

namespace kerf::fagor {

using cycles::lathe::LatheError;
using cycles::lathe::LathePath;
using cycles::lathe::LatheStep;

bool FagorInterpreter::executeCycle(const IsoBlock& iso) {
    const CycleWords& w = iso.cycle;
    const int g = w.g;
    m_lastCycle = g;
    const PlaneFrame& plane = m_modal.plane;
    m_at.column = program::columnOf(m_line.text, w.offset);
    // X-type values follow the diameter mode, Z-type values and radius values are lengths.
    auto point = [&](char z, char x) {
        return Vec2(axisValue(plane.abscissa, w[z].value), axisValue(plane.ordinate, w[x].value));
    };
    auto len = [&](char letter, double fallback) {
        return w.has(letter) ? length(w[letter].value) : fallback;
    };
    // The cycle's feeds (F, H) as the block's F: in mm, except G32's 1/min.
    auto feedOf = [&](char letter) {
        const double f = w.value(letter, 0.0);
        return m_modal.feed == FeedKind::InverseTime ? f : length(f);
    };
    const Vec2 call = plane.point(programmedPosition());
    LathePath path(call);
    LatheError error;
    bool ok = false;
    switch (g) {
        case 81:
        case 82:
        case 84:
        case 85: {
            cycles::lathe::TurningSection section;
            section.facing = g == 82 || g == 85;
            section.start = point('Z', 'X');
            cycles::lathe::ProfileElement element;
            element.end = point('R', 'Q');
            if (g == 84 || g == 85) {
                // I (radius) and K: the centre relative to A, like I, K of G02/G03.
                const Vec2 centre =
                    section.start + Vec2(length(w['K'].value), length(w['I'].value));
                element.centre = centre;
                element.ccw = cycles::lathe::shortArcIsCcw(section.start, element.end, centre);
                section.radiusTolerance = m_settings.circleToleranceMm;
                if (!arcFitsTheNose(call, section.start, element)) return false;
            }
            section.elements.push_back(element);
            section.maxStep = length(w['C'].value);
            if (w.has('D')) section.retract = length(w['D'].value);
            section.allowanceX = len('L', 0.0);
            section.allowanceZ = len('M', 0.0);
            section.finalRoughingFeed = feedOf('F');
            section.finishingFeed = feedOf('H');
            ok = cycles::lathe::expandTurningSection(section, call, path, error);
            break;
        }
        case 68:
        case 69: {
            // Stock removal (G68 passes along Z, G69 along X) over the profile S..E.
            cycles::lathe::TurningSection section;
            section.facing = g == 69;
            section.channels = true;
            section.plungeFeed = w.value('K', 0.0);
            section.start = point('Z', 'X');
            RawProfile raw;
            if (!readProfile(w, section.start, section.elements, raw)) return false;
            section.raw = {raw.start, std::move(raw.elements)};
            m_at.line = m_line.firstLine;
            checkToolReach(g, call, section.start, section.elements);
            section.maxStep = length(w['C'].value);
            if (w.has('D')) section.retract = length(w['D'].value);
            // The sign of L and M chooses the finishing pass's corners; M defaults to L.
            section.allowanceX = std::fabs(len('L', 0.0));
            section.allowanceZ = w.has('M') ? std::fabs(len('M', 0.0)) : section.allowanceX;
            section.finalRoughingFeed = feedOf('F');
            section.finishingFeed = feedOf('H');
            section.radiusTolerance = m_settings.circleToleranceMm;
            ok = cycles::lathe::expandTurningSection(section, call, path, error);
            if (ok) emitRawStockBlank(section.raw, call, section.start, !section.facing);
            break;
        }
        case 66: {
            cycles::lathe::PatternRepeat cycle;
            cycle.start = point('Z', 'X');
            RawProfile raw;
            if (!readProfile(w, cycle.start, cycle.elements, raw)) return false;
            cycle.raw = {raw.start, std::move(raw.elements)};
            m_at.line = m_line.firstLine;
            checkToolReach(g, call, cycle.start, cycle.elements);
            // A absent: the stock is measured along the tool's longer length (X on a tie).
            const ToolOffset& tool = m_tool.data;
            cycle.stockAlongZ =
                w.has('A') ? w['A'].value == 1.0 : std::fabs(tool.z) > std::fabs(tool.x);
            cycle.stock = length(w['I'].value);
            cycle.step = length(w['C'].value);
            // The sign of L and M chooses the finishing pass's corners; M defaults to L.
            cycle.allowanceX = std::fabs(len('L', 0.0));
            if (w.has('M')) cycle.allowanceZ = std::fabs(length(w['M'].value));
            cycle.finishingFeed = feedOf('H');
            cycle.radiusTolerance = m_settings.circleToleranceMm;
            ok = cycles::lathe::expandPatternRepeat(cycle, call, path, error);
            if (ok) emitRawStockBlank(cycle.raw, call, cycle.start, !cycle.stockAlongZ);
            break;
        }
        case 83: {
            cycles::lathe::AxialHole hole;
            hole.start = point('Z', 'X');
            hole.depth = length(w['I'].value);
            hole.peck = length(w['B'].value);
            hole.safety = len('D', 0.0);
            hole.dwellSeconds = w.value('K', 0.0) / 100.0;
            hole.retract = len('H', 0.0);
            hole.reapproach = len('C', 1.0);
            hole.minimumPeck = len('L', 0.0);
            const double r = w.value('R', 0.0);
            hole.factor = r == 0.0 ? 1.0 : r;
            hole.tappingType = static_cast<int>(r);
            if (r != std::floor(r)) hole.tappingType = -1;
            // Rigid tapping: the thread's lead is the feed per revolution.
            const double rpm = m_spindle.rpm;
            const double feed = m_feed;  // mm already
            hole.tappingLeadMm = m_modal.feed == FeedKind::PerRevolution ? feed
                                 : rpm > 0.0                             ? feed / rpm
                                                                         : 0.0;
            ok = cycles::lathe::expandAxialHole(hole, path, error);
            break;
        }
        case 86:
        case 87: {
            cycles::lathe::Thread thread;
            thread.face = g == 87;
            thread.start = point('Z', 'X');
            thread.end = point('R', 'Q');
            if (w.has('K')) {
                thread.measuredAt = thread.face ? axisValue(plane.ordinate, w['K'].value)
                                                : axisValue(plane.abscissa, w['K'].value);
            }
            thread.depth = length(w['I'].value);
            thread.infeed = length(w['B'].value);
            thread.minimumIncrement = len('E', 0.0);
            thread.safety = len('D', 0.0);
            thread.finishing = len('L', 0.0);
            thread.pitch = length(w['C'].value);
            thread.exit = len('J', 0.0);
            thread.infeedAngleDeg = w.value('A', 30.0);
            thread.spindleAngleDeg = w.value('W', 0.0);
            const double starts = w.value('V', 1.0);
            if (starts < 0.0 || starts != std::floor(starts) || starts > 360.0) {
                m_at.column = program::columnOf(m_line.text, w['V'].offset);
                fail("cycle-parameter", KERF_TR_NOOP("{1} must be a whole number from {2} to {3}"),
                     {"V", "0", "360"});
                return false;
            }
            thread.starts = static_cast<int>(starts);
            thread.pitchChange = len('M', 0.0);
            ok = cycles::lathe::expandThread(thread, call, path, error);
            break;
        }
        case 88:
        case 89: {
            cycles::lathe::Groove groove;
            groove.alongZ = g == 89;
            groove.start = point('Z', 'X');
            groove.end = point('R', 'Q');
            groove.maxStep = len('C', 0.0);
            groove.safety = len('D', 0.0);
            groove.dwellSeconds = w.value('K', 0.0) / 100.0;
            groove.toolWidth =
                m_toolTable && m_tool.tool > 0 ? m_toolTable->get(m_tool.tool).noseWidth : 0.0;
            groove.locationCode = m_tool.data.location;
            ok = cycles::lathe::expandGroove(groove, call, path, error);
            break;
        }
        default:
            return true;
    }
    if (!ok) {
        const size_t offset =
            error.letter != 0 && w.has(error.letter) ? w[error.letter].offset : w.offset;
        m_at.column = program::columnOf(m_line.text, offset);
        fail(error.code.c_str(), error.messageTemplate.c_str(), error.args);
        return false;
    }
    m_parameters.clobberForCycle();
    // G81, G82, G84, G85 keep the radius compensation programmed before them; the others
    // cancel it.
    if (g == 83 || g >= 86) m_modal.side = interp::CompSide::None;
    if (!runCycleSteps(path.steps(), iso)) return false;
    if (g == 66 || g == 68 || g == 69) {
        // Afterwards G00 and G40 (§1.4) and the last feed used: H, else F.
        m_modal.motion = 0;
        m_modal.side = interp::CompSide::None;
        for (const char letter : {'H', 'F'}) {
            if (w.value(letter, 0.0) > 0.0) {
                m_feed = feedOf(letter);
                m_feedSet = true;
                break;
            }
        }
    }
    m_lastTangent.reset();
    m_thread.previousWasThread = false;
    return true;
}

void FagorInterpreter::emitRawStockBlank(const cycles::lathe::RawStock& raw, const Vec2& call,
                                         const Vec2& start, bool stepsAlongX) {
    const PlaneFrame& plane = m_modal.plane;
    // Turned about Z: only in the lathe's own plane (abscissa Z, ordinate X).
    if (raw.elements.empty() || plane.abscissa != Axis::Z || plane.ordinate != Axis::X) return;
    constexpr double kChordErrorMm = 0.002;
    canon::StockRevolved blank;
    const Pose at = programmedPosition();
    auto stream = [&](const Vec2& p) {
        Pose pose = at;
        plane.setPoint(pose, p);
        return toStream(pose).xyz();
    };
    for (const Vec2& p : cycles::lathe::rawOutlinePoints(raw, kChordErrorMm))
        blank.outline.push_back(stream(p));
    // The material lies beyond the profile, away from the call point, along the passes' steps.
    const int axis = stepsAlongX ? 1 : 0;
    Vec2 away(0.0, 0.0);
    away[axis] = call[axis] > start[axis] ? -1.0 : 1.0;
    blank.materialSide = (stream(start + away) - stream(start)).normalized();
    emit(canon::StockDefinition{std::move(blank)});
}

bool FagorInterpreter::runCycleSteps(const std::vector<LatheStep>& steps, const IsoBlock& iso) {
    const PlaneFrame& plane = m_modal.plane;
    const canon::SpindleDirection atCall = m_spindle.direction;
    for (const LatheStep& step : steps) {
        switch (step.kind) {
            case LatheStep::Kind::Rapid:
            case LatheStep::Kind::Feed:
            case LatheStep::Kind::Thread: {
                const Pose from = programmedPosition();
                Pose to = from;
                plane.setPoint(to, step.to);
                OwnMoveData own;
                own.feed = step.feed;
                own.thread.lead = step.lead;
                own.thread.leadChange = step.leadChange;
                own.thread.startAngle = step.angleDeg;
                const MoveKind kind = step.kind == LatheStep::Kind::Rapid  ? MoveKind::Rapid
                                      : step.kind == LatheStep::Kind::Feed ? MoveKind::Feed
                                                                           : MoveKind::Thread;
                if (!submit(ContourElement::line(plane.plane, from, to), kind, iso, &own)) {
                    return false;
                }
                break;
            }
            case LatheStep::Kind::FeedArc: {
                const Pose from = programmedPosition();
                Pose to = from;
                plane.setPoint(to, step.to);
                const double sweep = arcSweep(plane.point(from), step.to, step.centre, step.ccw);
                const ContourElement element =
                    ContourElement::arc(plane.plane, from, to, plane.toGeometry(step.centre),
                                        plane.toGeometrySweep(sweep));
                OwnMoveData own;
                own.feed = step.feed;
                if (!submit(element, MoveKind::Feed, iso, &own)) return false;
                break;
            }
            case LatheStep::Kind::Dwell:
                emit(canon::Dwell{step.seconds});
                break;
            case LatheStep::Kind::SpindleStop:
                m_spindle.direction = canon::SpindleDirection::Stopped;
                emitSpindle();
                break;
            case LatheStep::Kind::SpindleReverse:
                m_spindle.direction = atCall == canon::SpindleDirection::Clockwise
                                          ? canon::SpindleDirection::CounterClockwise
                                          : canon::SpindleDirection::Clockwise;
                emitSpindle();
                break;
            case LatheStep::Kind::SpindleRestore:
                m_spindle.direction = atCall;
                emitSpindle();
                break;
            case LatheStep::Kind::Orient:
                emit(canon::SpindleOrient{step.angleDeg});
                break;
        }
    }
    return true;
}

}  // namespace kerf::fagor
