#include "core/cycles/thread/thread_helix.h"

#include <cmath>
#include <numbers>

namespace kerf::cycles {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr size_t kMaxPasses = 10000;
constexpr double kMaxTurns = 50000.0;

Vec2 polar(double radius, double angle) {
    return radius * Vec2(std::cos(angle), std::sin(angle));
}
}  // namespace

bool cutsTowardsSurface(double pitch, int climbOrUpCut, bool outside) {
    const bool climb = climbOrUpCut >= 0;
    const bool rightHand = pitch > 0.0;
    return (rightHand == climb) != outside;
}

bool threadCcw(double pitch, double dw) {
    return (pitch > 0.0) == (dw > 0.0);
}

void millThreadPass(CyclePath& path, const ThreadHelix& h, double wStart, double turns) {
    const double dir = h.ccw ? 1.0 : -1.0;
    const double half = h.dw * h.pitch / 2.0;
    const Vec2 contact = h.centre + Vec2(h.radius, 0.0);
    if (h.outside) {
        // From the start point outside the stud on a half circle turning against the thread,
        // which meets the thread path tangentially.
        const double a = h.pitch;
        path.moveW(wStart - half, h.prePosition);
        path.arc({contact.x(), contact.y(), wStart}, h.centre + Vec2(h.radius + a, 0.0), -dir * kPi,
                 h.approach);
    } else {
        path.moveW(wStart - half, h.prePosition);
        path.arc({contact.x(), contact.y(), wStart}, h.centre + Vec2(h.radius / 2.0, 0.0),
                 dir * kPi, h.approach);
    }
    const auto whole = static_cast<size_t>(std::floor(turns + 1e-9));
    const double rest = turns - static_cast<double>(whole);
    double w = wStart;
    for (size_t i = 0; i < whole && !path.limitReached(); ++i) {
        w += h.dw * h.pitch;
        path.arc({contact.x(), contact.y(), w}, h.centre, dir * 2.0 * kPi, h.mill);
    }
    double endAngle = 0.0;
    if (rest > 1e-9) {
        endAngle = dir * 2.0 * kPi * rest;
        w += h.dw * h.pitch * rest;
        const Vec2 end = h.centre + polar(h.radius, endAngle);
        path.arc({end.x(), end.y(), w}, h.centre, endAngle, h.mill);
    }
    const Vec2 end = h.centre + polar(h.radius, endAngle);
    if (h.outside) {
        const double a = h.pitch;
        const Vec2 out = h.centre + polar(h.radius + 2.0 * a, endAngle);
        path.arc({out.x(), out.y(), w + half}, h.centre + polar(h.radius + a, endAngle), -dir * kPi,
                 h.approach);
        // Around the stud, outside the thread, back to the start point.
        const Vec2 start = h.centre + Vec2(h.radius + 2.0 * a, 0.0);
        path.arc({start.x(), start.y(), w + half}, h.centre, -endAngle, h.prePosition);
    } else {
        path.arc({h.centre.x(), h.centre.y(), w + half}, (h.centre + end) / 2.0, dir * kPi,
                 h.approach);
    }
}

std::vector<ThreadPass> threadPasses(double depth, double pitch, int perStep, bool towardsSurface) {
    std::vector<ThreadPass> passes;
    const double totalTurns = depth / pitch;
    if (perStep == 0) {
        // One revolution ending (or starting) at the bottom of the thread.
        passes.push_back({towardsSurface ? depth : depth - pitch, 1.0});
        return passes;
    }
    if (totalTurns > kMaxTurns) return passes;
    const double step = perStep == 1 ? totalTurns : static_cast<double>(perStep);
    double done = 0.0;
    while (done < totalTurns - 1e-9) {
        if (passes.size() >= kMaxPasses) return {};
        const double turns = std::min(step, totalTurns - done);
        const double startDepth = towardsSurface ? depth - done * pitch : done * pitch;
        passes.push_back({startDepth, turns});
        done += turns;
    }
    return passes;
}

Feed centreFeed(const Feed& edgeFeed, double nominalRadius, double pathRadius) {
    Feed f = edgeFeed;
    if (!f.isRapid() && nominalRadius > 0.0) f.value = f.value * pathRadius / nominalRadius;
    return f;
}

void frontCircle(CyclePath& path, const Vec2& centre, double radius, bool ccw, const Feed& feed) {
    if (radius <= 0.0) return;
    const double dir = ccw ? 1.0 : -1.0;
    const double w = path.w();
    const Vec2 out = centre + Vec2(radius, 0.0);
    const Vec2 middle = centre + Vec2(radius / 2.0, 0.0);
    path.arc({out.x(), out.y(), w}, middle, dir * kPi, feed);
    path.arc({out.x(), out.y(), w}, centre, dir * 2.0 * kPi, feed);
    path.arc({centre.x(), centre.y(), w}, middle, dir * kPi, feed);
}

}  // namespace kerf::cycles
