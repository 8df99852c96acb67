#include "core/interp/path/offset_junction.h"

#include <cmath>
#include <vector>

#include "core/base/translate.h"

namespace kerf::interp {

namespace {

constexpr double kEps = 1e-9;
constexpr double kTangentTurn = 1e-7;  // radians below which a junction counts as tangent

bool isLine(const ContourElement& e) {
    return e.kind == ContourElement::Kind::Line;
}

// e from its start to the point p at parameter t; a line may be lengthened beyond its end.
ContourElement endAt(const ContourElement& e, double t, const Vec2& p) {
    ContourElement out = t <= 1.0 ? e.sub(0.0, t) : e;
    out.setInPlane(out.end, p);  // exactly on p despite rounding in sub()
    return out;
}

// e from the point p at parameter t to its end; a line may begin before its start.
ContourElement startAt(const ContourElement& e, double t, const Vec2& p) {
    ContourElement out = t >= 0.0 ? e.sub(t, 1.0) : e;
    out.setInPlane(out.start, p);
    return out;
}

// Signed angle from a to b about a centre, turning in the direction of `sign` (+1 ccw, -1 cw).
double turnFrom(const Vec2& a, const Vec2& b, double sign) {
    double angle = std::atan2(cross2(a, b), a.dot(b));
    if (sign < 0.0 && angle > kEps) angle -= kTwoPi;
    if (sign > 0.0 && angle < -kEps) angle += kTwoPi;
    return angle;
}

// A full circle of the tool radius around a contour point, to intersect with an offset.
ContourElement circleAround(const ContourElement& frame, const Vec2& center, double radius) {
    Pose start = frame.start;
    frame.setInPlane(start, center + Vec2(radius, 0.0));
    return ContourElement::arc(frame.plane, start, start, center, kTwoPi);
}

std::optional<OffsetJunction> byCarriers(const ContourElement& before, const ContourElement& after,
                                         const Vec2& gap) {
    if (isLine(before) && isLine(after)) {
        // On one line in the same direction: straight on to the start of the later offset.
        const Vec2 d = (before.end2() - before.start2()).normalized();
        const Vec2 e = (after.end2() - after.start2()).normalized();
        const double across = std::fabs(cross2(d, after.start2() - before.start2()));
        const double t = before.paramOf(after.start2());
        if (std::fabs(cross2(d, e)) < kTangentTurn && d.dot(e) > 0.0 && across < 1e-9 && t > kEps) {
            return OffsetJunction{endAt(before, t, after.start2()), std::nullopt, after};
        }
    }
    std::optional<OffsetJunction> best;
    double bestDistance = 1e300;
    for (const Vec2& p : intersectCarriers(before, after)) {
        const double ta = before.paramOf(p);
        const double tb = after.paramOf(p);
        if (ta <= kEps || tb >= 1.0 - kEps) continue;
        if ((!isLine(before) && ta > 1.0 + kEps) || (!isLine(after) && tb < -kEps)) continue;
        const double distance = (p - gap).norm();
        if (distance < bestDistance) {
            bestDistance = distance;
            best = OffsetJunction{endAt(before, ta, p), std::nullopt, startAt(after, tb, p)};
        }
    }
    return best;
}

// The tool touches the end of a: an arc around it from the end of a's offset to b's offset.
std::optional<OffsetJunction> aroundEndOfA(const ContourElement& before, const ContourElement& a,
                                           const ContourElement& after, double offset) {
    const Vec2 corner = a.end2();
    const double sign = offset > 0.0 ? -1.0 : 1.0;
    std::optional<OffsetJunction> best;
    double bestSweep = kPi;
    for (const Vec2& p : intersectCarriers(circleAround(a, corner, std::fabs(offset)), after)) {
        const double tb = after.paramOf(p);
        if (tb < -kEps || tb >= 1.0 - kEps) continue;
        const double sweep = turnFrom(before.end2() - corner, p - corner, sign);
        if (std::fabs(sweep) >= bestSweep) continue;
        bestSweep = std::fabs(sweep);
        OffsetJunction j{before, std::nullopt, startAt(after, std::max(tb, 0.0), p)};
        if (std::fabs(sweep) > kTangentTurn) {
            j.transition = ContourElement::arc(a.plane, before.end, j.after.start, corner, sweep);
        }
        best = j;
    }
    return best;
}

// The tool touches the start of b: a's offset ends where an arc around it reaches b's offset.
std::optional<OffsetJunction> aroundStartOfB(const ContourElement& before, const ContourElement& b,
                                             const ContourElement& after, double offset) {
    const Vec2 corner = b.start2();
    const double sign = offset > 0.0 ? -1.0 : 1.0;
    std::optional<OffsetJunction> best;
    double bestSweep = kPi;
    for (const Vec2& p : intersectCarriers(circleAround(b, corner, std::fabs(offset)), before)) {
        const double ta = before.paramOf(p);
        if (ta <= kEps || ta > 1.0 + kEps) continue;
        const double sweep = turnFrom(p - corner, after.start2() - corner, sign);
        if (std::fabs(sweep) >= bestSweep) continue;
        bestSweep = std::fabs(sweep);
        OffsetJunction j{endAt(before, std::min(ta, 1.0), p), std::nullopt, after};
        if (std::fabs(sweep) > kTangentTurn) {
            j.transition = ContourElement::arc(b.plane, j.before.end, after.start, corner, sweep);
        }
        best = j;
    }
    return best;
}

}  // namespace

JunctionOutcome joinAdjacent(const ContourElement& beforeTool, const ContourElement& a,
                             const ContourElement& b, double offset, bool activation) {
    JunctionOutcome out;
    auto next = offsetElement(b, offset);
    if (!next) {
        out.failure = {true, KERF_TR_NOOP("tool radius too large for this arc")};
        return out;
    }
    ContourElement before = beforeTool;
    std::optional<ContourElement> transition;
    if (activation) {
        Pose end = a.end;
        a.setInPlane(end, b.start2() + offset * leftNormal(b.startTangent()));
        before = ContourElement::line(a.plane, before.start, end);
        out.junction = OffsetJunction{before, transition, *next};
        return out;
    }
    const double turn = turnAngle(a, b);
    const bool tangent = std::fabs(turn) < kTangentTurn;
    const bool reversal = std::fabs(std::fabs(turn) - kPi) < kTangentTurn;
    if (std::fabs(offset) < kEps || tangent) {
        // Offsets of tangent elements meet at the same point.
    } else if (reversal || offset * turn < 0.0) {
        // Outside corner: arc around the programmed corner point.
        double sweep = reversal ? (offset > 0.0 ? -kPi : kPi) : turn;
        transition = ContourElement::arc(a.plane, before.end, next->start, a.end2(), sweep);
    } else {
        // Inside corner: both offsets end at their intersection nearest to the corner.
        std::vector<Vec2> points = intersectCarriers(before, *next);
        const Vec2 corner = a.end2();
        const Vec2* best = nullptr;
        for (const Vec2& p : points) {
            if (!best || (p - corner).squaredNorm() < (*best - corner).squaredNorm()) best = &p;
        }
        if (!best) {
            out.failure = {true, KERF_TR_NOOP("tool radius too large")};
            return out;
        }
        const double tHeld = before.paramOf(*best);
        const double tNext = next->paramOf(*best);
        const char* swallowed =
            KERF_TR_NOOP("tool radius too large: the offset swallows this element");
        if (tHeld <= kEps) {
            out.failure = {false, swallowed};
            return out;
        }
        if (tNext >= 1.0 - kEps) {
            out.failure = {true, swallowed};
            return out;
        }
        before = endAt(before, std::min(tHeld, 1.0), *best);
        *next = startAt(*next, std::max(tNext, 0.0), *best);
    }
    out.junction = OffsetJunction{before, transition, *next};
    return out;
}

std::optional<OffsetJunction> bridgeOffsets(const ContourElement& beforeTool,
                                            const ContourElement& a, const ContourElement& b,
                                            double offset) {
    auto after = offsetElement(b, offset);
    if (!after || std::fabs(offset) < kEps) return std::nullopt;
    const Vec2 gap = 0.5 * (a.end2() + b.start2());
    if (auto j = byCarriers(beforeTool, *after, gap)) return j;
    if (auto j = aroundEndOfA(beforeTool, a, *after, offset)) return j;
    return aroundStartOfB(beforeTool, b, *after, offset);
}

}  // namespace kerf::interp
