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

// One element in the (cut, step) frame, a line or an arc, as a function of t in [0, 1].
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
    // The parameter where the element reaches step level v (it is monotone in it: a line, or
    // an arc within a quarter circle); a flat element is reached at its start.
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
};

// The profile as a chain of elements, parameter t in [0, n].
struct Chain {
    std::vector<Section> parts;

    double size() const { return static_cast<double>(parts.size()); }
    Vec2 start() const { return parts.front().a; }
    Vec2 end() const { return parts.back().b; }
    Vec2 at(double t) const {
        const double i = std::clamp(std::floor(t), 0.0, size() - 1.0);
        return parts[static_cast<size_t>(i)].at(t - i);
    }
    // The first parameter where the chain, growing steadily, reaches step level v.
    double atLevel(double v, double side) const {
        for (size_t i = 0; i < parts.size(); ++i) {
            if (side * (parts[i].b.y() - v) >= -kTolerance) {
                return static_cast<double>(i) + parts[i].atLevel(v);
            }
        }
        return size();
    }
    Chain shifted(const Vec2& d) const {
        Chain moved = *this;
        for (Section& p : moved.parts) {
            p.a += d;
            p.b += d;
            p.c += d;
        }
        return moved;
    }
};

}  // namespace

bool shortArcIsCcw(const Vec2& a, const Vec2& b, const Vec2& centre) {
    return arcSweep(a, b, centre, true) <= kPi;
}

