#include "motion/planner/planner.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

#include "core/base/fixed_format.h"
#include "core/canon/value_limits.h"
#include "core/geometry/arc_math.h"
#include "core/geometry/plane.h"
#include "motion/planner/corner_blend.h"
#include "motion/planner/share_ladder.h"
#include "motion/planner/soft_limits.h"
#include "motion/planner/velocity_limits.h"

namespace kerf::motion {

namespace {

constexpr double kMaxBlendAngle = 175.0 * kPi / 180.0;
// Polyline smoothing: segments up to this length join a run, and a vertex turning more than
// this stays a corner (a real corner of the part, not a point of a curve).
constexpr double kMaxSmoothSegmentMm = 1.0;
constexpr double kMaxSmoothTurn = 10.0 * kPi / 180.0;
// Shorter runs are not worth a fit: their corners are blended as usual.
constexpr size_t kMinRunSegments = 4;
// Turns up to this much per segment still continue a run when the segments are long enough for
// the turn to be a curve of at least kMinSmoothRadiusMm (the crest of a sine as 0.5 mm lines
// turns 11.2 deg, a radius of 2.5 mm), not a kink of short segments.
constexpr double kMaxSmoothCurveTurn = 15.0 * kPi / 180.0;
constexpr double kMinSmoothRadiusMm = 2.0;

// Deviation a corner blend may take next to a fitted curve that deviates `fitted`: half the
// tolerance less the fit (the servo filter keeps the other half), but at least a quarter of
// what the fit leaves, so that a curve fitted beyond half the tolerance (a single segment,
// PolylineSmoother::kLooseFitFactor) still blends instead of stopping.
double blendDeviation(double tolerance, double fitted) {
    return std::max(tolerance / 2.0 - fitted, (tolerance - fitted) / 4.0);
}
// Beyond this distance from the last stop no share ladder can reach (shareLadder's stages).
constexpr double kFarFromStop = 100.0;
// Shorter curves (the blends of a polyline's corners) keep one share: stages on them would only
// add binding points between them and the lines.
constexpr double kMinLadderElementMm = 0.1;

AxisVector toAxes(const Pose& pose) {
    return pose.values;
}

bool movesOnlyXyz(const PathGeometry& g) {
    for (size_t i = 3; i < g.rate.size(); ++i) {
        if (std::fabs(g.rate[i]) > 1e-12) return false;
    }
    return true;
}

std::string blockName(const SourceLocation& source) {
    if (source.blockNumber >= 0) return std::to_string(source.blockNumber);
    return "line " + std::to_string(source.line);
}

Diagnostic makeDiagnostic(const SourceLocation& source, std::string code, std::string text,
                          std::vector<std::string> args) {
    Diagnostic d;
    d.severity = Severity::Error;
    d.code = std::move(code);
    d.messageTemplate = std::move(text);
    d.args = std::move(args);
    d.line = source.line;
    d.column = source.column;
    return d;
}

std::string mm(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3f", value);
    return buffer;
}

}  // namespace

Planner::Planner(const MachineModel& model, PlannerRole role)
    : m_model(model), m_role(role), m_lookahead(model), m_tolerance(model.toleranceMm) {}

void Planner::setPosition(const AxisVector& tip) {
    m_position = tip;
    m_needsPosition = false;
}

void Planner::reset(const AxisVector& tip) {
    m_lookahead.clear();
    m_pending.reset();
    m_short.reset();
    m_run.clear();
    m_sinceStop = 0.0;
    m_sinceBlend = 0.0;
    m_blendVelocity = kNoSlowPoint;
    m_synchronised = false;
    m_refused = false;
    m_joinedGroup = 0;  // a reset ends ESBLK (spec part 2 §6.3)
    setPosition(tip);
}

void Planner::setSpindle(canon::SpindleDirection direction, double rpm) {
    m_spindleDirection = direction;
    m_spindleRpm = rpm;
}

double Planner::pendingLength() const {
    double pending = m_pending ? m_pending->geometry.length - m_pending->trimStart : 0.0;
    if (m_short) pending += m_short->geometry.length;
    for (const Move& move : m_run)
        pending += move.geometry.length;
    return m_lookahead.pendingLength() + pending;
}

std::optional<MotionItem> Planner::next() {
    MotionItem item;
    if (m_lookahead.pop(item)) return item;
    return std::nullopt;
}

void Planner::flush() {
    exactStop();
    m_lookahead.close();
}

void Planner::refuse(Diagnostic diagnostic) {
    m_diagnostics.push_back(std::move(diagnostic));
    m_refused = true;
    flush();
}

bool Planner::acceptGeometry(const PathGeometry& geometry, const SourceLocation& source) {
    auto violation = checkSoftLimits(m_model, geometry, m_toolLength);
    if (!violation) return true;
    std::string axis(1, axisLetter(static_cast<Axis>(violation->axis)));
    if (violation->missingAxis) {
        refuse(makeDiagnostic(source, "motion.missing-axis",
                              KERF_TR_NOOP("Block {1}: the machine has no axis {2}."),
                              {blockName(source), axis}));
    } else {
        refuse(makeDiagnostic(
            source, "motion.soft-limit",
            KERF_TR_NOOP("Block {1}: the move would take axis {2} to {3} (machine coordinates), "
                         "beyond its soft limit {4}; the program is not run past this block."),
            {blockName(source), axis, mm(violation->reached), mm(violation->limit)}));
    }
    return false;
}

std::optional<Planner::Move> Planner::feedMove(const AxisVector& target, double feed,
                                               const SourceLocation& source) {
    Move move;
    move.geometry = makeLine(m_position, target);
    move.feedMove = true;
    if (m_feedMode == canon::FeedMode::PerRevolution) {
        if (m_spindleRpm <= 0.0 || m_spindleDirection == canon::SpindleDirection::Stopped) {
            refuse(makeDiagnostic(source, "motion.feed-per-rev-spindle-stopped",
                                  KERF_TR_NOOP("Block {1}: feed per revolution with the spindle "
                                               "stopped."),
                                  {blockName(source)}));
            return std::nullopt;
        }
        move.feedKind = FeedKind::PerRevolution;
        move.feed = feed;
    } else {
        move.feedKind = FeedKind::PerMinute;
        move.feed = std::min(feed / 60.0, m_model.maxFeed);
    }
    if (move.feed <= 0.0) {
        refuse(makeDiagnostic(source, "motion.no-feed",
                              KERF_TR_NOOP("Block {1}: feed move without a feed rate."),
                              {blockName(source)}));
        return std::nullopt;
    }
    return move;
}

bool Planner::add(const canon::Command& command) {
    if (m_refused) return false;
    const SourceLocation& source = command.location;
    const canon::CommandBody& body = command.body;
    // The interpreters refuse such a command already; geometry, limits and timing below need
    // finite numbers, so the planner does not rely on it.
    if (const auto unsafe = canon::findUnsafeValue(body)) {
        refuse(makeDiagnostic(
            source, "motion.unsafe-value",
            KERF_TR_NOOP("Block {1}: {2} = {3} is outside the range of the control; the program "
                         "is not run past this block."),
            {blockName(source), unsafe->quantity, formatShort(unsafe->value)}));
        return false;
    }
    if (const auto* rapid = std::get_if<canon::RapidMove>(&body)) {
        endSynchronisation(source);
        Move move;
        move.geometry = makeLine(m_position, toAxes(rapid->target));
        move.feedKind = FeedKind::Rapid;
        move.feed = m_model.rapidVelocity;
        addMove(move, toAxes(rapid->target), source);
    } else if (const auto* line = std::get_if<canon::LinearMove>(&body)) {
        endSynchronisation(source);
        if (auto move = feedMove(toAxes(line->target), line->feed, source)) {
            addMove(*move, toAxes(line->target), source);
        }
    } else if (const auto* arc = std::get_if<canon::ArcMove>(&body)) {
        endSynchronisation(source);
        auto move = feedMove(toAxes(arc->target), arc->feed, source);
        if (!move) return false;
        PlaneAxes axes = planeAxes(arc->plane);
        AxisVector to = toAxes(arc->target);
        move->geometry =
            makeHelix(m_position, to, {arc->center.x(), arc->center.y(), arc->center.z()},
                      axes.first, axes.second, axes.normal, arc->sweepRad);
        // The interpreter rounds end points: close a small gap linearly, refuse a real one.
        AxisVector end = positionAt(move->geometry, move->geometry.length);
        double gap = 0.0;
        for (size_t i = 0; i < end.size(); ++i)
            gap = std::max(gap, std::fabs(to[i] - end[i]));
        if (gap > 1e-3 + 1e-6 * move->geometry.radius) {
            refuse(makeDiagnostic(source, "motion.arc-end",
                                  KERF_TR_NOOP("Block {1}: the arc's end point is {2} mm off its "
                                               "circle."),
                                  {blockName(source), mm(gap)}));
            return false;
        }
        if (move->geometry.length > 0.0) {
            for (size_t i = 0; i < end.size(); ++i) {
                move->geometry.rate[i] += (to[i] - end[i]) / move->geometry.length;
            }
        }
        addMove(*move, to, source);
    } else if (const auto* synced = std::get_if<canon::SpindleSyncedMove>(&body)) {
        if (synced->leadChangeMmPerRev != 0.0) {
            // The servo cycle locks the spindle angle to the path with one lead per element.
            refuse(makeDiagnostic(source, "motion.variable-lead",
                                  KERF_TR_NOOP("Block {1}: threads with a variable lead (G34) "
                                               "cannot be executed yet."),
                                  {blockName(source)}));
            return false;
        }
        AxisVector to = toAxes(synced->target);
        double lead = std::fabs(synced->leadMmPerRev);
        if (lead <= 0.0 || m_spindleRpm <= 0.0) {
            refuse(makeDiagnostic(source, "motion.sync-no-speed",
                                  KERF_TR_NOOP("Block {1}: spindle-synchronised move without a "
                                               "lead or a spindle speed."),
                                  {blockName(source)}));
            return false;
        }
        Move move;
        move.geometry = makeLine(m_position, to);
        if (move.geometry.length <= 0.0) return true;
        move.feedKind = FeedKind::SpindleSynced;
        move.feed = lead;
        move.feedMove = true;
        Vec3Array direction{move.geometry.rate[0], move.geometry.rate[1], move.geometry.rate[2]};
        double handed = synced->leadMmPerRev < 0.0 ? -1.0 : 1.0;
        double turning =
            m_spindleDirection == canon::SpindleDirection::CounterClockwise ? -1.0 : 1.0;
        if (!m_synchronised) {
            m_syncSign = handed * turning;
            Action start;
            start.kind = ActionKind::SyncStart;
            start.value = synced->startAngleDeg;
            emitAction(start, source);
            m_synchronised = true;
        } else {
            double along = direction[0] * m_syncDirection[0] + direction[1] * m_syncDirection[1] +
                           direction[2] * m_syncDirection[2];
            // The thread is a helix: moving back along it turns the spindle back.
            if (along < 0.0) m_syncSign = -m_syncSign;
            if (along < 1.0 - 1e-9) exactStop();
        }
        m_syncDirection = direction;
        move.spindleDegPerUnit = m_syncSign * 360.0 / lead;
        addMove(move, to, source);
    } else if (const auto* probe = std::get_if<canon::ProbeMove>(&body)) {
        endSynchronisation(source);
        auto move = feedMove(toAxes(probe->target), probe->feed, source);
        if (!move) return false;
        move->probe = true;
        exactStop();
        addMove(*move, toAxes(probe->target), source);
        exactStop();
        m_needsPosition = true;
    } else if (const auto* dwell = std::get_if<canon::Dwell>(&body)) {
        emitAction({ActionKind::Dwell, std::max(0.0, dwell->seconds), 0.0, 0.0, 0}, source);
    } else if (const auto* spindle = std::get_if<canon::SpindleControl>(&body)) {
        endSynchronisation(source);
        m_spindleDirection = spindle->direction;
        m_spindleRpm = spindle->speedRpm;
        int direction = spindle->direction == canon::SpindleDirection::Clockwise          ? 1
                        : spindle->direction == canon::SpindleDirection::CounterClockwise ? -1
                                                                                          : 0;
        emitAction({ActionKind::Spindle, spindle->speedRpm, spindle->maxRpm,
                    spindle->surfaceSpeedMPerMin, direction},
                   source);
    } else if (const auto* orient = std::get_if<canon::SpindleOrient>(&body)) {
        endSynchronisation(source);
        emitAction({ActionKind::SpindleOrient, orient->angleDeg, 0.0, 0.0, 0}, source);
    } else if (const auto* coolant = std::get_if<canon::CoolantControl>(&body)) {
        int bits = (coolant->flood ? 1 : 0) | (coolant->mist ? 2 : 0);
        emitAction({ActionKind::Coolant, 0.0, 0.0, 0.0, bits}, source);
    } else if (const auto* tool = std::get_if<canon::ToolChange>(&body)) {
        endSynchronisation(source);
        double length = tool->geometry.lengthMm;
        // The joints stay where they are: the tip moves by the change of length.
        m_position[static_cast<size_t>(m_model.toolAxis)] += m_toolLength - length;
        m_toolLength = length;
        emitAction({ActionKind::ToolChange, length, 0.0, static_cast<double>(tool->number),
                    m_model.toolAxis},
                   source);
    } else if (const auto* update = std::get_if<canon::ToolUpdate>(&body)) {
        double length = update->geometry.lengthMm;
        m_position[static_cast<size_t>(m_model.toolAxis)] += m_toolLength - length;
        m_toolLength = length;
        emitAction({ActionKind::ToolChange, length, 0.0, -1.0, m_model.toolAxis}, source);
    } else if (const auto* mode = std::get_if<canon::SetFeedMode>(&body)) {
        m_feedMode = mode->mode;
    } else if (const auto* sync = std::get_if<canon::SyncPoint>(&body)) {
        emitAction({ActionKind::SyncPoint, 0.0, 0.0, 0.0, static_cast<int32_t>(sync->reason)},
                   source);
    } else if (const auto* stop = std::get_if<canon::ProgramStop>(&body)) {
        if (stop->kind == canon::StopKind::End) endSynchronisation(source);
        emitAction({ActionKind::ProgramStop, 0.0, 0.0, 0.0, static_cast<int32_t>(stop->kind)},
                   source);
    } else if (const auto* function = std::get_if<canon::MachineFunction>(&body)) {
        emitAction({ActionKind::MachineFunction, 0.0, 0.0, 0.0, function->number}, source);
    } else if (const auto* tolerance = std::get_if<canon::PathTolerance>(&body)) {
        m_tolerance = tolerance->toleranceMm > 0.0 ? tolerance->toleranceMm : m_model.toleranceMm;
    } else if (const auto* locks = std::get_if<canon::ControlLocks>(&body)) {
        if (!locks->joinBlocks) {
            m_joinedGroup = 0;
        } else if (m_joinedGroup == 0) {
            m_joinedGroup = ++m_joinedGroups;
        }
    }
    return !m_refused;
}

void Planner::addMove(Move move, const AxisVector& target, const SourceLocation& source) {
    move.source = source;
    move.tolerance = m_tolerance;
    move.joinedGroup = m_joinedGroup;
    if (move.geometry.length <= 1e-9) {
        m_position = target;
        return;
    }
    if (!acceptGeometry(move.geometry, source)) return;
    move.index = ++m_moveCount;
    m_lastMoveGeometry = move.geometry;
    if (m_role == PlannerRole::JudgeOnly) {
        m_position = target;
        return;
    }
    move.blendable = !move.probe && move.feedKind != FeedKind::SpindleSynced &&
                     movesOnlyXyz(move.geometry) && !exactStops();
    if (smoothable(move)) {
        if (!m_run.empty() && !continuesRun(move)) endRun();
        if (m_run.empty()) {
            m_smoother.start(m_position);
            m_runFirst = 1;
        }
        m_run.push_back(move);
        m_smoother.add(target);
        releaseRun(false);
    } else {
        endRun();
        pushMove(move);
    }
    m_position = target;
}

void Planner::pushMove(Move move) {
    if (m_short && !blendAcrossShort(move)) settleShort();
    if (m_short) {
        m_short.reset();
    } else if (m_pending && worthHolding(move)) {
        m_short = move;
        return;
    } else if (m_pending) {
        cornerTo(move);
    }
    m_pending = move;
}

bool Planner::smoothable(const Move& move) const {
    return m_model.options.smoothPolylines && move.blendable && move.feedMove &&
           move.feedKind == FeedKind::PerMinute && !move.geometry.curved() &&
           move.tolerance > 0.0 && move.geometry.length <= kMaxSmoothSegmentMm;
}

bool Planner::continuesRun(const Move& move) const {
    const Move& last = m_run.back();
    if (last.feed != move.feed || last.tolerance != move.tolerance) return false;
    const double turn = cornerAngle(last.geometry, move.geometry);
    const double mean = (last.geometry.length + move.geometry.length) / 2.0;
    return turn <= kMaxSmoothTurn ||
           (turn <= kMaxSmoothCurveTurn && mean >= turn * kMinSmoothRadiusMm);
}

void Planner::releaseRun(bool final) {
    if (m_run.empty()) return;
    if (final && m_runFirst == 1 && m_run.size() < kMinRunSegments) {
        std::deque<Move> run;
        run.swap(m_run);
        for (Move& move : run)
            pushMove(move);
        return;
    }
    // Half the tolerance for the fitted curve, the other half for the servo filter (as blends).
    const double deviation = m_run.front().tolerance / 2.0;
    m_pieces.clear();
    m_smoother.take(deviation, final, m_pieces);
    for (const SmoothPiece& piece : m_pieces) {
        const Move& last = m_run[piece.lastSegment - m_runFirst];
        if (!piece.fitted) {
            Move line = last;
            if (piece.startsOffVertex) {
                // The fitted piece before ended beside the vertex (PolylineSmoother::knotAt).
                line.geometry =
                    makeLine(piece.lineStart, positionAt(last.geometry, last.geometry.length));
                line.fitDeviation = distanceTo(
                    last.geometry, {piece.lineStart[0], piece.lineStart[1], piece.lineStart[2]},
                    0.0, last.geometry.length);
            }
            pushMove(line);
            continue;
        }
        // Each arc is named after the programmed moves it replaces (the last one holding its
        // end), so that the path deviation is measured from them.
        Move arc = m_run[piece.jointSegment - m_runFirst];
        arc.firstIndex = m_run[piece.firstSegment - m_runFirst].index;
        arc.geometry = piece.arcs[0];
        arc.tangentJoin = piece.tangentToPrevious;
        arc.endsBlock = false;
        arc.trimStart = 0.0;
        arc.fitDeviation = piece.deviation;
        arc.reachStart = m_run[piece.firstSegment - m_runFirst].geometry.length / 2.0;
        pushMove(arc);
        arc = last;
        arc.firstIndex = m_run[piece.jointSegment - m_runFirst].index;
        arc.geometry = piece.arcs[1];
        arc.tangentJoin = true;
        arc.trimStart = 0.0;
        arc.fitDeviation = piece.deviation;
        arc.reachEnd = last.geometry.length / 2.0;
        pushMove(arc);
    }
    if (!m_pieces.empty()) {
        const size_t released = m_pieces.back().lastSegment + 1 - m_runFirst;
        m_run.erase(m_run.begin(), m_run.begin() + static_cast<std::ptrdiff_t>(released));
        m_runFirst += released;
    }
}

void Planner::endRun() {
    if (m_run.empty()) return;
    releaseRun(true);
    m_run.clear();
}

bool Planner::worthHolding(const Move& move) const {
    const Move& before = *m_pending;
    // Feeds per revolution are not in mm/s here: those corners stay as they are.
    bool perSecond = move.feedKind == FeedKind::PerMinute || move.feedKind == FeedKind::Rapid;
    if (!before.blendable || !move.blendable || move.geometry.curved() || !perSecond ||
        before.feedKind != move.feedKind || move.tolerance <= 0.0 || exactStops())
        return false;
    double theta = cornerAngle(before.geometry, move.geometry);
    if (theta < 1e-9 || theta > kMaxBlendAngle) return false;
    // The blend could use half of the move: radius r = l / tan(theta / 2). Worth holding when
    // that turn would be slower than the feed even at the axes' full acceleration.
    double radius = move.geometry.length / 2.0 / std::tan(theta / 2.0);
    double accel = 1e300;
    for (size_t i = 0; i < 3; ++i) {
        if (m_model.axes[i].enabled) accel = std::min(accel, m_model.axes[i].accel);
    }
    return accel * radius < move.feed * move.feed;
}

bool Planner::blendAcrossShort(Move& move) {
    const Move& before = *m_pending;
    const Move& middle = *m_short;
    if (!move.blendable || middle.feedKind != move.feedKind || exactStops() ||
        cornerAngle(before.geometry, move.geometry) > kMaxBlendAngle)
        return false;
    // A fitted curve has used part of the tolerance already.
    double fitted = std::max(before.fitDeviation, move.fitDeviation);
    double tolerance = std::min(middle.tolerance, move.tolerance) - fitted;
    if (tolerance <= 0.0) return false;
    double maxBefore = std::min(before.blendReachEnd(), before.geometry.length - before.trimStart);
    CornerBlend blend = blendAcross(before.geometry, middle.geometry, move.geometry,
                                    tolerance / 2.0, maxBefore, move.blendReachStart());
    if (blend.arcCount == 0) return false;
    // Only when it turns more gently than the corner it replaces (half the middle, see above).
    double theta = cornerAngle(before.geometry, middle.geometry);
    double replaced = std::tan(theta / 2.0) / (middle.geometry.length / 2.0);
    for (int i = 0; i < blend.arcCount; ++i) {
        if (blend.arcs[static_cast<size_t>(i)].curvature() >= replaced) return false;
    }
    // Named after the middle move, so that the path deviation is measured from the move before;
    // when it reaches into a fitted curve, after the moves that curve stands for too.
    Move corner = middle;
    if (move.firstIndex > 0) {
        corner.index = move.index;
        corner.firstIndex = middle.index;
    }
    if (before.firstIndex > 0) corner.firstIndex = before.firstIndex;
    corner.feed = std::min({before.feed, middle.feed, move.feed});
    corner.feedMove = before.feedMove || middle.feedMove || move.feedMove;
    emitBlend(corner, blend, tolerance - blend.deviation);
    move.trimStart = blend.trimAfter;
    return true;
}

void Planner::settleShort() {
    if (!m_short) return;
    Move middle = *m_short;
    m_short.reset();
    cornerTo(middle);
    m_pending = middle;
}

void Planner::cornerTo(Move& move) {
    Move& before = *m_pending;
    if (move.tangentJoin) {
        emitPending(0.0);
        return;
    }
    double theta = cornerAngle(before.geometry, move.geometry);
    bool sameRegime = before.feedKind == move.feedKind;
    if (theta < 1e-9 && sameRegime && !exactStops()) {
        emitPending(0.0);
        return;
    }
    if (!before.blendable || !move.blendable || !sameRegime || theta > kMaxBlendAngle ||
        move.tolerance <= 0.0) {
        stopAfterPending();
        return;
    }
    // Half the tolerance for the blend, the other half for the servo filter's contour error.
    // A fitted curve has used part of the tolerance already.
    double fitted = std::max(before.fitDeviation, move.fitDeviation);
    double deviation = blendDeviation(move.tolerance, fitted);
    double maxBefore = std::min(before.blendReachEnd(), before.geometry.length - before.trimStart);
    CornerBlend blend =
        blendCorner(before.geometry, move.geometry, deviation, maxBefore, move.blendReachStart());
    // A sliver left between two blends would only add curvature steps: take it into the blend.
    double rest = before.geometry.length - before.trimStart - blend.trimBefore;
    if (blend.arcCount > 0 && rest > 0.0 && rest < 0.1 * before.geometry.length) {
        CornerBlend whole =
            blendCornerFrom(before.geometry, move.geometry, deviation,
                            before.geometry.length - before.trimStart, blend.trimAfter);
        if (whole.arcCount > 0) blend = whole;
    }
    if (blend.arcCount == 0) {
        stopAfterPending();
        return;
    }
    Move corner = move;
    // A blend from a fitted curve may reach back over several of the moves it stands for.
    if (before.firstIndex > 0) corner.firstIndex = before.firstIndex;
    corner.feed = std::min(before.feed, move.feed);
    corner.feedMove = before.feedMove || move.feedMove;
    emitBlend(corner, blend, move.tolerance - fitted - blend.deviation);
    move.trimStart = blend.trimAfter;
}

void Planner::emitBlend(const Move& corner, const CornerBlend& blend, double contourBudget) {
    const double velocity = blendVelocity(blend, contourBudget);
    emitPending(blend.trimBefore, velocity);  // ends the move before the corner
    for (int i = 0; i < blend.arcCount; ++i) {
        emitElement(corner, blend.arcs[static_cast<size_t>(i)], contourBudget, false);
    }
    m_sinceBlend = 0.0;
    m_blendVelocity = velocity;
}

double Planner::blendVelocity(const CornerBlend& blend, double contourBudget) const {
    // At the lowest share, which leaves the most of each axis's acceleration to the curvature.
    constexpr double lowest = kTangentialShares[std::size(kTangentialShares) - 1];
    double velocity = kNoSlowPoint;
    for (int i = 0; i < blend.arcCount; ++i) {
        const PathGeometry& arc = blend.arcs[static_cast<size_t>(i)];
        const AxisBounds bounds = axisBounds(arc);
        velocity = std::min(
            velocity, elementVelocityCap(m_model, arc, bounds,
                                         tangentialLimits(m_model, bounds, lowest), contourBudget));
    }
    return velocity;
}

void Planner::emitPending(double trimEnd, double exitVelocity) {
    if (!m_pending) return;
    const Move& move = *m_pending;
    double end = move.geometry.length - trimEnd;
    if (end - move.trimStart > 1e-9) {
        emitElement(move, trimmed(move.geometry, move.trimStart, end),
                    move.tolerance - move.fitDeviation, move.endsBlock, exitVelocity);
    }
    m_pending.reset();
}

void Planner::emitElement(const Move& move, const PathGeometry& geometry, double contourBudget,
                          bool blockEnd, double exitVelocity) {
    std::array<ShareStage, 4> stages;
    size_t count = 0;
    if (geometry.curved() && geometry.length >= kMinLadderElementMm &&
        move.feedKind == FeedKind::PerMinute && move.blendable &&
        (std::min(m_sinceStop, m_sinceBlend) < kFarFromStop || exitVelocity < kNoSlowPoint)) {
        count = shareLadder(m_model, geometry, contourBudget, move.feed, stages);
    }
    // A blend slower than the first stage's cap is braked into and left as a stop is: near it
    // the lowest share (R2.4 at F6000: 10 %, 200 mm/s^2) would brake and accelerate all along
    // the curve (2026-11-28: the quarter circles of cycle 24's approach took twice their bound).
    const bool stopFollows = count > 0 && exitVelocity < stages[0].cap;
    double sinceStop = m_sinceStop;  // at the start of the element (pushElement adds)
    if (count > 0 && m_blendVelocity < stages[0].cap) sinceStop = std::min(sinceStop, m_sinceBlend);
    if (count == 0 || (sinceStop >= kFarFromStop && !stopFollows)) {
        pushElement(move, geometry, contourBudget, blockEnd, nullptr);
        return;
    }
    // Stage k holds where the distance from the stop before (or, when one follows, to the stop
    // after) is below the stages' lengths up to k: pieces between those breakpoints.
    const double length = geometry.length;
    std::array<double, 10> cuts{};
    size_t cutCount = 0;
    double reach = 0.0;
    for (size_t k = 0; k < count; ++k) {
        reach += stages[k].length;
        for (double cut : {reach - sinceStop, stopFollows ? length - reach : -1.0}) {
            if (cut > 1e-6 && cut < length - 1e-6) cuts[cutCount++] = cut;
        }
    }
    std::sort(cuts.begin(), cuts.begin() + static_cast<std::ptrdiff_t>(cutCount));
    auto stageAt = [&](double s) {
        double sum = 0.0;
        for (size_t k = 0; k < count; ++k) {
            sum += stages[k].length;
            if (sinceStop + s < sum || (stopFollows && length - s < sum)) return k;
        }
        return count;
    };
    double from = 0.0;
    for (size_t i = 0; i <= cutCount; ++i) {
        const double to = i < cutCount ? cuts[i] : length;
        if (to - from < 1e-9) continue;
        // Pieces of one stage next to each other stay one.
        const size_t stage = stageAt((from + to) / 2.0);
        if (i < cutCount &&
            stageAt((to + (i + 1 < cutCount ? cuts[i + 1] : length)) / 2.0) == stage)
            continue;
        pushElement(move, trimmed(geometry, from, to), contourBudget, blockEnd && to >= length,
                    stage < count ? &stages[stage] : nullptr);
        from = to;
    }
}

void Planner::pushElement(const Move& move, const PathGeometry& geometry, double contourBudget,
                          bool blockEnd, const ShareStage* stage) {
    MotionItem item;
    item.kind = MotionItem::Kind::Element;
    item.sequence = ++m_sequence;
    item.source = move.source;
    PathElement& e = item.element;
    e.geometry = geometry;
    e.sStart = m_pathS;
    e.feed = move.feed;
    e.feedKind = move.feedKind;
    e.feedMove = move.feedMove;
    e.probe = move.probe;
    e.blockEnd = blockEnd;
    e.joinedGroup = move.joinedGroup;
    e.spindleDegPerUnit = move.spindleDegPerUnit;
    e.moveIndex = move.index;
    e.firstMoveIndex = move.firstIndex;
    e.source = move.source;
    if (move.feedKind == FeedKind::SpindleSynced) {
        double lead = move.feed;
        e.capVelocity = lead * m_model.spindleMaxRpm / 60.0;
        e.limits = {m_model.options.spindleAccelRevPerS2 * lead,
                    m_model.options.spindleJerkRevPerS3 * lead};
    } else if (move.feedKind != FeedKind::Rapid) {
        e.capVelocity = m_model.maxFeed;
    }
    if (stage) {
        e.limits = stage->limits;
        e.capVelocity = std::min(e.capVelocity, stage->cap);
    }
    m_pathS += geometry.length;
    m_sinceStop += geometry.length;
    m_sinceBlend += geometry.length;
    m_lookahead.push(item, contourBudget);
}

void Planner::exactStop() {
    endRun();
    stopAfterPending();
}

void Planner::stopAfterPending() {
    settleShort();
    emitPending(0.0, 0.0);
    m_lookahead.stopHere();
    m_sinceStop = 0.0;
}

void Planner::emitAction(const Action& action, const SourceLocation& source) {
    if (m_role == PlannerRole::JudgeOnly) return;
    // Every action happens with the axes at rest.
    exactStop();
    MotionItem item;
    item.kind = MotionItem::Kind::Action;
    item.sequence = ++m_sequence;
    item.action = action;
    item.action.joinedGroup = m_joinedGroup;
    item.source = source;
    m_lookahead.push(item);
}

void Planner::endSynchronisation(const SourceLocation& source) {
    if (!m_synchronised) return;
    m_synchronised = false;
    emitAction({ActionKind::SyncEnd, 0.0, 0.0, 0.0, 0}, source);
}

}  // namespace kerf::motion
