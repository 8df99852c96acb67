#include "core/cycles/pocket/stud_machining.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/contour_region.h"

namespace kerf::cycles::pocket {

namespace {

constexpr size_t kMaxPasses = 10000;

}  // namespace

std::optional<CycleError> machineStud(const MillingSetup& s, const StudShape& shape,
                                      CyclePath& path) {
    if (s.depth == 0.0) return std::nullopt;
    const double radius = s.tool.radius;
    const HoleLevels& l = s.levels;
    const Placement& place = shape.placement;
    // Climb milling with M3 runs clockwise round a stud.
    auto oriented = [&](const ClosedContour& c) {
        return place.contour(s.climb ? c.reversed() : c);
    };
    const double inset = radius + s.sideAllowance;
    const double margin = std::max(0.0, shape.margin);
    const double step = s.overlap * radius;
    const double count = std::max(1.0, std::ceil(margin / step - 1e-9));
    if (count > static_cast<double>(kMaxPasses)) return tooManyMoves(s.cycle);
    const int n = static_cast<int>(count);
    std::vector<ClosedContour> passes;
    for (int k = 1; k <= n; ++k) {
        auto pass = offsetClosed(shape.stud, inset + margin * (n - k) / n);
        if (!pass) return toolTooLarge(s.cycle);
        passes.push_back(oriented(*pass));
    }
    auto wall = offsetClosed(shape.stud, radius);
    if (!wall) return toolTooLarge(s.cycle);
    ClosedContour finishRing = oriented(*wall);
    Vec2 outward = place.point({1, 0}) - place.point({0, 0});
    const double arcRadius = kBesideBlankMm;
    Vec2 startPoint = place.point(shape.stud.segments.front().start) +
                      (s.sideAllowance + margin + radius + kBesideBlankMm) * outward;
    if (shape.startCorner) {
        // Every pass is an offset of the stud: their points nearest the corner lie on one ray
        // from the stud (about the same corner centre), along which the tool steps inwards.
        startPoint = place.point(*shape.startCorner);
        for (ClosedContour& pass : passes)
            pass = startingNearest(pass, startPoint);
        finishRing = startingNearest(finishRing, startPoint);
        outward = (startPoint - passes.front().segments.front().start).normalized();
    }

    // One depth: down beside the blank, passes inwards, out on a quarter arc, back to the start.
    auto machineAt = [&](double level, const std::vector<ClosedContour>& rings, const Feed& feed) {
        if ((path.uv() - startPoint).norm() > 1e-9) {
            path.rapidUv(startPoint);
            path.rapidW(l.clearance);
        }
        path.moveW(level, s.plungeFeed);
        path.moveUv(approachStart(rings.front(), outward, arcRadius), feed);
        approachArc(path, rings.front(), outward, arcRadius, feed);
        for (size_t k = 0; k < rings.size(); ++k) {
            if (k > 0) path.moveUv(rings[k].segments.front().start, feed);
            followContour(path, rings[k], feed, 0.0);
        }
        departureArc(path, rings.back(), outward, arcRadius, feed);
        path.moveUv(startPoint, feed);
    };

    if ((path.w() - l.top) * l.up < 0.0) path.rapidW(l.top);
    if (s.rough) {
        std::vector<double> levels;
        const double roughDepth = std::max(0.0, s.depth - s.floorAllowance);
        if (auto e = stepLevels(s, 0.0, roughDepth, s.infeed, levels)) return e;
        for (double level : levels)
            machineAt(level, passes, s.mill);
    }
    if (s.finish && s.sideAllowance > 0.0) {
        std::vector<double> levels;
        if (auto e = stepLevels(s, 0.0, s.depth, s.finishInfeed, levels)) return e;
        for (double level : levels)
            machineAt(level, {finishRing}, s.finishFeed);
    }
    if (s.finish && s.floorAllowance > 0.0) machineAt(l.at(s.depth), passes, s.finishFeed);
    path.rapidW(l.top);
    return std::nullopt;
}

}  // namespace kerf::cycles::pocket
