#include "core/interp/fagor/contour_shaper.h"

#include <cmath>

#include "core/base/translate.h"
#include "core/interp/fagor/tangent_arcs.h"

namespace kerf::fagor {

namespace {

constexpr double kEps = 1e-9;

interp::PathError error(const SourceLocation& at, const char* message) {
    return interp::PathError{at, "contour", message, {}};
}

bool hasRequest(const Move& m) {
    return m.request.corner != ContourRequest::Corner::None || m.request.entryRadius > 0.0;
}

Pose withPoint(const ContourElement& frame, Pose pose, const Vec2& p) {
    frame.setInPlane(pose, p);
    return pose;
}

}  // namespace

std::optional<interp::PathError> ContourShaper::forward(const Move& move) {
    Move plain = move;
    plain.request = ContourRequest{};
    return m_next.add(plain);
}

void ContourShaper::addCommand(canon::Command command) {
    if (m_held) {
        m_after.push_back(std::move(command));
    } else {
        m_next.addCommand(std::move(command));
    }
}

std::optional<interp::PathError> ContourShaper::add(const Move& move) {
    if (hasRequest(move) && move.kind == MoveKind::Thread) {
        return error(move.location,
                     KERF_TR_NOOP("G36, G37, G38 and G39 cannot be used in a thread"));
    }
    if (!m_held) {
        if (hasRequest(move)) {
            if (!move.geometry.movesInPlane()) {
                return error(move.location,
                             KERF_TR_NOOP("G36, G37, G38 and G39 need a move in the plane"));
            }
            m_held = move;
            return std::nullopt;
        }
        return forward(move);
    }
    Move first = *m_held;
    m_held.reset();
    return resolve(first, move);
}

std::optional<interp::PathError> ContourShaper::resolve(Move first, Move next) {
    if (!next.geometry.movesInPlane()) {
        return error(first.location,
                     KERF_TR_NOOP("the next block must be a contour element in the plane"));
    }
    // The pieces `first` becomes, in order; a corner acts on the last one.
    std::vector<Move> pieces;
    if (first.request.entryRadius > 0.0) {
        const ContourElement& g = first.geometry;
        if (g.kind != ContourElement::Kind::Line) {
            return error(first.location, KERF_TR_NOOP("G37 needs a straight line (G00 or G01)"));
        }
        auto arc = tangentialEntry(g.start2(), g.end2(), next.geometry.startTangent(),
                                   first.request.entryRadius);
        if (!arc) {
            return error(first.location,
                         KERF_TR_NOOP("G37: the start point lies inside the entry circle"));
        }
        Move line = first;
        line.geometry =
            ContourElement::line(g.plane, g.start, withPoint(g, g.end, arc->tangentPoint));
        pieces.push_back(line);
        if (std::fabs(arc->sweep) > kEps) {
            Move entry = first;
            entry.kind = MoveKind::Feed;
            entry.geometry =
                ContourElement::arc(g.plane, line.geometry.end, g.end, arc->center, arc->sweep);
            pieces.push_back(entry);
        }
    } else {
        pieces.push_back(first);
    }
    Move& last = pieces.back();
    Move inserted = last;
    inserted.kind = MoveKind::Feed;
    bool insert = false;
    const double size = first.request.cornerSize;
    switch (first.request.corner) {
        case ContourRequest::Corner::None:
            break;
        case ContourRequest::Corner::Round: {
            auto f = fillet(last.geometry, next.geometry, size);
            if (!f) {
                return error(
                    first.location,
                    KERF_TR_NOOP("G36: the rounding radius does not fit between the elements"));
            }
            last.geometry = last.geometry.sub(0.0, f->paramOnA);
            next.geometry = next.geometry.sub(f->paramOnB, 1.0);
            inserted.geometry = ContourElement::arc(last.geometry.plane, last.geometry.end,
                                                    next.geometry.start, f->center, f->sweep);
            insert = true;
            break;
        }
        case ContourRequest::Corner::Chamfer: {
            const ContourElement& a = last.geometry;
            const ContourElement& b = next.geometry;
            if (a.kind != ContourElement::Kind::Line || b.kind != ContourElement::Kind::Line) {
                return error(first.location,
                             KERF_TR_NOOP("G39 needs straight lines on both sides"));
            }
            const double la = a.planarLength();
            const double lb = b.planarLength();
            if (size >= la - kEps || size >= lb - kEps) {
                return error(first.location,
                             KERF_TR_NOOP("G39: the chamfer is longer than an adjacent line"));
            }
            last.geometry = a.sub(0.0, 1.0 - size / la);
            next.geometry = b.sub(size / lb, 1.0);
            inserted.geometry =
                ContourElement::line(a.plane, last.geometry.end, next.geometry.start);
            insert = true;
            break;
        }
        case ContourRequest::Corner::TangentExit: {
            if (next.geometry.kind != ContourElement::Kind::Line || next.kind == MoveKind::Thread) {
                return error(
                    next.location,
                    KERF_TR_NOOP("the block after G38 must be a straight line (G00 or G01)"));
            }
            const ContourElement& a = last.geometry;
            auto arc = tangentialExit(a.end2(), a.endTangent(), next.geometry.end2(), size);
            if (!arc) {
                return error(first.location,
                             KERF_TR_NOOP("G38: the end point lies inside the exit circle"));
            }
            if (std::fabs(arc->sweep) > kEps) {
                inserted.geometry =
                    ContourElement::arc(a.plane, a.end, withPoint(a, a.end, arc->tangentPoint),
                                        arc->center, arc->sweep);
                insert = true;
                next.geometry =
                    ContourElement::line(a.plane, inserted.geometry.end, next.geometry.end);
            }
            break;
        }
    }
    for (const Move& piece : pieces) {
        if (auto e = forward(piece)) return e;
    }
    for (canon::Command& c : m_after)
        m_next.addCommand(std::move(c));
    m_after.clear();
    if (insert) {
        if (auto e = forward(inserted)) return e;
    }
    if (hasRequest(next)) {
        m_held = next;
        return std::nullopt;
    }
    return forward(next);
}

std::optional<interp::PathError> ContourShaper::flush() {
    if (!m_held) return std::nullopt;
    const SourceLocation at = m_held->location;
    m_held.reset();
    m_after.clear();
    return error(at, KERF_TR_NOOP("G36, G37, G38 and G39 need a following contour element"));
}

}  // namespace kerf::fagor
