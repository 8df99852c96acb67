#include "core/cycles/lathe/reachable_profile.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/arc_math.h"
#include "core/geometry/open_chain_offset.h"

namespace kerf::cycles::lathe {

namespace {

constexpr double kTolerance = 1e-9;

// A profile in the frame (u along the feed, v outwards), as a start and elements.
struct Chain {
    Vec2 start{0.0, 0.0};
    std::vector<ProfileElement> elements;
};

Vec2 endOf(const Chain& c) {
    return c.elements.empty() ? c.start : c.elements.back().end;
}

double angleOf(const Vec2& centre, const Vec2& p) {
    return std::atan2(p.y() - centre.y(), p.x() - centre.x());
}

Vec2 onCircle(const Vec2& centre, double radius, double angle) {
    return centre + radius * Vec2(std::cos(angle), std::sin(angle));
}

// Splits every arc where the gain w . p has its extremes, so that the gain changes in one
// direction along each piece.
Chain splitAtExtremes(const Chain& chain, const Vec2& w) {
    Chain out{chain.start, {}};
    Vec2 from = chain.start;
    const double phi = std::atan2(w.y(), w.x());
    for (const ProfileElement& e : chain.elements) {
        if (!e.centre) {
            out.elements.push_back(e);
            from = e.end;
            continue;
        }
        const Vec2 c = *e.centre;
        const double radius = (from - c).norm();
        const double sweep = arcSweep(from, e.end, c, e.ccw);
        const double a0 = angleOf(c, from);
        std::vector<double> cuts;  // fractions of the sweep
        for (const double extreme : {phi, phi + kPi}) {
            // Every angle extreme + k 2 pi strictly inside the sweep.
            for (int k = -2; k <= 2; ++k) {
                const double s = (extreme + k * kTwoPi - a0) / sweep;
                if (s > 1e-9 && s < 1.0 - 1e-9) cuts.push_back(s);
            }
        }
        std::sort(cuts.begin(), cuts.end());
        for (const double s : cuts) {
            ProfileElement piece = e;
            piece.end = onCircle(c, radius, a0 + s * sweep);
            out.elements.push_back(piece);
        }
        out.elements.push_back(e);
        from = e.end;
    }
    return out;
}

// The point of the piece from `from` where the gain w . p equals `level` (the gain rises along
// the piece through it).
Vec2 crossing(const Vec2& from, const ProfileElement& e, const Vec2& w, double level) {
    const double g0 = w.dot(from);
    const double g1 = w.dot(e.end);
    if (!e.centre) {
        const double t =
            g1 - g0 > kTolerance ? std::clamp((level - g0) / (g1 - g0), 0.0, 1.0) : 1.0;
        return from + t * (e.end - from);
    }
    // On the circle w . p = w . c + r |w| cos(a - phi); the piece is monotone in the gain, so
    // bisect over its sweep.
    const Vec2 c = *e.centre;
    const double radius = (from - c).norm();
    const double sweep = arcSweep(from, e.end, c, e.ccw);
    const double a0 = angleOf(c, from);
    double lo = 0.0;
    double hi = 1.0;
    for (int i = 0; i < 80; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (w.dot(onCircle(c, radius, a0 + mid * sweep)) < level) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return onCircle(c, radius, a0 + hi * sweep);
}

// Bridges every stretch where the gain w . p falls below the highest value it had before: from
// the point of that value, straight to where the gain reaches it again. Walking along the chain,
// that is the line at the steepest slope the insert follows (w's normal).
Chain bridgeDips(const Chain& chain, const Vec2& w) {
    const Chain split = splitAtExtremes(chain, w);
    Chain out{split.start, {}};
    Vec2 from = split.start;
    double best = w.dot(from);
    bool inDip = false;
    for (const ProfileElement& e : split.elements) {
        const double gEnd = w.dot(e.end);
        if (!inDip) {
            if (gEnd >= w.dot(from) - kTolerance) {
                out.elements.push_back(e);
                best = std::max(best, gEnd);
            } else {
                inDip = true;  // the bridge starts at the end of what is kept: `from`
            }
        }
        if (inDip && gEnd >= best - kTolerance) {
            ProfileElement bridge;
            bridge.end = crossing(from, e, w, best);
            bridge.line = e.line;
            out.elements.push_back(bridge);
            if ((e.end - bridge.end).norm() > kTolerance) out.elements.push_back(e);
            best = gEnd;
            inDip = false;
        }
        from = e.end;
    }
    if (inDip) {
        // The profile ends in the dip: the bridge runs to above its end.
        const Vec2 last = endOf(out);
        const Vec2 end = endOf(split);
        const Vec2 along(w.y(), -w.x());  // the bridge's direction, forwards
        ProfileElement bridge;
        bridge.end = last + ((end - last).x() / along.x()) * along;
        bridge.line = split.elements.back().line;
        out.elements.push_back(bridge);
    }
    return out;
}

Chain reversed(const Chain& chain) {
    Chain out{endOf(chain), {}};
    for (size_t i = chain.elements.size(); i-- > 0;) {
        ProfileElement e = chain.elements[i];
        e.end = i == 0 ? chain.start : chain.elements[i - 1].end;
        e.ccw = !e.ccw;
        out.elements.push_back(e);
    }
    return out;
}

bool advancesAlongU(const Chain& chain) {
    Vec2 from = chain.start;
    for (const ProfileElement& e : chain.elements) {
        if (e.end.x() < from.x() - kTolerance) return false;
        if (e.centre) {
            // Each piece between extremes of u is monotone in u: its ends decide.
            const Chain split = splitAtExtremes(Chain{from, {e}}, Vec2(1.0, 0.0));
            Vec2 a = from;
            for (const ProfileElement& p : split.elements) {
                if (p.end.x() < a.x() - kTolerance) return false;
                a = p.end;
            }
        }
        from = e.end;
    }
    return true;
}

std::vector<PlanarSegment> segmentsOf(const Vec2& start,
                                      const std::vector<ProfileElement>& elements) {
    std::vector<PlanarSegment> out;
    Vec2 from = start;
    for (const ProfileElement& e : elements) {
        if ((e.end - from).norm() > kTolerance) {
            out.push_back(e.centre ? PlanarSegment{PlanarSegment::Kind::Arc, from, e.end, *e.centre,
                                                   arcSweep(from, e.end, *e.centre, e.ccw)}
                                   : PlanarSegment::line(from, e.end));
        }
        from = e.end;
    }
    return out;
}

// The profile elements of segments; each takes the program line of the nearest element of
// `source` (the elements they come from).
std::vector<ProfileElement> elementsOf(const std::vector<PlanarSegment>& segments,
                                       const std::vector<PlanarSegment>& source,
                                       const std::vector<uint32_t>& sourceLines) {
    std::vector<ProfileElement> out;
    for (const PlanarSegment& s : segments) {
        ProfileElement e;
        e.end = s.end;
        if (s.kind == PlanarSegment::Kind::Arc) {
            e.centre = s.center;
            e.ccw = s.sweep > 0.0;
        }
        const Vec2 middle =
            s.kind == PlanarSegment::Kind::Line
                ? Vec2(0.5 * (s.start + s.end))
                : onCircle(s.center, s.radius(), angleOf(s.center, s.start) + s.sweep / 2.0);
        double nearest = HUGE_VAL;
        for (size_t k = 0; k < source.size(); ++k) {
            const double d = source[k].distanceTo(middle);
            if (d < nearest) nearest = d, e.line = sourceLines[k];
        }
        out.push_back(e);
    }
    return out;
}

// A concave arc tighter than the nose (its centre on the side the material is not, `airSide`
// +1 left of the travel, -1 right): the nose rolled along the profile cannot enter it. The
// profile the nose reaches there is the profile offset out by the nose radius and back: the
// neighbours up to where the nose touches them, joined by an arc of the nose's radius. Worked
// out over the arc and its neighbours, wider while the nose's arc reaches beyond them.
std::vector<ProfileElement> roundTightArcs(const Vec2& start, std::vector<ProfileElement> profile,
                                           double airSide, double noseRadius) {
    if (noseRadius <= 0.0) return profile;
    for (size_t i = 0; i < profile.size(); ++i) {
        const Vec2 from = i == 0 ? start : profile[i - 1].end;
        const ProfileElement& e = profile[i];
        if (!e.centre || (e.ccw ? 1.0 : -1.0) != airSide ||
            (from - *e.centre).norm() >= noseRadius - 1e-9) {
            continue;
        }
        for (size_t widen = 1; widen <= profile.size(); ++widen) {
            const size_t first = i >= widen ? i - widen : 0;
            const size_t last = std::min(i + widen, profile.size() - 1);
            const Vec2 windowStart = first == 0 ? start : profile[first - 1].end;
            const std::vector<ProfileElement> window(profile.begin() + static_cast<long>(first),
                                                     profile.begin() + static_cast<long>(last) + 1);
            const std::vector<PlanarSegment> chain = segmentsOf(windowStart, window);
            const auto out = offsetOpenChain(chain, airSide * noseRadius);
            const auto back = out ? offsetOpenChain(*out, -airSide * noseRadius) : std::nullopt;
            const bool fits = back && !back->empty() &&
                              (back->front().start - chain.front().start).norm() < 1e-6 &&
                              (back->back().end - chain.back().end).norm() < 1e-6;
            if (!fits && (first > 0 || last + 1 < profile.size())) continue;
            if (!fits) return profile;  // the whole profile is narrower than the nose
            std::vector<uint32_t> lines;
            Vec2 at = windowStart;
            for (const ProfileElement& w : window) {
                if ((w.end - at).norm() > kTolerance) lines.push_back(w.line);
                at = w.end;
            }
            std::vector<ProfileElement> rounded = elementsOf(*back, chain, lines);
            rounded.back().end = window.back().end;  // exactly where the rest starts
            profile.erase(profile.begin() + static_cast<long>(first),
                          profile.begin() + static_cast<long>(last) + 1);
            profile.insert(profile.begin() + static_cast<long>(first), rounded.begin(),
                           rounded.end());
            i = first;  // look again from the window: what follows has moved
            break;
        }
    }
    return profile;
}

}  // namespace

std::vector<ProfileElement> reachableProfile(const Vec2& start,
                                             const std::vector<ProfileElement>& rawProfile,
                                             const Vec2& feed, const Vec2& outward,
                                             const InsertGeometry& insert) {
    const std::vector<ProfileElement> profile = roundTightArcs(
        start, rawProfile, cross2(feed, outward) > 0.0 ? 1.0 : -1.0, insert.noseRadius);
    if (insert.cuttingAngleDeg <= 0.0 || insert.noseAngleDeg <= 0.0) return profile;
    // The frame (u, v): a reflection when (feed, outward) turns clockwise, so arcs turn too.
    const bool reflected = cross2(feed, outward) < 0.0;
    auto toLocal = [&](const Vec2& p) { return Vec2(p.dot(feed), p.dot(outward)); };
    auto toPlane = [&](const Vec2& p) { return Vec2(p.x() * feed + p.y() * outward); };
    Chain chain{toLocal(start), {}};
    for (ProfileElement e : profile) {
        e.end = toLocal(e.end);
        if (e.centre) e.centre = toLocal(*e.centre);
        if (reflected) e.ccw = !e.ccw;
        chain.elements.push_back(e);
    }
    if (!advancesAlongU(chain)) return profile;
    const double descent = 180.0 - insert.cuttingAngleDeg - insert.noseAngleDeg;
    if (descent < 90.0) {
        // Forwards the gain v + u tan(descent) may not fall.
        chain = bridgeDips(chain, Vec2(std::tan(degToRad(std::max(descent, 0.0))), 1.0));
    }
    if (insert.cuttingAngleDeg < 90.0) {
        // Backwards the gain v - u tan(CUTA) may not fall.
        chain = reversed(
            bridgeDips(reversed(chain), Vec2(-std::tan(degToRad(insert.cuttingAngleDeg)), 1.0)));
    }
    std::vector<ProfileElement> out;
    for (ProfileElement e : chain.elements) {
        e.end = toPlane(e.end);
        if (e.centre) e.centre = toPlane(*e.centre);
        if (reflected) e.ccw = !e.ccw;
        out.push_back(e);
    }
    return out;
}

}  // namespace kerf::cycles::lathe
