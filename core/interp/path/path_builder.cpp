#include "core/interp/path/path_builder.h"

#include <cmath>

#include "core/base/translate.h"
#include "core/interp/path/approach_geometry.h"

namespace kerf::interp {

namespace {

constexpr double kEps = 1e-9;

PathError error(const SourceLocation& at, const char* code, const char* message) {
    return PathError{at, code, message, {}};
}

Pose withPlanePoint(const ContourElement& frame, Pose pose, const Vec2& p) {
    frame.setInPlane(pose, p);
    return pose;
}

}  // namespace

void PathBuilder::reset(const Pose& toolPosition) {
    m_tool = toolPosition;
    m_held.reset();
    m_corner.reset();
    m_heldAfter.clear();
    m_comp.reset();
    m_compAfter.clear();
    m_approach.reset();
    m_side = CompSide::None;
    m_lookAhead = 0;
    m_ahead.clear();
    m_leftOutAtEnd = {};
}

std::optional<PathError> PathBuilder::setLookAhead(int blocks) {
    if (blocks == m_lookAhead) return std::nullopt;
    auto e = aheadDrain();
    m_lookAhead = blocks;
    return e;
}

void PathBuilder::addMachineLine(const Pose& target, bool rapid, double feed,
                                 const SourceLocation& location) {
    emitStraight(target, rapid, feed, location);
    m_tool = m_space ? m_space->toPath(target) : target;
}

void PathBuilder::setSpace(const PathSpace* space, double toleranceMm) {
    m_space = space;
    m_spaceToleranceMm = toleranceMm;
}

std::optional<PathError> PathBuilder::takeSpaceError() {
    if (!m_spaceError) return std::nullopt;  // asked after every block
    auto e = std::move(m_spaceError);
    m_spaceError.reset();
    return e;
}

double PathBuilder::signedOffset(CompSide side) const {
    return static_cast<double>(static_cast<int>(side)) * m_radius;
}

// ---- output ---------------------------------------------------------------------------------

void PathBuilder::emitInSpace(const ContourElement& element, bool rapid, double feed,
                              const SourceLocation& location) {
    m_tool = element.end;
    if (m_spaceError) return;  // the run stops at the first element that could not be split
    m_pieces.clear();
    if (!machinePieces(*m_space, element, feed, m_spaceToleranceMm, m_pieces)) {
        m_spaceError = error(location, "tolerance",
                             KERF_TR_NOOP("the rotary axes turn too far in this block to keep "
                                          "the tool tip on the path; split the block"));
        return;
    }
    for (const MachinePiece& piece : m_pieces) {
        m_spaceError = m_space->refusePiece(piece.target, location);
        if (m_spaceError) return;
    }
    for (const MachinePiece& piece : m_pieces)
        emitStraight(piece.target, rapid, piece.feed, location);
}

void PathBuilder::emitStraight(const Pose& target, bool rapid, double feed,
                               const SourceLocation& location) {
    canon::Command command;
    command.location = location;
    if (rapid) {
        command.body = canon::RapidMove{target};
    } else {
        command.body = canon::LinearMove{target, feed};
    }
    m_sink.consume(command);
}

void PathBuilder::emitLine(const Pose& target, bool rapid, double feed,
                           const SourceLocation& location) {
    if (m_space)
        return emitInSpace(ContourElement::line(Plane::XY, m_tool, target), rapid, feed, location);
    emitStraight(target, rapid, feed, location);
    m_tool = target;
}

void PathBuilder::emitArc(Plane plane, const Pose& target, const Vec2& center, double sweep,
                          double feed, const SourceLocation& location) {
    if (m_space) {
        return emitInSpace(ContourElement::arc(plane, m_tool, target, center, sweep), false, feed,
                           location);
    }
    PlaneAxes axes = planeAxes(plane);
    canon::ArcMove arc;
    arc.target = target;
    arc.plane = plane;
    arc.sweepRad = sweep;
    arc.feed = feed;
    arc.center = m_tool.xyz();
    arc.center[axisIndex(axes.first)] = center.x();
    arc.center[axisIndex(axes.second)] = center.y();
    m_sink.consume(canon::Command{location, arc});
    m_tool = target;
}

void PathBuilder::emitElement(const ContourElement& element, const PathMove& move) {
    if (element.kind == ContourElement::Kind::Arc) {
        emitArc(element.plane, element.end, element.center, element.sweep, move.feed,
                move.location);
    } else {
        emitLine(element.end, move.rapid, move.feed, move.location);
    }
}

// ---- stage 1: roundings and chamfers on the programmed contour --------------------------------

std::optional<PathError> PathBuilder::addMove(const PathMove& move) {
    if (!m_held) {
        m_held = move;
        return std::nullopt;
    }
    if (!m_corner && passesStraightOn(*m_held)) {
        // What forwardHeld() and compMove() do with it, without their copies and checks.
        emitLine(m_held->geometry.end, m_held->rapid, m_held->feed, m_held->location);
        *m_held = move;
        return std::nullopt;
    }
    if (!m_corner) {
        if (auto e = forwardHeld()) return e;
        m_held = move;
        return std::nullopt;
    }
    const Corner corner = *m_corner;
    m_corner.reset();
    PathMove next = move;
    if (!next.geometry.movesInPlane()) {
        return error(next.location, "contour",
                     KERF_TR_NOOP("a rounding or chamfer must be followed by a contour element in "
                                  "the working plane"));
    }
    PathMove& previous = *m_held;
    PathMove inserted = previous;
    inserted.rapid = false;
    inserted.location = corner.location;
    if (corner.feed) inserted.feed = *corner.feed;
    if (corner.chamfer) {
        const ContourElement& a = previous.geometry;
        const ContourElement& b = next.geometry;
        if (a.kind != ContourElement::Kind::Line || b.kind != ContourElement::Kind::Line) {
            return error(corner.location, "contour",
                         KERF_TR_NOOP("a chamfer needs straight lines on both sides"));
        }
        const double la = a.planarLength();
        const double lb = b.planarLength();
        if (corner.size >= la - kEps || corner.size >= lb - kEps) {
            return error(corner.location, "contour",
                         KERF_TR_NOOP("the chamfer is longer than the adjacent element"));
        }
        previous.geometry = a.sub(0.0, 1.0 - corner.size / la);
        next.geometry = b.sub(corner.size / lb, 1.0);
        inserted.geometry =
            ContourElement::line(a.plane, previous.geometry.end, next.geometry.start);
    } else {
        auto f = fillet(previous.geometry, next.geometry, corner.size);
        if (!f) {
            return error(corner.location, "contour",
                         KERF_TR_NOOP("the rounding radius does not fit between the elements"));
        }
        previous.geometry = previous.geometry.sub(0.0, f->paramOnA);
        next.geometry = next.geometry.sub(f->paramOnB, 1.0);
        inserted.geometry = ContourElement::arc(previous.geometry.plane, previous.geometry.end,
                                                next.geometry.start, f->center, f->sweep);
    }
    if (auto e = forwardHeld()) return e;
    if (auto e = compMove(inserted)) return e;
    m_held = next;
    return std::nullopt;
}

std::optional<PathError> PathBuilder::addRounding(double radius, std::optional<double> feed,
                                                  const SourceLocation& location) {
    if (!m_held || !m_held->geometry.movesInPlane() || m_corner) {
        return error(location, "contour",
                     KERF_TR_NOOP("a rounding needs a contour element before it"));
    }
    m_corner = Corner{false, radius, feed, location};
    return std::nullopt;
}

std::optional<PathError> PathBuilder::addChamfer(double length, std::optional<double> feed,
                                                 const SourceLocation& location) {
    if (!m_held || !m_held->geometry.movesInPlane() || m_corner) {
        return error(location, "contour",
                     KERF_TR_NOOP("a chamfer needs a contour element before it"));
    }
    m_corner = Corner{true, length, feed, location};
    return std::nullopt;
}

void PathBuilder::addCommand(canon::Command command) {
    if (m_held) {
        m_heldAfter.push_back(std::move(command));
    } else {
        compCommand(std::move(command));
    }
}

bool PathBuilder::passesStraightOn(const PathMove& held) const {
    return held.side == CompSide::None && m_side == CompSide::None &&
           held.geometry.kind == ContourElement::Kind::Line && m_heldAfter.empty() && !m_comp &&
           !m_approach && m_ahead.empty() && m_leftOutAtEnd.count == 0;
}

std::optional<PathError> PathBuilder::forwardHeld() {
    if (!m_held) return std::nullopt;
    PathMove move = *m_held;
    m_held.reset();
    if (auto e = compMove(move)) return e;
    for (canon::Command& c : m_heldAfter)
        compCommand(std::move(c));
    m_heldAfter.clear();
    return std::nullopt;
}

std::optional<PathError> PathBuilder::flush() {
    if (m_corner) {
        SourceLocation at = m_corner->location;
        m_corner.reset();
        return error(at, "contour",
                     KERF_TR_NOOP("a rounding or chamfer must be followed by a contour element"));
    }
    if (auto e = forwardHeld()) return e;
    if (m_approach) {
        SourceLocation at = m_approach->location;
        m_approach.reset();
        return error(at, "contour",
                     KERF_TR_NOOP("an approach must be followed by a compensated contour element"));
    }
    if (auto e = compFinishHeld()) return e;
    compFlushQueue();
    return std::nullopt;
}

std::optional<PathError> PathBuilder::addApproach(const ApproachSpec& spec) {
    if (m_corner) {
        return error(m_corner->location, "contour",
                     KERF_TR_NOOP("a rounding or chamfer must be followed by a contour element"));
    }
    if (auto e = forwardHeld()) return e;
    if (auto e = compFinishHeld()) return e;
    compFlushQueue();
    if (spec.side == CompSide::None) {
        return error(spec.location, "contour", KERF_TR_NOOP("an approach needs RL or RR"));
    }
    m_approach = spec;
    m_side = spec.side;
    return std::nullopt;
}

std::optional<PathError> PathBuilder::addDeparture(const ApproachSpec& spec) {
    if (m_corner) {
        return error(m_corner->location, "contour",
                     KERF_TR_NOOP("a rounding or chamfer must be followed by a contour element"));
    }
    if (auto e = forwardHeld()) return e;
    if (auto e = aheadDrain()) return e;
    if (!m_comp || m_side == CompSide::None) {
        return error(spec.location, "contour",
                     KERF_TR_NOOP("a departure needs a compensated contour element before it"));
    }
    const ContourElement last = m_comp->move.geometry;
    const double offset = signedOffset(m_side);
    if (auto e = compFinishHeld()) return e;
    compFlushQueue();
    auto moves = departureMoves(spec.kind, last.end2(), last.endTangent(), offset, spec.length,
                                spec.angleDeg, spec.radius, last.inPlane(spec.endPoint));
    if (!moves) {
        return error(spec.location, "contour",
                     KERF_TR_NOOP("the departure cannot be constructed with these values"));
    }
    for (const PlanarMove& m : *moves) {
        Pose target = withPlanePoint(last, m_tool, m.end);
        if (spec.kind == ApproachKind::LineCircle && &m == &moves->back()) {
            target = spec.endPoint;
        }
        if (m.arc) {
            emitArc(last.plane, target, m.center, m.sweep, spec.feed, spec.location);
        } else {
            emitLine(target, false, spec.feed, spec.location);
        }
    }
    m_side = CompSide::None;
    m_lookAhead = 0;  // M120 ends with the compensation
    return std::nullopt;
}

// ---- stage 2: tool-radius compensation ------------------------------------------------------

void PathBuilder::compCommand(canon::Command command) {
    if (m_comp || m_approach) {
        m_compAfter.push_back(Queued{std::move(command), std::nullopt});
    } else {
        m_sink.consume(command);
    }
}

void PathBuilder::compFlushQueue() {
    emitQueued(m_compAfter);
}

void PathBuilder::emitQueued(std::vector<Queued>& queue) {
    for (Queued& q : queue) {
        if (q.command) {
            m_sink.consume(*q.command);
        } else if (q.axialMove) {
            // A tool-axis move at the current tool position in the plane.
            const ContourElement& g = q.axialMove->geometry;
            Pose target = withPlanePoint(g, q.axialMove->geometry.end, g.inPlane(m_tool));
            emitLine(target, q.axialMove->rapid, q.axialMove->feed, q.axialMove->location);
        }
    }
    queue.clear();
}

std::optional<PathError> PathBuilder::compFinishHeld() {
    if (auto e = aheadDrain()) return e;
    if (!m_comp) return std::nullopt;
    Compensated held = *m_comp;
    m_comp.reset();
    if (held.activation) {
        // Switching on and off in the same element: perpendicular to the element itself.
        const ContourElement& g = held.move.geometry;
        Vec2 end = g.end2() + signedOffset(held.move.side) * leftNormal(g.endTangent());
        held.tool = ContourElement::line(g.plane, held.tool.start, withPlanePoint(g, g.end, end));
    }
    emitElement(held.tool, held.move);
    compFlushQueue();
    return std::nullopt;
}

std::optional<PathError> PathBuilder::compMove(const PathMove& move) {
    const bool inPlane = move.geometry.movesInPlane();
    if (move.side == CompSide::None) {
        if (m_approach) {
            return error(move.location, "contour",
                         KERF_TR_NOOP("an approach must be followed by a compensated contour "
                                      "element"));
        }
        const bool wasCompensated = m_comp.has_value();
        if (auto e = compFinishHeld()) return e;
        if (m_side != CompSide::None) m_lookAhead = 0;  // M120 ends with R0
        m_side = CompSide::None;
        if (move.geometry.kind == ContourElement::Kind::Arc) {
            if (wasCompensated &&
                (move.geometry.start2() - move.geometry.inPlane(m_tool)).norm() > 1e-6) {
                return error(move.location, "contour",
                             KERF_TR_NOOP("leave radius compensation with a straight line"));
            }
            emitElement(move.geometry, move);
        } else {
            emitLine(move.geometry.end, move.rapid, move.feed, move.location);
        }
        return std::nullopt;
    }
    if (m_side != CompSide::None && move.side != m_side && (m_comp || !inPlane)) {
        return error(move.location, "contour",
                     KERF_TR_NOOP("switching between RL and RR needs a block with R0 between"));
    }
    if (!inPlane) {
        if (m_comp || m_approach) {
            m_compAfter.push_back(Queued{std::nullopt, move});
            return std::nullopt;
        }
        m_side = move.side;
        Pose target =
            withPlanePoint(move.geometry, move.geometry.end, move.geometry.inPlane(m_tool));
        emitLine(target, move.rapid, move.feed, move.location);
        return std::nullopt;
    }
    if (m_approach) return compResolveApproach(move);
    if (!m_comp) {
        if (move.geometry.kind == ContourElement::Kind::Arc) {
            return error(move.location, "contour",
                         KERF_TR_NOOP("radius compensation must begin with a straight line"));
        }
        Compensated held;
        held.move = move;
        held.activation = true;
        held.tool = ContourElement::line(move.geometry.plane, m_tool, move.geometry.end);
        m_comp = held;
        m_side = move.side;
        return std::nullopt;
    }
    if (m_lookAhead > 0) return aheadAdd(move);
    return compCorner(move);
}

std::optional<PathError> PathBuilder::compCorner(const PathMove& move) {
    const Compensated& held = *m_comp;
    JunctionOutcome out = joinAdjacent(held.tool, held.move.geometry, move.geometry,
                                       signedOffset(move.side), held.activation);
    if (!out.junction) {
        return error(out.failure.swallowedLater ? move.location : held.move.location,
                     "radius-too-large", out.failure.messageTemplate);
    }
    commitJunction(*out.junction, move, m_compAfter);
    return std::nullopt;
}

void PathBuilder::commitJunction(const OffsetJunction& junction, const PathMove& next,
                                 std::vector<Queued>& between) {
    Compensated& held = *m_comp;
    emitElement(junction.before, held.move);
    emitQueued(between);
    if (const auto& t = junction.transition) {
        emitArc(t->plane, withPlanePoint(next.geometry, m_tool, t->end2()), t->center, t->sweep,
                next.feed, next.location);
    }
    held.move = next;
    held.tool = junction.after;
    held.tool.start = withPlanePoint(next.geometry, held.tool.start, held.tool.inPlane(m_tool));
    held.activation = false;
}

// ---- look-ahead (M120) ------------------------------------------------------------------------

std::optional<PathError> PathBuilder::aheadAdd(const PathMove& move) {
    m_ahead.push_back(Ahead{move, std::move(m_compAfter), m_leftOutAtEnd});
    m_compAfter.clear();
    m_leftOutAtEnd = {};
    // Every element after the held one counts against LA, the left-out ones too.
    int seen = 0;
    for (const Ahead& a : m_ahead)
        seen += 1 + a.leftOut.count;
    if (seen > m_lookAhead) return aheadCommit();
    return std::nullopt;
}

// Runs the corner rules over the held elements; the element to leave out first, if any.
std::optional<size_t> PathBuilder::aheadFindUndercut() const {
    ContourElement tool = m_comp->tool;
    ContourElement programmed = m_comp->move.geometry;
    bool activation = m_comp->activation;
    for (size_t i = 0; i < m_ahead.size(); ++i) {
        const PathMove& move = m_ahead[i].move;
        const double offset = signedOffset(move.side);
        if (activation || m_ahead[i].leftOut.count == 0) {
            JunctionOutcome out = joinAdjacent(tool, programmed, move.geometry, offset, activation);
            if (!out.junction) {
                // The first held element has begun already: the one after it goes instead.
                return out.failure.swallowedLater || i == 0 ? i : i - 1;
            }
            tool = out.junction->after;
        } else {
            auto bridge = bridgeOffsets(tool, programmed, move.geometry, offset);
            if (!bridge) return i;
            tool = bridge->after;
        }
        programmed = move.geometry;
        activation = false;
    }
    return std::nullopt;
}

// Leaves out one held element; what was queued around it keeps its place.
std::optional<PathError> PathBuilder::aheadLeaveOut(size_t index) {
    Ahead& gone = m_ahead[index];
    const bool last = index + 1 == m_ahead.size();
    LeftOut& run = last ? m_leftOutAtEnd : m_ahead[index + 1].leftOut;
    std::vector<Queued>& following = last ? m_compAfter : m_ahead[index + 1].before;
    LeftOut joined{gone.leftOut.count + 1 + run.count,
                   gone.leftOut.count > 0 ? gone.leftOut.first : gone.move.location};
    std::vector<Queued> queue = std::move(gone.before);
    queue.insert(queue.end(), std::make_move_iterator(following.begin()),
                 std::make_move_iterator(following.end()));
    following = std::move(queue);
    run = joined;
    m_ahead.erase(m_ahead.begin() + static_cast<std::ptrdiff_t>(index));
    if (joined.count > m_lookAhead) {
        // More elements in a row would have to be left out than the look-ahead sees.
        return error(joined.first, "radius-too-large",
                     KERF_TR_NOOP("tool radius too large: the offset swallows this element"));
    }
    return std::nullopt;
}

// Leaves out what cuts into the contour, then resolves the junction after the held element.
std::optional<PathError> PathBuilder::aheadCommit() {
    while (auto index = aheadFindUndercut()) {
        if (auto e = aheadLeaveOut(*index)) return e;
    }
    if (m_ahead.empty()) return std::nullopt;  // the element after the left-out ones is to come
    Ahead next = std::move(m_ahead.front());
    m_ahead.erase(m_ahead.begin());
    const Compensated& held = *m_comp;
    const double offset = signedOffset(next.move.side);
    std::optional<OffsetJunction> junction;
    if (held.activation || next.leftOut.count == 0) {
        junction =
            joinAdjacent(held.tool, held.move.geometry, next.move.geometry, offset, held.activation)
                .junction;
    } else {
        junction = bridgeOffsets(held.tool, held.move.geometry, next.move.geometry, offset);
    }
    commitJunction(*junction, next.move, next.before);
    return std::nullopt;
}

std::optional<PathError> PathBuilder::aheadDrain() {
    while (!m_ahead.empty()) {
        if (auto e = aheadCommit()) return e;
    }
    if (m_leftOutAtEnd.count > 0) {
        // Left-out elements at the end of the contour: no element after them to join.
        const SourceLocation at = m_leftOutAtEnd.first;
        m_leftOutAtEnd = {};
        return error(at, "radius-too-large",
                     KERF_TR_NOOP("tool radius too large: the offset swallows this element"));
    }
    return std::nullopt;
}

std::optional<PathError> PathBuilder::compResolveApproach(const PathMove& move) {
    const ApproachSpec spec = *m_approach;
    m_approach.reset();
    const ContourElement& first = move.geometry;
    const double offset = signedOffset(move.side);
    auto moves =
        approachMoves(spec.kind, first.inPlane(m_tool), first.start2(), first.startTangent(),
                      offset, spec.length, spec.angleDeg, spec.radius);
    if (!moves) {
        return error(spec.location, "contour",
                     KERF_TR_NOOP("the approach cannot be constructed with these values"));
    }
    auto next = offsetElement(first, offset);
    if (!next) {
        return error(move.location, "radius-too-large",
                     KERF_TR_NOOP("tool radius too large for this arc"));
    }
    const PlaneAxes axes = planeAxes(first.plane);
    for (size_t i = 0; i < moves->size(); ++i) {
        const PlanarMove& m = (*moves)[i];
        Pose target = withPlanePoint(first, m_tool, m.end);
        if (i > 0) target[axes.normal] = spec.contourPoint[axes.normal];
        if (i == 0) {
            emitLine(target, spec.rapidToHelper, spec.feed, spec.location);
            if (spec.moveToolAxis && m_tool[axes.normal] != spec.contourPoint[axes.normal]) {
                Pose down = m_tool;
                down[axes.normal] = spec.contourPoint[axes.normal];
                emitLine(down, false, spec.feed, spec.location);
            }
        } else if (m.arc) {
            emitArc(first.plane, target, m.center, m.sweep, spec.feed, spec.location);
        } else {
            emitLine(target, false, spec.feed, spec.location);
        }
    }
    compFlushQueue();
    Compensated held;
    held.move = move;
    held.tool = *next;
    held.tool.start = withPlanePoint(first, held.tool.start, first.inPlane(m_tool));
    held.activation = false;
    m_comp = held;
    m_side = move.side;
    return std::nullopt;
}

}  // namespace kerf::interp
