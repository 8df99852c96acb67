#include "core/cycles/pocket/milling_setup.h"

#include <cmath>
#include <numbers>

#include "core/base/translate.h"

namespace kerf::cycles::pocket {

namespace {

constexpr size_t kMaxLevels = 10000;

double cross(const Vec2& a, const Vec2& b) {
    return a.x() * b.y() - a.y() * b.x();
}

Feed scaled(const Feed& feed, double factor) {
    Feed out = feed;
    if (!feed.isRapid()) out.value *= factor;
    return out;
}

}  // namespace

std::optional<CycleError> readSetup(int cycle, const CycleValues& v, const CycleContext& ctx,
                                    MillingSetup& s) {
    s.cycle = cycle;
    const int operation = v.has(215) ? v.integer(215) : 0;
    s.rough = operation != 2;
    s.finish = operation != 1;
    s.sideAllowance = v.number(368);
    s.floorAllowance = v.number(369);
    s.infeed = v.number(202);
    // A shorter cutting length LCUTS limits the infeed (spec §4 intro).
    if (ctx.tool.cuttingLength > 0.0 && (s.infeed <= 0.0 || ctx.tool.cuttingLength < s.infeed)) {
        s.infeed = ctx.tool.cuttingLength;
    }
    s.finishInfeed = v.number(338);
    s.overlap = v.has(370) ? v.number(370) : 1.0;
    s.plunge = static_cast<Plunge>(v.has(366) ? v.integer(366) : 0);
    s.feedReference = v.integer(439);
    s.mill = v.feed(207);
    s.plungeFeed = v.feed(206);
    s.finishFeed = v.has(385) ? v.feed(385) : v.feed(207);
    if (s.finishFeed.isZero()) s.finishFeed = s.mill;
    s.depth = std::fabs(v.number(201));
    s.setUpClearance = v.number(200);
    s.levels = holeLevels(v, v.number(201));
    // Q351 0 counts as climb; a mirror image reverses the path, so the direction is swapped
    // to keep the milling type (as in cycle 208).
    s.climb = v.integer(351) >= 0;
    if (ctx.mirroredMain != ctx.mirroredSecondary) s.climb = !s.climb;
    s.tool = ctx.tool;
    if (auto e = checkDepthSign(cycle, 201, v.number(201), ctx)) return e;
    if (ctx.tool.radius <= 0.0) {
        return CycleError{"cycle-tool",
                          KERF_TR_NOOP("cycle {1} needs a tool with a radius greater than 0"),
                          {std::to_string(cycle)}};
    }
    if (s.plunge != Plunge::Vertical && ctx.tool.plungeAngleDeg <= 0.0) {
        return CycleError{"cycle-tool",
                          KERF_TR_NOOP("cycle {1}: helical or reciprocating plunging (Q366) "
                                       "needs the plunge angle ANGLE of the tool"),
                          {std::to_string(cycle)}};
    }
    return std::nullopt;
}

std::optional<CycleError> stepLevels(const MillingSetup& s, double fromDepth, double toDepth,
                                     double step, std::vector<double>& levels) {
    levels.clear();
    const double span = toDepth - fromDepth;
    if (span <= 1e-9) return std::nullopt;
    const double count = step > 0.0 ? std::ceil(span / step - 1e-9) : 1.0;
    if (count > static_cast<double>(kMaxLevels)) return tooManyMoves(s.cycle);
    const int n = static_cast<int>(count);
    for (int k = 1; k <= n; ++k)
        levels.push_back(s.levels.at(k == n ? toDepth : fromDepth + k * step));
    return std::nullopt;
}

Vec2 Placement::point(const Vec2& local) const {
    const double c = std::cos(angleRad);
    const double s = std::sin(angleRad);
    return origin + Vec2(c * local.x() - s * local.y(), s * local.x() + c * local.y());
}

void followContour(CyclePath& path, const ClosedContour& contour, const Feed& feed,
                   double edgeOffset) {
    const auto& segments = contour.segments;
    const double w = path.w();
    for (size_t i = 0; i < segments.size(); ++i) {
        const PlanarSegment& s = segments[i];
        if (s.kind == PlanarSegment::Kind::Line) {
            path.moveUv(s.end, feed);
            continue;
        }
        double sweep = s.sweep;
        Vec2 end = s.end;
        while (i + 1 < segments.size() && segments[i + 1].kind == PlanarSegment::Kind::Arc &&
               (segments[i + 1].center - s.center).norm() < 1e-9 &&
               std::fabs(segments[i + 1].radius() - s.radius()) < 1e-9 &&
               std::fabs(sweep + segments[i + 1].sweep) <= 2.0 * std::numbers::pi + 1e-9) {
            ++i;
            sweep += segments[i].sweep;
            end = segments[i].end;
        }
        const double r = s.radius();
        const double factor =
            edgeOffset != 0.0 && r + edgeOffset > 0.0 ? r / (r + edgeOffset) : 1.0;
        path.arc({end.x(), end.y(), w}, s.center, sweep, scaled(feed, factor));
    }
}

// Zig-zag along `stroke` down to `toW`, then strokes at the depth to flatten the ramp and end
// where the stroke starts (the core's start: in a circular slot a straight way back would leave
// the slot).
void reciprocateDown(CyclePath& path, const PlanarSegment& stroke, double toW, double drop,
                     const Feed& feed) {
    bool forward = true;
    auto go = [&](double w) {
        const PlanarSegment s = forward ? stroke : stroke.reversed();
        if (s.kind == PlanarSegment::Kind::Arc) {
            path.arc({s.end.x(), s.end.y(), w}, s.center, s.sweep, feed);
        } else {
            path.move({s.end.x(), s.end.y(), w}, feed);
        }
        forward = !forward;
    };
    // `drop` is signed like the infeed direction (positive when moving down in w).
    while ((path.w() - toW) * drop > 1e-9) {
        const double next = path.w() - drop;
        go((next - toW) * drop > 0.0 ? next : toW);
    }
    go(toW);
    if (!forward) go(toW);
}

Vec2 approachStart(const ClosedContour& contour, const Vec2& normal, double radius) {
    const PlanarSegment& first = contour.segments.front();
    return first.start + radius * (normal - first.startTangent());
}

void approachArc(CyclePath& path, const ClosedContour& contour, const Vec2& normal, double radius,
                 const Feed& feed) {
    const PlanarSegment& first = contour.segments.front();
    const Vec2 t = first.startTangent();
    const Vec2 centre = first.start + radius * normal;
    const double sweep = (cross(-t, -normal) >= 0.0 ? 1.0 : -1.0) * std::numbers::pi / 2.0;
    path.arc({first.start.x(), first.start.y(), path.w()}, centre, sweep, feed);
}

void departureArc(CyclePath& path, const ClosedContour& contour, const Vec2& normal, double radius,
                  const Feed& feed) {
    const PlanarSegment& last = contour.segments.back();
    const Vec2 t = last.endTangent();
    const Vec2 centre = last.end + radius * normal;
    const Vec2 end = centre + radius * t;
    const double sweep = (cross(-normal, t) >= 0.0 ? 1.0 : -1.0) * std::numbers::pi / 2.0;
    path.arc({end.x(), end.y(), path.w()}, centre, sweep, feed);
}

CycleError toolTooLarge(int cycle) {
    return CycleError{"cycle-tool",
                      KERF_TR_NOOP("cycle {1}: the tool is too large for the programmed size "
                                   "and finishing allowance"),
                      {std::to_string(cycle)}};
}

}  // namespace kerf::cycles::pocket
