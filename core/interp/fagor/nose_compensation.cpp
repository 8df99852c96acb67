#include "core/interp/fagor/nose_compensation.h"

#include <cmath>

#include "core/base/translate.h"

namespace kerf::fagor {

namespace {

constexpr double kEps = 1e-9;
constexpr double kTangentTurn = 1e-7;
constexpr double kStraightLimit = 300.0 * kPi / 180.0;  // COMPMODE: angle between the paths
constexpr int kMaxBlocksWithoutMotion = 48;

interp::PathError error(const SourceLocation& at, const char* code, const char* message) {
    return interp::PathError{at, code, message, {}};
}

Pose withPoint(const ContourElement& frame, Pose pose, const Vec2& p) {
    frame.setInPlane(pose, p);
    return pose;
}

// A piece of path from `from` to `to` in the element's plane, keeping the element's other axes.
ContourElement lineBetween(const ContourElement& frame, const Pose& fromPose, const Vec2& from,
                           const Vec2& to) {
    return ContourElement::line(frame.plane, withPoint(frame, fromPose, from),
                                withPoint(frame, fromPose, to));
}

const Vec2* nearest(const std::vector<Vec2>& points, const Vec2& to) {
    const Vec2* best = nullptr;
    for (const Vec2& p : points) {
        if (!best || (p - to).squaredNorm() < (*best - to).squaredNorm()) best = &p;
    }
    return best;
}

}  // namespace

void NoseCompensation::reset(const Pose& position) {
    m_position = position;
    m_held.reset();
    m_queue.clear();
    m_start.reset();
    m_side = interp::CompSide::None;
    m_pieces.clear();
    m_blocksWithoutMotion = 0;
}

void NoseCompensation::setTool(double radius, const Vec2& tipInPlane) {
    m_radius = radius;
    m_tip = tipInPlane;
}

double NoseCompensation::offsetFor(interp::CompSide side) const {
    return static_cast<double>(static_cast<int>(side)) * m_radius;
}

std::vector<SourceLocation> NoseCompensation::takeRemovedLoops() {
    std::vector<SourceLocation> out;
    out.swap(m_removedLoops);
    return out;
}

// ---- output ---------------------------------------------------------------------------------

void NoseCompensation::emit(const ContourElement& centrePath, MoveKind kind, double feed,
                            const ThreadData& thread, const SourceLocation& at) {
    const Vec2 tip = m_radius * m_tip;
    Piece piece;
    piece.kind = kind;
    piece.feed = feed;
    piece.thread = thread;
    piece.location = at;
    piece.block = m_block;
    const Pose target = withPoint(centrePath, centrePath.end, centrePath.end2() + tip);
    if (centrePath.kind == ContourElement::Kind::Arc) {
        const Vec2 center = centrePath.center + tip;
        piece.path =
            ContourElement::arc(centrePath.plane, m_position, target, center, centrePath.sweep);
    } else {
        piece.path = ContourElement::line(centrePath.plane, m_position, target);
    }
    m_position = target;
    push(std::move(piece));
}

void NoseCompensation::emitPlain(const Move& move, const Pose& target) {
    ContourElement path = move.geometry;
    path.end = target;
    const bool arc = path.kind == ContourElement::Kind::Arc;
    Piece piece;
    piece.kind = move.kind;
    piece.feed = move.feed;
    piece.thread = move.thread;
    piece.location = move.location;
    piece.block = m_block;
    piece.path = arc ? ContourElement::arc(path.plane, m_position, target, path.center, path.sweep)
                     : ContourElement::line(path.plane, m_position, target);
    m_position = target;
    push(std::move(piece));
}

void NoseCompensation::addCommand(canon::Command command) {
    if (m_held) {
        m_queue.push_back(Queued{std::move(command), std::nullopt});
        return;
    }
    Piece piece;
    piece.command = std::move(command);
    piece.block = m_block;
    push(std::move(piece));
}

void NoseCompensation::output(const Piece& piece) {
    if (piece.command) {
        m_out.consume(*piece.command);
        return;
    }
    const ContourElement& p = piece.path;
    canon::Command command;
    command.location = piece.location;
    if (p.kind == ContourElement::Kind::Arc) {
        const PlaneAxes axes = planeAxes(p.plane);
        canon::ArcMove arc;
        arc.target = p.end;
        arc.plane = p.plane;
        arc.sweepRad = p.sweep;
        arc.feed = piece.feed;
        arc.center = p.start.xyz();
        arc.center[axisIndex(axes.first)] = p.center.x();
        arc.center[axisIndex(axes.second)] = p.center.y();
        command.body = arc;
    } else if (piece.kind == MoveKind::Rapid) {
        command.body = canon::RapidMove{p.end};
    } else if (piece.kind == MoveKind::Thread) {
        command.body = canon::SpindleSyncedMove{p.end, piece.thread.lead, piece.thread.startAngle,
                                                piece.thread.leadChange};
    } else if (piece.kind == MoveKind::ProbeTouch || piece.kind == MoveKind::ProbeRelease) {
        command.body = canon::ProbeMove{p.end, piece.feed, piece.kind == MoveKind::ProbeRelease};
    } else {
        command.body = canon::LinearMove{p.end, piece.feed};
    }
    m_out.consume(command);
}

// ---- collision detection ----------------------------------------------------------------------

void NoseCompensation::push(Piece piece) {
    if (m_window < 3) {
        drainWindow(0);
        output(piece);
        return;
    }
    if (!piece.command && piece.path.movesInPlane()) removeLoops(piece);
    m_pieces.push_back(std::move(piece));
    drainWindow(static_cast<size_t>(m_window));
}

void NoseCompensation::drainWindow(size_t keepBlocks) {
    auto blocks = [&] {
        size_t n = 0;
        uint64_t last = 0;
        for (const Piece& p : m_pieces) {
            if (p.command) continue;
            if (n == 0 || p.block != last) ++n;
            last = p.block;
        }
        return n;
    };
    while (!m_pieces.empty() && (keepBlocks == 0 || blocks() > keepBlocks)) {
        output(m_pieces.front());
        m_pieces.pop_front();
    }
}

void NoseCompensation::removeLoops(Piece& piece) {
    // The newest motion piece shares its start with the previous one: only older ones can form a
    // loop with it.
    std::optional<size_t> previous;
    for (size_t i = m_pieces.size(); i-- > 0;) {
        if (m_pieces[i].command || !m_pieces[i].path.movesInPlane()) continue;
        if (!previous) {
            previous = i;
            continue;
        }
        Piece& older = m_pieces[i];
        for (const Vec2& x : intersectCarriers(older.path, piece.path)) {
            const double to = older.path.paramOf(x);
            const double tn = piece.path.paramOf(x);
            if (to < -kEps || to > 1.0 - 1e-7 || tn < 1e-7 || tn > 1.0 + kEps) continue;
            // Cut the loop: the older piece ends at the crossing, the new one starts there; the
            // motion in between is dropped, everything else in it is kept.
            older.path = older.path.sub(0.0, std::max(0.0, to));
            older.path.setInPlane(older.path.end, x);
            piece.path = piece.path.sub(tn, 1.0);
            piece.path.setInPlane(piece.path.start, x);
            // The warning names the first block whose motion is dropped.
            SourceLocation dropped = piece.location;
            bool named = false;
            std::deque<Piece> kept;
            for (size_t j = i + 1; j < m_pieces.size(); ++j) {
                if (m_pieces[j].command) {
                    kept.push_back(std::move(m_pieces[j]));
                } else if (!named) {
                    dropped = m_pieces[j].location;
                    named = true;
                }
            }
            m_pieces.erase(m_pieces.begin() + static_cast<std::ptrdiff_t>(i) + 1, m_pieces.end());
            for (Piece& k : kept)
                m_pieces.push_back(std::move(k));
            m_removedLoops.push_back(dropped);
            return;
        }
    }
}

// ---- compensation -------------------------------------------------------------------------

void NoseCompensation::flushQueue() {
    std::vector<Queued> queue;
    queue.swap(m_queue);
    for (Queued& q : queue) {
        if (q.command) {
            Piece piece;
            piece.command = std::move(*q.command);
            piece.block = m_block;
            push(std::move(piece));
        } else if (q.axial) {
            // A move of other axes at the tool's present point in the plane.
            const ContourElement& g = q.axial->geometry;
            Move move = *q.axial;
            move.geometry = ContourElement::line(g.plane, m_position,
                                                 withPoint(g, g.end, g.inPlane(m_position)));
            emitPlain(move, move.geometry.end);
        }
    }
    m_blocksWithoutMotion = 0;
}

void NoseCompensation::emitHeld(const ContourElement& path) {
    const Held held = *m_held;
    emit(path, held.move.kind, held.move.feed, held.move.thread, held.move.location);
    flushQueue();
}

void NoseCompensation::finishHeldPerpendicular() {
    if (!m_held) return;
    ContourElement path = m_held->path;
    if (m_held->activation) {
        const ContourElement& g = m_held->move.geometry;
        const Vec2 end = g.end2() + offsetFor(m_held->move.side) * leftNormal(g.endTangent());
        path = lineBetween(g, g.end, path.start2(), end);
        path.start = m_held->path.start;
    }
    emitHeld(path);
    m_held.reset();
}

std::optional<interp::PathError> NoseCompensation::suspend() {
    finishHeldPerpendicular();
    flushQueue();
    drainWindow(0);
    if (m_side != interp::CompSide::None) m_start = Start::Activation;
    return std::nullopt;
}

void NoseCompensation::startCompensation(const Move& move) {
    m_side = move.side;
    const double offset = offsetFor(move.side);
    const ContourElement& g = move.geometry;
    if (g.kind == ContourElement::Kind::Arc || m_start == Start::AtPoint) {
        // First perpendicular to the element's start, then along its offset.
        auto path = offsetElement(g, offset);
        const Vec2 start = g.start2() + offset * leftNormal(g.startTangent());
        emit(lineBetween(g, g.start, g.start2(), start), MoveKind::Feed, move.feed, move.thread,
             move.location);
        Held held;
        held.move = move;
        held.path = path ? *path : g;
        m_held = held;
    } else {
        Held held;
        held.move = move;
        held.activation = true;
        held.path = ContourElement::line(g.plane, m_position, g.end);
        m_held = held;
    }
    m_start.reset();
}

std::optional<interp::PathError> NoseCompensation::join(const Held& held,
                                                        const ContourElement& next,
                                                        const ContourElement& nextPath,
                                                        double offset, const SourceLocation& at,
                                                        Join& out) const {
    const ContourElement& a = held.move.geometry;
    // The held element's offset; an activation line is joined as if it were compensated.
    ContourElement carrier = held.path;
    if (held.activation) {
        auto full = offsetElement(a, offset);
        carrier = full ? *full : a;
    }
    auto activationTo = [&](const Vec2& p) {
        ContourElement line = lineBetween(a, a.end, held.path.start2(), p);
        line.start = held.path.start;
        return line;
    };
    out.transition.clear();
    out.next = nextPath;
    const double turn = turnAngle(a, next);
    const bool reversal = std::fabs(std::fabs(turn) - kPi) < kTangentTurn;
    if (std::fabs(offset) < kEps || std::fabs(turn) < kTangentTurn) {
        out.held = held.activation ? activationTo(carrier.end2()) : carrier;
        out.next.setInPlane(out.next.start, out.held.end2());
        return std::nullopt;
    }
    const Vec2 corner = a.end2();
    if (!reversal && offset * turn > 0.0) {
        // Inside corner: both offsets end at their intersection nearest to the corner.
        const std::vector<Vec2> points = intersectCarriers(carrier, nextPath);
        const Vec2* x = nearest(points, corner);
        if (x == nullptr) return error(at, "compensation", KERF_TR_NOOP("tool radius too large"));
        const double ta = carrier.paramOf(*x);
        const double tb = nextPath.paramOf(*x);
        const bool swallowsHeld = !held.activation && ta <= kEps;
        if ((swallowsHeld || tb >= 1.0 - kEps) && m_window < 3) {
            return error(swallowsHeld ? held.move.location : at, "compensation",
                         KERF_TR_NOOP("tool radius too large: the offset swallows this element"));
        }
        if (swallowsHeld || tb >= 1.0 - kEps) {
            // Collision detection cuts the loop this leaves: join the perpendiculars.
            out.held = held.activation ? activationTo(carrier.end2()) : carrier;
            out.transition.push_back(lineBetween(a, a.end, carrier.end2(), nextPath.start2()));
            return std::nullopt;
        }
        out.held = held.activation ? activationTo(*x) : carrier.sub(0.0, std::min(ta, 1.0));
        out.held.setInPlane(out.held.end, *x);
        out.next = nextPath.sub(std::max(tb, 0.0), 1.0);
        out.next.setInPlane(out.next.start, *x);
        return std::nullopt;
    }
    // Outside corner.
    out.held = held.activation ? activationTo(carrier.end2()) : carrier;
    const double between = kPi + std::fabs(turn);
    const bool arc = m_compMode == 1 || between > kStraightLimit + 1e-9 || reversal;
    if (!arc && m_compMode == 2) {
        const std::vector<Vec2> points = intersectCarriers(carrier, nextPath);
        if (const Vec2* x = nearest(points, corner)) {
            const double ta = carrier.paramOf(*x);
            const double tb = nextPath.paramOf(*x);
            if (ta >= 1.0 - 1e-7 && tb <= 1e-7) {
                out.held = held.activation ? activationTo(*x) : carrier.sub(0.0, ta);
                out.held.setInPlane(out.held.end, *x);
                out.next = nextPath.sub(tb, 1.0);
                out.next.setInPlane(out.next.start, *x);
                return std::nullopt;
            }
        }
    } else if (!arc) {
        // Straight sections: tangent extensions of both offsets joined by a line, all tangent to
        // the arc of radius R around the corner.
        const double d = std::fabs(offset) * std::tan(std::fabs(turn) / 4.0);
        const Vec2 q1 = carrier.end2() + d * a.endTangent();
        const Vec2 q2 = nextPath.start2() - d * next.startTangent();
        if (a.kind == ContourElement::Kind::Line && !held.activation) {
            out.held.setInPlane(out.held.end, q1);  // the line's own extension
        } else {
            out.transition.push_back(lineBetween(a, a.end, carrier.end2(), q1));
        }
        out.transition.push_back(lineBetween(a, a.end, q1, q2));
        if (next.kind == ContourElement::Kind::Line) {
            out.next.setInPlane(out.next.start, q2);
        } else {
            out.transition.push_back(lineBetween(a, a.end, q2, nextPath.start2()));
        }
        return std::nullopt;
    }
    const double sweep = reversal ? (offset > 0.0 ? -kPi : kPi) : turn;
    out.transition.push_back(ContourElement::arc(a.plane, withPoint(a, a.end, carrier.end2()),
                                                 withPoint(a, a.end, nextPath.start2()), corner,
                                                 sweep));
    return std::nullopt;
}

std::optional<interp::PathError> NoseCompensation::corner(const Move& move) {
    const double offset = offsetFor(move.side);
    auto nextPath = offsetElement(move.geometry, offset);
    if (!nextPath) {
        return error(move.location, "compensation",
                     KERF_TR_NOOP("tool radius too large for this arc"));
    }
    Join j;
    if (auto e = join(*m_held, move.geometry, *nextPath, offset, move.location, j)) return e;
    emitHeld(j.held);
    for (const ContourElement& t : j.transition) {
        emit(t, MoveKind::Feed, move.feed, move.thread, move.location);
    }
    Held held;
    held.move = move;
    held.path = j.next;
    m_held = held;
    return std::nullopt;
}

std::optional<interp::PathError> NoseCompensation::changeSide(const Move& move) {
    const double offset = offsetFor(move.side);
    auto nextPath = offsetElement(move.geometry, offset);
    if (!nextPath) {
        return error(move.location, "compensation",
                     KERF_TR_NOOP("tool radius too large for this arc"));
    }
    const Held& held = *m_held;
    ContourElement path = held.path;
    if (held.activation) {
        const ContourElement& g = held.move.geometry;
        const Vec2 end = g.end2() + offsetFor(held.move.side) * leftNormal(g.endTangent());
        path = lineBetween(g, g.end, held.path.start2(), end);
        path.start = held.path.start;
    }
    // Each element on its own side: they switch where the offsets cross, or through an extra
    // segment between the perpendiculars.
    std::optional<Vec2> crossing;
    for (const Vec2& x : intersectCarriers(path, *nextPath)) {
        const double ta = path.paramOf(x);
        const double tb = nextPath->paramOf(x);
        if (ta > kEps && ta <= 1.0 + kEps && tb >= -kEps && tb < 1.0 - kEps) {
            if (!crossing ||
                (x - move.geometry.start2()).norm() < (*crossing - move.geometry.start2()).norm()) {
                crossing = x;
            }
        }
    }
    std::vector<ContourElement> transition;
    if (crossing) {
        path = path.sub(0.0, std::min(1.0, path.paramOf(*crossing)));
        path.setInPlane(path.end, *crossing);
        *nextPath = nextPath->sub(std::max(0.0, nextPath->paramOf(*crossing)), 1.0);
        nextPath->setInPlane(nextPath->start, *crossing);
    } else {
        transition.push_back(
            lineBetween(move.geometry, move.geometry.start, path.end2(), nextPath->start2()));
    }
    emitHeld(path);
    for (const ContourElement& t : transition) {
        emit(t, MoveKind::Feed, move.feed, move.thread, move.location);
    }
    Held next;
    next.move = move;
    next.path = *nextPath;
    m_held = next;
    m_side = move.side;
    return std::nullopt;
}

std::optional<interp::PathError> NoseCompensation::deactivate(const Move& move) {
    const bool inPlane = move.geometry.movesInPlane();
    if (!inPlane || move.kind == MoveKind::Rapid) {
        // Cancelled at the compensated end of the last element.
        finishHeldPerpendicular();
        const ContourElement& g = move.geometry;
        const Pose target = inPlane ? g.end : withPoint(g, g.end, g.inPlane(m_position));
        emitPlain(move, target);
    } else {
        if (move.geometry.kind == ContourElement::Kind::Arc) {
            return error(move.location, "compensation",
                         KERF_TR_NOOP("G40 needs a straight line (G00 or G01)"));
        }
        const double offset = offsetFor(m_held->move.side);
        auto path = offsetElement(move.geometry, offset);
        Join j;
        if (auto e = join(*m_held, move.geometry, *path, offset, move.location, j)) return e;
        emitHeld(j.held);
        m_held.reset();
        for (const ContourElement& t : j.transition) {
            emit(t, MoveKind::Feed, move.feed, move.thread, move.location);
        }
        emitPlain(move, move.geometry.end);
    }
    m_side = interp::CompSide::None;
    m_start.reset();
    drainWindow(0);
    return std::nullopt;
}

std::optional<interp::PathError> NoseCompensation::add(const Move& move) {
    ++m_block;
    if (move.side == interp::CompSide::None) {
        if (m_held) return deactivate(move);
        m_start.reset();
        m_side = interp::CompSide::None;
        emitPlain(move, move.geometry.end);
        drainWindow(0);
        return std::nullopt;
    }
    m_window = move.collisionWindow >= 3 ? move.collisionWindow : 0;
    const bool inPlane = move.geometry.movesInPlane();
    if (move.kind == MoveKind::Rapid) {
        // Feed -> rapid: the feed element ends perpendicular, the rapid move is not compensated;
        // the next feed move starts compensation again.
        finishHeldPerpendicular();
        m_side = move.side;
        emitPlain(move, move.geometry.end);
        m_start = Start::Activation;
        return std::nullopt;
    }
    if (!inPlane) {
        if (m_held) {
            if (++m_blocksWithoutMotion >= kMaxBlocksWithoutMotion) {
                return error(move.location, "compensation",
                             KERF_TR_NOOP("48 blocks without motion in the plane under radius "
                                          "compensation"));
            }
            m_queue.push_back(Queued{std::nullopt, move});
            return std::nullopt;
        }
        // Compensation is taken up here; the first move in the plane starts perpendicular.
        const ContourElement& g = move.geometry;
        const Pose target = withPoint(g, g.end, g.inPlane(m_position));
        // G01 G41 alone moves nothing: no zero-length move in the stream.
        if (target.values != m_position.values) emitPlain(move, target);
        m_side = move.side;
        m_start = Start::AtPoint;
        return std::nullopt;
    }
    if (!m_held) {
        startCompensation(move);
        return std::nullopt;
    }
    if (move.side != m_held->move.side) return changeSide(move);
    return corner(move);
}

}  // namespace kerf::fagor
