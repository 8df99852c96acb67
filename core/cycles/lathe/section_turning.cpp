#include "core/cycles/lathe/section_turning.h"

#include <algorithm>
#include <cmath>

#include "core/base/translate.h"
#include "core/geometry/arc_math.h"

namespace kerf::cycles::lathe {

namespace {

constexpr double kTolerance = 1e-9;

// The cycle works in a (cut, step) frame: turning cuts along Z and steps in X, facing the other
// way. Swapping the axes mirrors the plane: arcs turn the other way.
Vec2 swapped(const Vec2& p, bool swap) {
    return swap ? Vec2(p.y(), p.x()) : p;
}

double sign(double v) {
    return v < 0.0 ? -1.0 : 1.0;
}

LatheError positionError(char letter) {
    return {letter,
            "cycle-position",
            KERF_TR_NOOP("the tool position is not correct for the cycle ({1})"),
            {std::string(1, letter)}};
}

// The section in the (cut, step) frame, a line or an arc, as a function of t in [0, 1].
struct Section {
    Vec2 a{0.0, 0.0};
    Vec2 b{0.0, 0.0};
    bool arc = false;
    Vec2 c{0.0, 0.0};
    double r = 0.0;
    double theta0 = 0.0;
    double sweep = 0.0;

    Vec2 at(double t) const {
        if (t <= 0.0) return a;
        if (t >= 1.0) return b;
        if (!arc) return a + t * (b - a);
        const double theta = theta0 + t * sweep;
        return c + r * Vec2(std::cos(theta), std::sin(theta));
    }
    // The parameter where the section reaches step level v (it is monotone in it: a line, or
    // an arc within a quarter circle).
    double atLevel(double v) const {
        if (!arc) {
            const double dy = b.y() - a.y();
            return std::fabs(dy) < kTolerance ? 0.0 : std::clamp((v - a.y()) / dy, 0.0, 1.0);
        }
        const double base = std::asin(std::clamp((v - c.y()) / r, -1.0, 1.0));
        double best = 0.0;
        double bestDistance = HUGE_VAL;
        for (const double angle : {base, kPi - base}) {
            for (const double turn : {-kTwoPi, 0.0, kTwoPi}) {
                const double t = (angle + turn - theta0) / sweep;
                const double distance = t < 0.0 ? -t : t > 1.0 ? t - 1.0 : 0.0;
                if (distance < bestDistance) {
                    bestDistance = distance;
                    best = std::clamp(t, 0.0, 1.0);
                }
            }
        }
        return best;
    }
    Section shifted(const Vec2& d) const {
        Section s = *this;
        s.a += d;
        s.b += d;
        s.c += d;
        return s;
    }
};

}  // namespace

bool expandTurningSection(const TurningSection& section, const Vec2& callZx, LathePath& path,
                          LatheError& error) {
    const bool f = section.facing;
    const Vec2 call = swapped(callZx, f);
    Section s;
    s.a = swapped(section.a, f);
    s.b = swapped(section.b, f);
    if (section.centre) {
        s.arc = true;
        s.c = swapped(*section.centre, f);
        s.r = (s.a - s.c).norm();
        if (std::fabs((s.b - s.c).norm() - s.r) > section.radiusTolerance || s.r < kTolerance) {
            error = {'I',
                     "cycle-geometry",
                     KERF_TR_NOOP("A and B are not on one circle about the centre I, K"),
                     {}};
            return false;
        }
        // The arc of at most half a turn from A to B.
        s.theta0 = std::atan2(s.a.y() - s.c.y(), s.a.x() - s.c.x());
        const double ccw = arcSweep(s.a, s.b, s.c, true);
        s.sweep = ccw <= kPi ? ccw : ccw - 2.0 * kPi;
        // Passes meet it once only if it stays within a quarter circle.
        const double q0 = s.theta0 / (kPi / 2.0);
        const double q1 = (s.theta0 + s.sweep) / (kPi / 2.0);
        if (std::ceil(std::min(q0, q1) + 1e-9) <= std::floor(std::max(q0, q1) - 1e-9)) {
            error = {'I',
                     "cycle-geometry",
                     KERF_TR_NOOP("the arc must stay within a quarter circle from A to B"),
                     {}};
            return false;
        }
    }
    // Allowances along the cut and the step directions of this frame.
    const double allowCut = f ? section.allowanceX : section.allowanceZ;
    const double allowStep = f ? section.allowanceZ : section.allowanceX;
    const double cutDirection = s.b.x() - s.a.x();
    if (std::fabs(cutDirection) < kTolerance) {
        // Turning needs a length along Z, facing along X: the passes run from A towards B.
        error = {f ? 'Q' : 'R',
                 "cycle-geometry",
                 KERF_TR_NOOP("the section has no length along the passes"),
                 {}};
        return false;
    }
    const double sideCut = -sign(cutDirection);        // the call point lies before A
    const double sideStep = sign(call.y() - s.a.y());  // the material lies between call and A
    // Clearance (spec: along X from the call point to B at least L, along Z to A at least M),
    // and B no deeper than A: the section may not turn back under material already passed.
    if (sideStep * (call.y() - s.b.y()) < allowStep - kTolerance ||
        std::fabs(call.y() - s.a.y()) < kTolerance) {
        error = positionError(f ? 'Z' : 'X');
        return false;
    }
    if (sideCut * (call.x() - s.a.x()) < allowCut - kTolerance) {
        error = positionError(f ? 'X' : 'Z');
        return false;
    }
    if (sideStep * (s.b.y() - s.a.y()) < -kTolerance) {
        error = {f ? 'R' : 'Q',
                 "cycle-geometry",
                 KERF_TR_NOOP("the section runs back under the material: B must not be deeper "
                              "than A"),
                 {}};
        return false;
    }
    const Section s1 = s.shifted(Vec2(sideCut * allowCut, sideStep * allowStep));
    auto out = [&](const Vec2& p) { return swapped(p, f); };
    auto onWall = [&](double v) {
        return sideStep * (v - s1.b.y()) >= -kTolerance ||
               std::fabs(s1.b.y() - s1.a.y()) < kTolerance;
    };
    // Where a pass at step level v meets the section plus allowances (beyond B: B's wall).
    auto passEnd = [&](double v) {
        return onWall(v) ? Vec2(s1.b.x(), v) : Vec2(s1.at(s1.atLevel(v)).x(), v);
    };
    // Follows `sec` from its point at parameter t0 to the one at t1.
    auto follow = [&](const Section& sec, double t1, double feed) {
        const Vec2 to = sec.at(t1);
        if (sec.arc) {
            path.arc(out(to), out(sec.c), (sec.sweep > 0.0) != f, feed);
        } else {
            path.feed(out(to), feed);
        }
    };
    const double depth = sideStep * (call.y() - s1.a.y());
    const double count = depth > kTolerance ? std::ceil(depth / section.maxStep - 1e-9) : 0.0;
    if (count * 5 > LathePath::kStepLimit) {
        error = tooManySteps('C');
        return false;
    }
    const int passes = static_cast<int>(count);
    const double step = passes > 0 ? depth / passes : 0.0;
    double previous = call.y();
    for (int k = 1; k <= passes; ++k) {
        const double level = k == passes ? s1.a.y() : call.y() - sideStep * k * step;
        path.rapid(out({call.x(), level}));  // 1-2
        const Vec2 end = passEnd(level);
        path.feed(out(end));  // 2-3
        if (!section.retract) {
            // 3-4 along the section (and up B's wall) to the previous level.
            if (!onWall(level)) follow(s1, onWall(previous) ? 1.0 : s1.atLevel(previous), 0.0);
            path.feed(out(passEnd(previous)));
        } else if (*section.retract > 0.0) {
            const double d = *section.retract;  // 3-4 at 45 degrees
            path.rapid(out(end + Vec2(sideCut * d, sideStep * d)));
        }
        path.rapid(out({call.x(), swapped(path.position(), f).y()}));  // 4-5
        previous = level;
    }
    // Final roughing pass and finishing pass: along the section (plus allowances), up B's wall.
    auto along = [&](const Section& sec, double feed) {
        path.rapid(out({call.x(), sec.a.y()}));
        path.feed(out(sec.a), feed);
        follow(sec, 1.0, feed);
        path.feed(out({sec.b.x(), call.y()}), feed);
        path.rapid(callZx);
    };
    if (section.finalRoughingFeed > 0.0) along(s1, section.finalRoughingFeed);
    if (section.finishingFeed > 0.0) along(s, section.finishingFeed);
    path.rapid(callZx);
    if (path.full()) {
        error = tooManySteps('C');
        return false;
    }
    return true;
}

}  // namespace kerf::cycles::lathe
