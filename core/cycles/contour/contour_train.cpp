#include "core/cycles/contour/contour_train.h"

#include <cmath>
#include <numbers>

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

}  // namespace kerf::cycles::contour
