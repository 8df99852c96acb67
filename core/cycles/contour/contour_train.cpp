#include "core/cycles/contour/contour_train.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/base/translate.h"
#include "core/cycles/contour/sl_machining.h"
#include "core/geometry/arc_math.h"
#include "core/geometry/contour_region.h"
#include "core/geometry/open_chain_offset.h"

namespace kerf::cycles::contour {

namespace {

Vec2 rotated(const Vec2& v, double angleRad) {
    const double c = std::cos(angleRad);
    const double s = std::sin(angleRad);
    return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

}  // namespace

Chain reversedChain(const Chain& chain) {
    Chain out;
    out.reserve(chain.size());
    for (auto it = chain.rbegin(); it != chain.rend(); ++it)
        out.push_back(it->reversed());
    return out;
}

std::optional<CycleError> trainToolSide(int cycle, const CycleContext& ctx, int& side) {
    side = ctx.train.side;
    if (ctx.trainData == nullptr) return std::nullopt;
    if (side != 0) {
        return contourError(cycle, KERF_TR_NOOP("cycle {1}: with cycle 270 the contour "
                                                "subprogram must be programmed without RL/RR "
                                                "(Q391 gives the side)"));
    }
    const int q391 = ctx.trainData->integer(391);
    side = q391 == 1 ? 1 : q391 == 2 ? -1 : 0;
    return std::nullopt;
}

Chain trainCentrePath(const ContourTrain& train, int side, double distance) {
    if (side == 0 || distance <= 0.0) return train.segments;
    if (!train.closed) {
        auto offset = offsetOpenChain(train.segments, side * distance);
        return offset ? *offset : Chain{};
    }
    // A closed path: the tool inside or outside the area it encloses.
    ClosedContour contour{train.segments};
    const bool counterClockwise = contour.signedArea() > 0.0;
    const bool inside = counterClockwise == (side > 0);
    const Region offset = offsetRegion(regionOf(contour), inside ? -distance : distance);
    const ClosedContour* ring = nullptr;
    for (const ClosedContour& boundary : offset.boundaries) {
        if (boundary.signedArea() <= 0.0) continue;  // a hole closed off outside
        if (ring != nullptr) return {};              // the tool splits the path
        ring = &boundary;
    }
    if (ring == nullptr) return {};
    const ClosedContour directed = counterClockwise ? *ring : ring->reversed();
    return startingNearest(directed, train.segments.front().start).segments;
}

TrainApproach readTrainApproach(const CycleValues* data) {
    TrainApproach a;
    if (data == nullptr) return a;
    a.kind = static_cast<TrainApproach::Kind>(data->integer(390));
    a.radius = data->number(392);
    a.angleRad = data->number(393) * std::numbers::pi / 180.0;
    a.distance = data->number(394);
    // An arc without radius or angle, a line without length: straight down onto the path.
    const bool none = a.kind == TrainApproach::Kind::Arc ? a.radius <= 0.0 || a.angleRad <= 0.0
                                                         : a.distance <= 0.0;
    if (none) a.kind = TrainApproach::Kind::Straight;
    return a;
}

Vec2 approachStart(const TrainApproach& a, const Chain& chain, int freeSide) {
    const Vec2 s = chain.front().start;
    const Vec2 t = chain.front().startTangent();
    const Vec2 n = static_cast<double>(freeSide) * leftNormal(t);
    switch (a.kind) {
        case TrainApproach::Kind::Arc: {
            const Vec2 centre = s + a.radius * n;
            return centre + rotated(s - centre, -freeSide * a.angleRad);
        }
        case TrainApproach::Kind::Tangent:
            return s - a.distance * t;
        case TrainApproach::Kind::Perpendicular:
            return s + a.distance * n;
        case TrainApproach::Kind::Straight:
            break;
    }
    return s;
}

void approachPath(CyclePath& path, const TrainApproach& a, const Chain& chain, int freeSide,
                  const Feed& feed) {
    const Vec2 s = chain.front().start;
    if (a.kind == TrainApproach::Kind::Arc) {
        const Vec2 n = static_cast<double>(freeSide) * leftNormal(chain.front().startTangent());
        path.arc({s.x(), s.y(), path.w()}, s + a.radius * n, freeSide * a.angleRad, feed);
    } else {
        path.moveUv(s, feed);
    }
}

void departPath(CyclePath& path, const TrainApproach& a, const Chain& chain, int freeSide,
                const Feed& feed) {
    const Vec2 e = chain.back().end;
    const Vec2 t = chain.back().endTangent();
    const Vec2 n = static_cast<double>(freeSide) * leftNormal(t);
    switch (a.kind) {
        case TrainApproach::Kind::Arc: {
            const Vec2 centre = e + a.radius * n;
            const Vec2 end = centre + rotated(e - centre, freeSide * a.angleRad);
            path.arc({end.x(), end.y(), path.w()}, centre, freeSide * a.angleRad, feed);
            break;
        }
        case TrainApproach::Kind::Tangent:
            path.moveUv(e + a.distance * t, feed);
            break;
        case TrainApproach::Kind::Perpendicular:
            path.moveUv(e + a.distance * n, feed);
            break;
        case TrainApproach::Kind::Straight:
            break;
    }
}

void followChain(CyclePath& path, const Chain& chain, const Feed& feed) {
    const double w = path.w();
    for (const PlanarSegment& s : chain) {
        if (s.kind == PlanarSegment::Kind::Line) {
            path.moveUv(s.end, feed);
        } else {
            path.arc({s.end.x(), s.end.y(), w}, s.center, s.sweep, feed);
        }
    }
}

namespace {

// Where along the segment (0 ... 1) its point nearest to `p` lies.
double fractionNear(const PlanarSegment& s, const Vec2& p) {
    if (s.kind == PlanarSegment::Kind::Line) {
        const Vec2 d = s.end - s.start;
        const double lengthSquared = d.squaredNorm();
        return lengthSquared > 0.0 ? std::clamp((p - s.start).dot(d) / lengthSquared, 0.0, 1.0)
                                   : 0.0;
    }
    const Vec2 a = s.start - s.center;
    const Vec2 b = p - s.center;
    double angle = std::atan2(cross2(a, b), a.dot(b));  // from the start, counter-clockwise
    if (s.sweep < 0.0) angle = -angle;
    if (angle < 0.0) angle += 2.0 * std::numbers::pi;
    const double sweep = std::fabs(s.sweep);
    if (angle > sweep) {  // beyond the end: the nearer end
        return angle - sweep < 2.0 * std::numbers::pi - angle ? 1.0 : 0.0;
    }
    return sweep > 0.0 ? angle / sweep : 0.0;
}

}  // namespace

double heightNear(const ContourTrain& train, const Vec2& p, bool fromEnd) {
    const size_t n = std::min(train.segments.size(), train.heights.size());
    size_t best = 0;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < n; ++k) {
        const size_t i = fromEnd ? n - 1 - k : k;
        const double d = train.segments[i].distanceTo(p);
        if (d < bestDistance - 1e-9) {
            bestDistance = d;
            best = i;
        }
    }
    if (n == 0) return 0.0;
    const auto [from, to] = train.heights[best];
    return from + (to - from) * fractionNear(train.segments[best], p);
}

void followChain3d(CyclePath& path, const Chain& chain, const ContourTrain& train, double shift,
                   const Feed& feed) {
    for (size_t i = 0; i < chain.size(); ++i) {
        const PlanarSegment& s = chain[i];
        const double w = heightNear(train, s.end, i + 1 == chain.size()) + shift;
        if (s.kind == PlanarSegment::Kind::Line) {
            path.move({s.end.x(), s.end.y(), w}, feed);
        } else {
            path.arc({s.end.x(), s.end.y(), w}, s.center, s.sweep, feed);
        }
    }
}

}  // namespace kerf::cycles::contour
