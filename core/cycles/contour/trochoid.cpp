#include "core/cycles/contour/trochoid.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/geometry/arc_math.h"

namespace kerf::cycles::contour {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

Vec2 rotated(const Vec2& v, double angleRad) {
    const double c = std::cos(angleRad);
    const double s = std::sin(angleRad);
    return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

}  // namespace

double chainLength(const Chain& chain) {
    double sum = 0.0;
    for (const PlanarSegment& s : chain)
        sum += s.length();
    return sum;
}

ChainPoint chainPointAt(const Chain& chain, double s) {
    for (size_t i = 0; i < chain.size(); ++i) {
        const PlanarSegment& seg = chain[i];
        const double length = seg.length();
        if (s > length + 1e-9 && i + 1 < chain.size()) {
            s -= length;
            continue;
        }
        const double f = length > 0.0 ? std::clamp(s / length, 0.0, 1.0) : 0.0;
        if (seg.kind == PlanarSegment::Kind::Line) {
            return {seg.start + f * (seg.end - seg.start), seg.startTangent(), i};
        }
        const Vec2 point = seg.center + rotated(seg.start - seg.center, f * seg.sweep);
        const Vec2 radial = (point - seg.center).normalized();
        const Vec2 tangent = seg.sweep >= 0.0 ? leftNormal(radial) : Vec2(-leftNormal(radial));
        return {point, tangent, i};
    }
    return {};
}

std::vector<double> loopStations(double length, double pitch) {
    std::vector<double> out{0.0};
    if (pitch <= 0.0) return out;
    for (double s = pitch; s < length - 1e-9; s += pitch)
        out.push_back(s);
    if (length > 1e-9) out.push_back(length);
    return out;
}

void runTrochoid(CyclePath& path, const Chain& chain, const Trochoid& t, const Feed& feed) {
    const double w = path.w();
    if (t.loopRadius <= 1e-9) {
        followChain(path, chain, feed);
        return;
    }
    // Links run on the side where the circle moves forwards: right of the line for
    // counter-clockwise loops, left for clockwise ones.
    const double side = t.counterClockwise ? -1.0 : 1.0;
    const double sweep = t.counterClockwise ? kTwoPi : -kTwoPi;
    const double edge = t.loopRadius + t.edgeOffset;
    Feed loopFeed = feed;
    if (t.edgeOffset != 0.0 && edge > 0.0 && !feed.isRapid()) {
        loopFeed.value *= t.loopRadius / edge;
    }
    const std::vector<double> stations = loopStations(chainLength(chain), t.pitch);
    ChainPoint previous{};
    for (size_t k = 0; k < stations.size(); ++k) {
        const ChainPoint c = chainPointAt(chain, stations[k]);
        const Vec2 side0 = c.point + side * t.loopRadius * leftNormal(c.tangent);
        const PlanarSegment& seg = chain[c.segment];
        const bool onOneArc = k > 0 && previous.segment == c.segment &&
                              seg.kind == PlanarSegment::Kind::Arc &&
                              (side0 - seg.center).norm() > 1e-6;
        if (onOneArc) {
            const double advance = (stations[k] - stations[k - 1]) / seg.radius();
            path.arc({side0.x(), side0.y(), w}, seg.center, seg.sweep >= 0.0 ? advance : -advance,
                     feed);
        } else {
            path.moveUv(side0, feed);
        }
        path.arc({side0.x(), side0.y(), w}, c.point, sweep, loopFeed);
        previous = c;
    }
    path.moveUv(chain.back().end, feed);
}

}  // namespace kerf::cycles::contour