bool expandTurningSection(const TurningSection& section, const Vec2& callZx, LathePath& path,
                          LatheError& error) {
    const bool f = section.facing;
    const Vec2 call = swapped(callZx, f);
    Chain chain;
    Vec2 from = swapped(section.start, f);
    for (const ProfileElement& e : section.elements) {
        Section s;
        s.a = from;
        s.b = swapped(e.end, f);
        from = s.b;
        if (e.centre) {
            s.arc = true;
            s.c = swapped(*e.centre, f);
            s.r = (s.a - s.c).norm();
            if (std::fabs((s.b - s.c).norm() - s.r) > section.radiusTolerance || s.r < kTolerance) {
                error = {'I',
                         "cycle-geometry",
                         KERF_TR_NOOP("the start and the end of an arc are not on one circle "
                                      "about its centre"),
                         {}};
                return false;
            }
            // Swapping the axes mirrors the plane: the turning sense flips.
            s.theta0 = std::atan2(s.a.y() - s.c.y(), s.a.x() - s.c.x());
            s.sweep = arcSweep(s.a, s.b, s.c, e.ccw != f);
            // Passes meet it once only if it stays within a quarter circle.
            const double q0 = s.theta0 / (kPi / 2.0);
            const double q1 = (s.theta0 + s.sweep) / (kPi / 2.0);
            if (std::ceil(std::min(q0, q1) + 1e-9) <= std::floor(std::max(q0, q1) - 1e-9)) {
                error = {'I',
                         "cycle-geometry",
                         KERF_TR_NOOP("an arc of the profile must stay within a quarter circle"),
                         {}};
                return false;
            }
        }
        if ((s.b - s.a).norm() > kTolerance) chain.parts.push_back(s);
    }
    if (chain.parts.empty() || std::fabs(chain.end().x() - chain.start().x()) < kTolerance) {
        // Turning needs a length along Z, facing along X: the passes run from A towards B.
        error = {f ? 'Q' : 'R',
                 "cycle-geometry",
                 KERF_TR_NOOP("the section has no length along the passes"),
                 {}};
        return false;
    }
    // Allowances along the cut and the step directions of this frame.
    const double allowCut = f ? section.allowanceX : section.allowanceZ;
    const double allowStep = f ? section.allowanceZ : section.allowanceX;
    const Vec2 a = chain.start();
    const Vec2 b = chain.end();
    const double sideCut = -sign(b.x() - a.x());     // the call point lies before A
    const double sideStep = sign(call.y() - a.y());  // the material lies between call and A
    // Every element moves away from the call point and grows towards it (no undercut).
    for (const Section& s : chain.parts) {
        if (sideCut * (s.b.x() - s.a.x()) > kTolerance ||
            sideStep * (s.b.y() - s.a.y()) < -kTolerance) {
            error = {f ? 'R' : 'Q',
                     "cycle-geometry",
                     KERF_TR_NOOP("the profile runs back under the material (a channel or an "
                                  "undercut): not supported yet"),
                     {}};
            return false;
        }
    }
    // Clearance (spec: along X from the call point to B at least L, along Z to A at least M).
    if (sideStep * (call.y() - b.y()) < allowStep - kTolerance ||
        std::fabs(call.y() - a.y()) < kTolerance) {
        error = positionError(f ? 'Z' : 'X');
        return false;
    }
    if (sideCut * (call.x() - a.x()) < allowCut - kTolerance) {
        error = positionError(f ? 'X' : 'Z');
        return false;
    }
    const Chain c1 = chain.shifted(Vec2(sideCut * allowCut, sideStep * allowStep));
    const Vec2 a1 = c1.start();
    const Vec2 b1 = c1.end();
    auto out = [&](const Vec2& p) { return swapped(p, f); };
    auto onWall = [&](double v) { return sideStep * (v - b1.y()) >= -kTolerance; };
    auto levelT = [&](double v) { return onWall(v) ? c1.size() : c1.atLevel(v, sideStep); };
    // Where a pass at step level v meets the profile plus allowances (beyond B: B's wall).
    auto passEnd = [&](double v) {
        return onWall(v) ? Vec2(b1.x(), v) : Vec2(c1.at(levelT(v)).x(), v);
    };
    // Follows `chain` from parameter t0 to t1 (t0 <= t1), element by element.
    auto follow = [&](const Chain& ch, double t0, double t1, double feed) {
        for (size_t i = static_cast<size_t>(std::max(0.0, std::floor(t0)));
             i < ch.parts.size() && static_cast<double>(i) < t1; ++i) {
            const Section& part = ch.parts[i];
            const double local = std::min(1.0, t1 - static_cast<double>(i));
            const Vec2 to = part.at(local);
            if (part.arc) {
                path.arc(out(to), out(part.c), (part.sweep > 0.0) != f, feed);
            } else {
                path.feed(out(to), feed);
            }
        }
    };
    const double depth = sideStep * (call.y() - a1.y());
    const double count = depth > kTolerance ? std::ceil(depth / section.maxStep - 1e-9) : 0.0;
    if (count * (5.0 + c1.size()) > LathePath::kStepLimit) {
        error = tooManySteps('C');
        return false;
    }
    const int passes = static_cast<int>(count);
    const double step = passes > 0 ? depth / passes : 0.0;
    const double feed = section.roughingFeed;
    double previous = call.y();
    for (int k = 1; k <= passes; ++k) {
        const double level = k == passes ? a1.y() : call.y() - sideStep * k * step;
        path.rapid(out({call.x(), level}));  // 1-2
        const Vec2 end = passEnd(level);
        path.feed(out(end), feed);  // 2-3
        if (!section.retract) {
            // 3-4 along the profile (and up B's wall) to the previous level.
            if (!onWall(level)) follow(c1, levelT(level), levelT(previous), feed);
            path.feed(out(passEnd(previous)), feed);
        } else if (*section.retract > 0.0) {
            const double d = *section.retract;  // 3-4 at 45 degrees
            path.rapid(out(end + Vec2(sideCut * d, sideStep * d)));
        }
        path.rapid(out({call.x(), swapped(path.position(), f).y()}));  // 4-5
        previous = level;
    }
    // Final roughing pass and finishing pass: along the profile (plus allowances), up B's wall.
    auto along = [&](const Chain& ch, double passFeed) {
        path.rapid(out({call.x(), ch.start().y()}));
        path.feed(out(ch.start()), passFeed);
        follow(ch, 0.0, ch.size(), passFeed);
        path.feed(out({ch.end().x(), call.y()}), passFeed);
        path.rapid(callZx);
    };
    if (section.finalRoughingFeed > 0.0) along(c1, section.finalRoughingFeed);
    if (section.finishingFeed > 0.0) along(chain, section.finishingFeed);
    path.rapid(callZx);
    if (path.full()) {
        error = tooManySteps('C');
        return false;
    }
    return true;
}

}  // namespace kerf::cycles::lathe
