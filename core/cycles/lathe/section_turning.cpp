#include "core/cycles/lathe/section_turning.h"

#include <algorithm>
#include <cmath>

#include "core/base/translate.h"
#include "core/cycles/lathe/channel_roughing.h"
#include "core/cycles/lathe/turning_chain.h"
#include "core/geometry/arc_math.h"

namespace kerf::cycles::lathe {

namespace {

constexpr double kTolerance = kChainTolerance;

double sign(double v) {
    return v < 0.0 ? -1.0 : 1.0;
}

LatheError positionError(char letter) {
    return {letter,
            "cycle-position",
            KERF_TR_NOOP("the tool position is not correct for the cycle ({1})"),
            {std::string(1, letter)}};
}

// The elements from `start` in the cycle's frame (`facing`: swapped); arcs split at their quadrant
// points (`splitArcs`), or else refused beyond a quarter circle (G81-G85). False with `error` for
// an arc whose ends are not on one circle within `radiusTolerance`.
bool toChain(const Vec2& start, const std::vector<ProfileElement>& elements, bool facing,
             double radiusTolerance, bool splitArcs, Chain& chain, LatheError& error) {
    const bool f = facing;
    Vec2 from = swapped(start, f);
    for (const ProfileElement& e : elements) {
        Section s;
        s.a = from;
        s.b = swapped(e.end, f);
        from = s.b;
        if (e.centre) {
            s.arc = true;
            s.c = swapped(*e.centre, f);
            s.r = (s.a - s.c).norm();
            if (std::fabs((s.b - s.c).norm() - s.r) > radiusTolerance || s.r < kTolerance) {
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
            // Passes meet it once only if it stays within a quarter circle; a profile's arcs
            // are split at their quadrant points.
            if (splitArcs) {
                chain.addArcByQuadrants(s);
                continue;
            }
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
    return true;
}

}  // namespace

bool shortArcIsCcw(const Vec2& a, const Vec2& b, const Vec2& centre) {
    return arcSweep(a, b, centre, true) <= kPi;
}

bool expandTurningSection(const TurningSection& section, const Vec2& callZx, LathePath& path,
                          LatheError& error) {
    const bool f = section.facing;
    const Vec2 call = swapped(callZx, f);
    Chain chain;
    if (!toChain(section.start, section.elements, f, section.radiusTolerance, section.channels,
                 chain, error)) {
        return false;
    }
    Chain raw;
    if (!section.raw.elements.empty()) {
        if (!toChain(section.raw.start, section.raw.elements, f, section.radiusTolerance, true, raw,
                     error)) {
            return false;
        }
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
    // Every element moves away from the call point (no undercut) and, but in a profile with
    // channels, grows towards it.
    for (const Section& s : chain.parts) {
        if (sideCut * (s.b.x() - s.a.x()) > kTolerance) {
            error = {f ? 'R' : 'Q',
                     "cycle-geometry",
                     KERF_TR_NOOP("the profile runs back against the passes (an undercut): the "
                                  "tool cannot reach it"),
                     {}};
            return false;
        }
        if (!section.channels && sideStep * (s.b.y() - s.a.y()) < -kTolerance) {
            error = {f ? 'R' : 'Q',
                     "cycle-geometry",
                     KERF_TR_NOOP("the section runs back under the material"),
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
    // A pass runs to B's wall when the profile never rises to its level.
    const double highest = c1.lowest(-sideStep);
    auto onWall = [&](double v) { return sideStep * (v - highest) >= -kTolerance; };
    auto levelT = [&](double v) { return onWall(v) ? c1.size() : c1.atLevel(v, sideStep); };
    // Where a pass at step level v meets the profile plus allowances (beyond B: B's wall).
    auto passEnd = [&](double v) {
        return onWall(v) ? Vec2(b1.x(), v) : Vec2(c1.at(levelT(v)).x(), v);
    };
    auto follow = [&](const Chain& ch, double t0, double t1, double feed) {
        followChain(ch, t0, t1, feed, f, path);
    };
    // Whether the profile rises all the way from t0 to t1 (no channel in between).
    auto rises = [&](double t0, double t1) {
        for (auto i = static_cast<size_t>(std::floor(t0)); static_cast<double>(i) < t1; ++i) {
            if (i < c1.parts.size() &&
                sideStep * (c1.parts[i].b.y() - c1.parts[i].a.y()) < -kTolerance) {
                return false;
            }
        }
        return true;
    };
    // The levels: equal steps down to A (plus allowances), or, with channels deeper than A, down
    // to the profile's lowest point; the main passes stop at A.
    const double lowest = section.channels ? c1.lowest(sideStep) : a1.y();
    const double bottom = sideStep * (lowest - a1.y()) < -kTolerance ? lowest : a1.y();
    // With a raw stock the levels start at its top.
    double top = call.y();
    if (!raw.parts.empty() && sideStep * (top - raw.lowest(-sideStep)) > 0.0) {
        top = raw.lowest(-sideStep);
    }
    const Chain* stock = raw.parts.empty() ? nullptr : &raw;
    const double depth = sideStep * (top - bottom);
    const double count = depth > kTolerance ? std::ceil(depth / section.maxStep - 1e-9) : 0.0;
    if (count * (5.0 + c1.size()) > LathePath::kStepLimit) {
        error = tooManySteps('C');
        return false;
    }
    const int passes = static_cast<int>(count);
    const double step = passes > 0 ? depth / passes : 0.0;
    const double feed = section.roughingFeed;
    std::vector<double> levels;
    for (int k = 1; k <= passes; ++k) {
        levels.push_back(k == passes ? bottom : top - sideStep * k * step);
    }
    double previous = call.y();
    for (const double level : levels) {
        if (sideStep * (level - a1.y()) < -kTolerance) break;  // below A: channels only
        path.rapid(out({call.x(), level}));                    // 1-2
        const Vec2 end = passEnd(level);
        cutAlongLevel(stock, sideStep, end.x(), level, feed, f, path);  // 2-3
        if (!section.retract && rises(levelT(level), levelT(previous))) {
            // 3-4 along the profile (and up B's wall) to the previous level.
            if (!onWall(level)) follow(c1, levelT(level), levelT(previous), feed);
            path.feed(out(passEnd(previous)), feed);
        } else if (section.retract && *section.retract > 0.0) {
            const double d = *section.retract;  // 3-4 at 45 degrees
            path.rapid(out(end + Vec2(sideCut * d, sideStep * d)));
        }
        path.rapid(out({call.x(), swapped(path.position(), f).y()}));  // 4-5
        previous = level;
    }
    if (section.channels) {
        ChannelRoughing job;
        job.chain = &c1;
        job.raw = stock;
        job.levels = levels;
        job.call = call;
        job.side = sideStep;
        job.passDirection = -sideCut;
        job.retract = section.retract;
        job.feed = feed;
        job.plungeFeed = section.plungeFeed;
        job.facing = f;
        if (roughChannels(job, path)) path.rapid(callZx);  // along the call point's level
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
