#include "core/geometry/fk/fk_candidates.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/arc_math.h"

namespace kerf::fk {

namespace {

Vec2 unitAt(double degrees) {
    const double a = degToRad(degrees);
    return {std::cos(a), std::sin(a)};
}

double angleDegOf(const Vec2& v) {
    return radToDeg(std::atan2(v.y(), v.x()));
}

// The absolute value of a datum; incremental data need the start (`base` is its value there).
std::optional<double> absolute(const std::optional<FkValue>& v, std::optional<double> base) {
    if (!v) return std::nullopt;
    if (!v->incremental) return v->value;
    if (!base) return std::nullopt;
    return *base + v->value;
}

// Everything the element's data fix without knowing its carrier.
struct Known {
    std::optional<double> x, y, pr, paDeg;
    std::optional<Vec2> end;
    std::optional<Vec2> direction;  // AN
    std::optional<double> centreX, centreY;
    std::optional<Vec2> centre;
    std::optional<Vec2> pd;
    std::vector<Vec2> pointsOn;
};

Known knownData(const FkElement& e, const CandidateContext& c) {
    Known k;
    const auto& s = c.start;
    std::optional<double> sx = s ? std::optional(s->x()) : std::nullopt;
    std::optional<double> sy = s ? std::optional(s->y()) : std::nullopt;
    std::optional<double> spr, spa;
    if (s && c.pole) {
        spr = (*s - *c.pole).norm();
        spa = angleDegOf(*s - *c.pole);
    }
    k.x = absolute(e.x, sx);
    k.y = absolute(e.y, sy);
    k.pr = absolute(e.pr, spr);
    k.paDeg = absolute(e.pa, spa);
    if (k.x && k.y) k.end = Vec2(*k.x, *k.y);
    if (k.pr && k.paDeg && c.pole) k.end = *c.pole + *k.pr * unitAt(*k.paDeg);
    if (e.closeEnd && c.contourStart) k.end = *c.contourStart;
    std::optional<double> tangentAngle =
        c.startTangent ? std::optional(angleDegOf(*c.startTangent)) : std::nullopt;
    if (auto an = absolute(e.an, tangentAngle)) k.direction = unitAt(*an);
    k.centreX = absolute(e.ccx, sx);
    k.centreY = absolute(e.ccy, sy);
    if (k.centreX && k.centreY) k.centre = Vec2(*k.centreX, *k.centreY);
    auto cpr = absolute(e.ccpr, spr);
    auto cpa = absolute(e.ccpa, spa);
    if (cpr && cpa && c.pole) k.centre = *c.pole + *cpr * unitAt(*cpa);
    auto px = absolute(e.pdx, sx);
    auto py = absolute(e.pdy, sy);
    if (px && py) k.pd = Vec2(*px, *py);
    for (const auto& p : e.pointsOn)
        if (p) k.pointsOn.push_back(*p);
    // A point at distance 0 lies on the element.
    if (k.pd && e.distance && *e.distance <= kFkTolerance) {
        k.pointsOn.push_back(*k.pd);
        k.pd.reset();
    }
    return k;
}

// Points the element passes through, in the order of travel as far as known.
std::vector<Vec2> throughPoints(const Known& k, const CandidateContext& c) {
    std::vector<Vec2> points;
    if (c.start) points.push_back(*c.start);
    points.insert(points.end(), k.pointsOn.begin(), k.pointsOn.end());
    if (k.end) points.push_back(*k.end);
    return points;
}

bool runsAlong(const Carrier& carrier, const Vec2& axis) {
    return !carrier.circle && std::fabs(cross2(carrier.dir, axis)) <= kFkTolerance;
}

bool sameDirection(const Vec2& a, const Vec2& b) {
    return (a - b).norm() <= 1e-6;
}

// A tangential neighbour: the carrier, and whether it comes before the element.
struct Neighbour {
    Carrier carrier;
    bool before = true;
};

bool touches(const Carrier& candidate, const Neighbour& n) {
    return n.before ? touchPoint(n.carrier, candidate).has_value()
                    : touchPoint(candidate, n.carrier).has_value();
}

std::vector<Neighbour> neighbours(const FkElement& e, const CandidateContext& c) {
    std::vector<Neighbour> out;
    if (e.isTangent() && !c.start && c.previous) out.push_back({*c.previous, true});
    if (c.next) out.push_back({*c.next, false});
    return out;
}

CarrierCandidates finish(std::vector<Carrier> candidates, const std::vector<bool>& keep) {
    CarrierCandidates out;
    for (size_t i = 0; i < candidates.size(); ++i)
        if (keep[i]) out.carriers.push_back(candidates[i]);
    out.found = out.carriers.empty() ? Found::Contradiction : Found::Some;
    return out;
}

// Lines leaving circle `from` and entering circle `to`, each along the circle's direction of
// travel. A line of direction d touches a circle (centre c, radius r, s = +1 counter-clockwise,
// -1 clockwise) at c - s r n, n = leftNormal(d); both touch points on one line of direction d
// means cross(d, cTo - cFrom) = sTo rTo - sFrom rFrom: sin(phi - theta) = k / |cTo - cFrom| with
// d = (cos theta, sin theta) and phi the direction from centre to centre. Of the two directions,
// those that run from the first touch point to the second are kept.
std::vector<Carrier> tangentsBetween(const Carrier& from, const Carrier& to) {
    const Vec2 apart = to.centre - from.centre;
    const double distance = apart.norm();
    const double k = (to.ccw ? to.radius : -to.radius) - (from.ccw ? from.radius : -from.radius);
    if (distance <= kFkTolerance || std::fabs(k) > distance + kFkTolerance) return {};
    const double phi = std::atan2(apart.y(), apart.x());
    const double offset = std::asin(std::clamp(k / distance, -1.0, 1.0));
    std::vector<Carrier> out;
    for (double theta : {phi - offset, phi - (kPi - offset)}) {
        const Vec2 d(std::cos(theta), std::sin(theta));
        const Vec2 n = leftNormal(d);
        const Vec2 leave = from.centre - (from.ccw ? 1.0 : -1.0) * from.radius * n;
        const Vec2 enter = to.centre - (to.ccw ? 1.0 : -1.0) * to.radius * n;
        if (d.dot(enter - leave) > kFkTolerance * from.scale())
            out.push_back(Carrier::line(leave, d));
    }
    return out;
}

CarrierCandidates lineCandidates(const FkElement& e, const Known& k, const CandidateContext& c) {
    const std::vector<Vec2> points = throughPoints(k, c);
    std::optional<Vec2> dir = k.direction;
    if (!dir && e.isTangent() && c.start && c.startTangent) dir = *c.startTangent;
    const std::vector<Neighbour> touching = neighbours(e, c);
    const Neighbour* circle = nullptr;
    const Neighbour* straight = nullptr;
    const Neighbour* circleAfter = nullptr;
    for (const Neighbour& n : touching) {
        const Neighbour*& slot = n.carrier.circle ? circle : straight;
        if (slot == nullptr) slot = &n;
        if (n.carrier.circle && !n.before) circleAfter = &n;
    }
    std::vector<Carrier> found;
    if (straight != nullptr) {
        found.push_back(straight->carrier);  // a line tangent to a line is that line
    } else if (points.empty() && !dir && circle != nullptr && circle->before &&
               circleAfter != nullptr) {
        found = tangentsBetween(circle->carrier, circleAfter->carrier);  // between two arcs
    } else if (points.size() >= 2 && (points.back() - points.front()).norm() > kFkTolerance) {
        Vec2 along = (points.back() - points.front()).normalized();
        if (dir && dir->dot(along) < 0.0) along = -along;
        found.push_back(Carrier::line(points.front(), along));
    } else if (!points.empty() && dir) {
        found.push_back(Carrier::line(points.front(), *dir));
    } else if (dir && k.y && std::fabs(dir->y()) <= kFkTolerance) {
        found.push_back(Carrier::line({0.0, *k.y}, *dir));  // "FL AN+0 Y+20": the line y = 20
    } else if (dir && k.x && std::fabs(dir->x()) <= kFkTolerance) {
        found.push_back(Carrier::line({*k.x, 0.0}, *dir));
    } else if (dir && circle) {
        const Carrier& t = circle->carrier;
        // The line runs along the circle's direction of travel where it touches it.
        const Vec2 radial = t.ccw ? Vec2(-leftNormal(*dir)) : leftNormal(*dir);
        found.push_back(Carrier::line(t.centre + t.radius * radial, *dir));
    } else if (dir && k.pd && e.distance) {
        // Parallel to the direction at distance D from PD: right of it first, then left.
        found.push_back(Carrier::line(*k.pd - *e.distance * leftNormal(*dir), *dir));
        found.push_back(Carrier::line(*k.pd + *e.distance * leftNormal(*dir), *dir));
    } else if (!points.empty() && (circle || (k.pd && e.distance))) {
        const Vec2 q = points.front();
        const Vec2 centre = circle ? circle->carrier.centre : *k.pd;
        const double radius = circle ? circle->carrier.radius : *e.distance;
        const bool fromCircle = circle && circle->before;
        for (const Vec2& t : tangentPointsFrom(q, centre, radius)) {
            const Vec2 along = fromCircle ? Vec2(q - t) : Vec2(t - q);
            if (along.norm() > kFkTolerance) found.push_back(Carrier::line(q, along));
        }
    } else {
        return {};
    }
    std::vector<bool> keep(found.size(), true);
    for (size_t i = 0; i < found.size(); ++i) {
        const Carrier& l = found[i];
        for (const Vec2& p : points)
            if (!l.contains(p)) keep[i] = false;
        if (dir && !sameDirection(l.dir, *dir)) keep[i] = false;
        for (const Neighbour& n : touching) {
            if (n.carrier.circle ? !touches(l, n) : !l.sameAs(n.carrier)) keep[i] = false;
        }
        if (k.pd && e.distance &&
            std::fabs(l.distanceTo(*k.pd) - *e.distance) > kFkTolerance * l.scale()) {
            keep[i] = false;
        }
    }
    return finish(std::move(found), keep);
}

// Where the centre of an arc may lie, one constraint at a time.
std::vector<Carrier> centreLoci(const Known& k, const std::vector<Vec2>& points,
                                const std::optional<double>& radius, bool ccw,
                                const std::optional<std::pair<Vec2, Vec2>>& tangentAtStart,
                                const std::vector<Neighbour>& touching,
                                std::vector<Vec2>& fixedCentres) {
    std::vector<Carrier> loci;
    if (k.centreX) loci.push_back(Carrier::line({*k.centreX, 0.0}, {0.0, 1.0}));
    if (k.centreY) loci.push_back(Carrier::line({0.0, *k.centreY}, {1.0, 0.0}));
    if (tangentAtStart) {
        const auto& [s, d] = *tangentAtStart;
        const Vec2 inward = ccw ? leftNormal(d) : Vec2(-leftNormal(d));
        if (radius) {
            fixedCentres.push_back(s + *radius * inward);
        } else {
            loci.push_back(Carrier::line(s, inward));
        }
    }
    if (radius) {
        for (const Neighbour& n : touching) {
            const Carrier& t = n.carrier;
            if (!t.circle) {
                const Vec2 inward = ccw ? leftNormal(t.dir) : Vec2(-leftNormal(t.dir));
                loci.push_back(Carrier::line(t.point + *radius * inward, t.dir));
            } else if (t.ccw == ccw) {
                const double apart = std::fabs(t.radius - *radius);
                if (apart <= kFkTolerance * t.scale()) {
                    fixedCentres.push_back(t.centre);
                } else {
                    loci.push_back(Carrier::arc(t.centre, apart, true));
                }
            } else {
                loci.push_back(Carrier::arc(t.centre, t.radius + *radius, true));
            }
        }
        for (const Vec2& p : points)
            loci.push_back(Carrier::arc(p, *radius, true));
    } else if (points.size() >= 2 && (points[1] - points[0]).norm() > kFkTolerance) {
        const Vec2 mid = 0.5 * (points[0] + points[1]);
        loci.push_back(Carrier::line(mid, leftNormal((points[1] - points[0]).normalized())));
    }
    return loci;
}

CarrierCandidates arcCandidates(const FkElement& e, const Known& k, const CandidateContext& c) {
    const std::vector<Vec2> points = throughPoints(k, c);
    const std::vector<Neighbour> touching = neighbours(e, c);
    std::optional<std::pair<Vec2, Vec2>> tangentAtStart;
    if (c.start && k.direction) {
        tangentAtStart = std::pair(*c.start, *k.direction);
    } else if (c.start && e.isTangent() && c.startTangent) {
        tangentAtStart = std::pair(*c.start, *c.startTangent);
    }
    std::vector<bool> rotations;
    if (e.rotation != FkRotation::Cw) rotations.push_back(true);
    if (e.rotation != FkRotation::Ccw) rotations.push_back(false);
    std::vector<Carrier> found;
    bool anyDetermined = false;
    for (bool ccw : rotations) {
        std::vector<Vec2> centres;
        if (k.centre) {
            centres.push_back(*k.centre);
        } else {
            std::vector<Carrier> loci =
                centreLoci(k, points, e.radius, ccw, tangentAtStart, touching, centres);
            if (centres.empty() && loci.size() >= 2) centres = intersect(loci[0], loci[1]);
            if (centres.empty() && loci.size() == 1 && e.radius && k.pd && e.distance) {
                // PD at distance D: the centre lies R + D from it (PD outside the arc), then
                // |R - D| (inside).
                for (double apart : {*e.radius + *e.distance, std::fabs(*e.radius - *e.distance)})
                    if (apart > kFkTolerance)
                        for (const Vec2& p : intersect(loci[0], Carrier::arc(*k.pd, apart, true)))
                            centres.push_back(p);
            }
            if (centres.empty() && loci.size() < 2 && !e.radius && points.size() >= 3) {
                if (auto circle = circleThrough(points[0], points[1], points[2])) {
                    centres.push_back(circle->center);
                }
            }
            if (centres.empty() && loci.size() < 2 && points.size() < 3) continue;
        }
        anyDetermined = true;
        for (const Vec2& centre : centres) {
            std::optional<double> radius = e.radius;
            if (!radius && !points.empty()) radius = (points.front() - centre).norm();
            if (!radius) {
                for (const Neighbour& n : touching) {
                    if (!n.carrier.circle) radius = n.carrier.distanceTo(centre);
                }
            }
            if (!radius) {
                anyDetermined = false;
                continue;
            }
            if (*radius > kFkTolerance) found.push_back(Carrier::arc(centre, *radius, ccw));
        }
    }
    if (!anyDetermined) return {};
    std::vector<bool> keep(found.size(), true);
    for (size_t i = 0; i < found.size(); ++i) {
        const Carrier& a = found[i];
        for (const Vec2& p : points)
            if (!a.contains(p)) keep[i] = false;
        if (tangentAtStart &&
            !sameDirection(a.tangentAt(tangentAtStart->first), tangentAtStart->second)) {
            keep[i] = false;
        }
        for (const Neighbour& n : touching)
            if (!touches(a, n)) keep[i] = false;
        if (k.pd && e.distance &&
            std::fabs(std::fabs((a.centre - *k.pd).norm() - a.radius) - *e.distance) >
                kFkTolerance * a.scale()) {
            keep[i] = false;
        }
    }
    return finish(std::move(found), keep);
}

}  // namespace

CarrierCandidates carrierCandidates(const FkElement& element, const CandidateContext& context) {
    const Known k = knownData(element, context);
    return element.isArc() ? arcCandidates(element, k, context)
                           : lineCandidates(element, k, context);
}

bool runsForward(const Carrier& carrier, const Vec2& start, const Vec2& end) {
    if (carrier.circle) return true;  // an arc may close on itself (a full circle)
    return carrier.dir.dot(end - start) > kFkTolerance * carrier.scale();
}

EndCandidates endCandidates(const FkElement& e, const Carrier& carrier, const Vec2& start,
                            const CandidateContext& context) {
    CandidateContext here = context;
    here.start = start;
    const Known k = knownData(e, here);
    std::vector<Vec2> ends;
    bool given = true;
    if (k.end) {
        ends.push_back(*k.end);
    } else if (k.x && !runsAlong(carrier, {0.0, 1.0})) {
        ends = intersect(carrier, Carrier::line({*k.x, 0.0}, {0.0, 1.0}));
    } else if (k.y && !runsAlong(carrier, {1.0, 0.0})) {
        ends = intersect(carrier, Carrier::line({0.0, *k.y}, {1.0, 0.0}));
    } else if (k.pr && here.pole) {
        ends = intersect(carrier, Carrier::arc(*here.pole, *k.pr, true));
    } else if (k.paDeg && here.pole) {
        const Vec2 ray = unitAt(*k.paDeg);
        for (const Vec2& p : intersect(carrier, Carrier::line(*here.pole, ray)))
            if (ray.dot(p - *here.pole) > -kFkTolerance) ends.push_back(p);
    } else if (e.length && !carrier.circle) {
        ends.push_back(start + *e.length * carrier.dir);
    } else if (e.length) {
        ends = intersect(carrier, Carrier::arc(start, *e.length, true));
    } else if (e.endAngleAboutCentre && carrier.circle) {
        ends.push_back(carrier.centre + carrier.radius * unitAt(*e.endAngleAboutCentre));
    } else {
        given = false;
    }
    if (!given) {
        // X of a line parallel to Y (or Y of one parallel to X) says where the line lies, not
        // where it ends.
        const double tol = kFkTolerance * carrier.scale();
        if ((k.x && std::fabs(carrier.point.x() - *k.x) > tol) ||
            (k.y && std::fabs(carrier.point.y() - *k.y) > tol)) {
            return {Found::Contradiction, {}};
        }
        return {};
    }
    // Every other datum of the end point must agree.
    EndCandidates out;
    for (const Vec2& p : ends) {
        const double tol = kFkTolerance * std::max(carrier.scale(), p.cwiseAbs().maxCoeff());
        bool ok = carrier.contains(p) && runsForward(carrier, start, p);
        if (k.x && std::fabs(p.x() - *k.x) > tol) ok = false;
        if (k.y && std::fabs(p.y() - *k.y) > tol) ok = false;
        if (k.pr && here.pole && std::fabs((p - *here.pole).norm() - *k.pr) > tol) ok = false;
        if (k.paDeg && here.pole && (p - *here.pole).norm() > tol &&
            !sameDirection((p - *here.pole).normalized(), unitAt(*k.paDeg))) {
            ok = false;
        }
        if (e.length && std::fabs((p - start).norm() - *e.length) > tol) ok = false;
        if (e.endAngleAboutCentre && carrier.circle &&
            !sameDirection((p - carrier.centre).normalized(), unitAt(*e.endAngleAboutCentre))) {
            ok = false;
        }
        if (ok) out.ends.push_back(p);
    }
    if (!carrier.circle) orderAlong(out.ends, carrier.dir);
    out.found = out.ends.empty() ? Found::Contradiction : Found::Some;
    return out;
}

}  // namespace kerf::fk
