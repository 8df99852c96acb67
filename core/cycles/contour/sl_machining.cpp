#include "core/cycles/contour/sl_machining.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/base/translate.h"
#include "core/cycles/drilling/hole_levels.h"
#include "core/geometry/segment_intersection.h"

namespace kerf::cycles::contour {

namespace {

constexpr size_t kMaxLevels = 10000;
constexpr size_t kMaxRings = 10000;

// A subcontour's area, counter-clockwise.
Region areaOf(const SubContour& sub) {
    return regionOf(sub.contour);
}

}  // namespace

CycleError contourError(int cycle, const char* messageTemplate) {
    return CycleError{"cycle-contour", messageTemplate, {std::to_string(cycle)}};
}

std::optional<CycleError> readContourData(int cycle, const CycleContext& ctx, ContourData& out) {
    if (ctx.contourData == nullptr) {
        return contourError(cycle, KERF_TR_NOOP("cycle {1} needs cycle 20 CONTOUR DATA before it"));
    }
    const CycleValues& v = *ctx.contourData;
    if (auto e = checkDepthSign(20, 1, v.number(1), ctx)) return e;
    out.depth = std::fabs(v.number(1));
    out.up = v.number(1) > 0.0 ? -1.0 : 1.0;
    out.overlap = v.number(2);
    out.sideAllowance = v.number(3);
    out.floorAllowance = v.number(4);
    out.surface = v.number(5);
    out.setUpClearance = v.number(6);
    out.clearanceHeight = v.number(7);
    out.cornerRadius = v.number(8);
    // A mirror image reverses the paths; the direction is swapped to keep the milling type.
    out.climb = v.integer(9) >= 0;
    if (ctx.mirroredMain != ctx.mirroredSecondary) out.climb = !out.climb;
    return std::nullopt;
}

size_t levelAt(const ContourArea& area, double depthBelow) {
    for (size_t k = 0; k < area.levels.size(); ++k) {
        if (area.levels[k].bottom >= depthBelow - 1e-9) return k;
    }
    return area.levels.size() - 1;
}

namespace {

std::optional<CycleError> formulaArea(int cycle, const ContourFormula& formula,
                                      const ContourData& data, ContourArea& out) {
    out.levels = formulaLevels(formula, data.depth);
    out.islandsOnly = false;
    if (out.levels.empty()) {
        return contourError(cycle, KERF_TR_NOOP("cycle {1}: the contour formula leaves no area "
                                                "to machine"));
    }
    out.area = out.levels.front().area;
    return std::nullopt;
}

}  // namespace

std::optional<CycleError> combineContours(int cycle, const CycleContext& ctx,
                                          const ContourData& data, ContourArea& out) {
    out.cornerRadius = data.cornerRadius;
    if (ctx.formula) return formulaArea(cycle, *ctx.formula, data, out);
    if (ctx.contours.empty()) {
        return contourError(cycle, KERF_TR_NOOP("cycle {1} needs cycle 14 CONTOUR before it"));
    }
    std::optional<Region> pockets;
    std::optional<Vec2> firstStart;
    std::vector<Region> islandAreas;
    for (const SubContour& sub : ctx.contours) {
        const Region area = areaOf(sub);
        if (sub.island) {
            islandAreas.push_back(area);
            continue;
        }
        if (!pockets) {
            pockets = area;
            firstStart = sub.contour.segments.front().start;
            continue;
        }
        // Spec §6.2: the first pocket starting inside a later one keeps the common area only.
        const bool inside =
            area.contains(*firstStart) && sub.contour.distanceTo(*firstStart) > 1e-6;
        pockets = inside ? intersect(*pockets, area) : unite(*pockets, area);
    }
    const Region islands = islandAreas.empty() ? Region{} : uniteAll(islandAreas);
    if (!pockets) {
        out.area = islands;
        out.islandsOnly = true;
        out.levels = {AreaLevel{data.depth, out.area}};
        return std::nullopt;
    }
    out.area = islands.empty() ? *pockets : subtract(*pockets, islands);
    out.islandsOnly = false;
    if (out.area.empty()) {
        return contourError(cycle, KERF_TR_NOOP("cycle {1}: the islands of cycle 14 cover the "
                                                "whole pocket"));
    }
    out.levels = {AreaLevel{data.depth, out.area}};
    return std::nullopt;
}

Region toolCentreRegion(const ContourArea& area, double inset, size_t level) {
    if (!area.islandsOnly) {
        const Region centre = offsetRegion(area.levels[level].area, -inset);
        if (area.cornerRadius <= 0.0 || centre.empty()) return centre;
        const Region core = offsetRegion(centre, -area.cornerRadius);
        return core.empty() ? core : offsetRegion(core, area.cornerRadius);
    }
    // Around islands only: the tool centre stays outside them, the free side on the left.
    Region around = offsetRegion(area.area, inset);
    for (ClosedContour& c : around.boundaries)
        c = c.reversed();
    return around;
}

std::optional<CycleError> infeedDepths(int cycle, double from, double to, double step,
                                       std::vector<double>& out) {
    out.clear();
    const double span = to - from;
    if (span <= 1e-9) return std::nullopt;
    step = std::fabs(step);
    const double count = step > 0.0 ? std::ceil(span / step - 1e-9) : 1.0;
    if (count > static_cast<double>(kMaxLevels)) return tooManyMoves(cycle);
    const int n = static_cast<int>(count);
    for (int k = 1; k <= n; ++k)
        out.push_back(k == n ? to : from + k * step);
    return std::nullopt;
}

namespace {

// Which boundaries of a clearing level enclose nothing of the next level: an outer boundary
// with no boundary of `inner` inside it, and the holes inside such an outer one. (Holes around
// islands lie left of their outer boundary's area; a hole's outer one is the one enclosing it.)
std::vector<bool> fullWidthRings(const Region& level, const Region& inner) {
    const std::vector<ClosedContour>& rings = level.boundaries;
    std::vector<bool> full(rings.size(), false);
    std::vector<Region> outers(rings.size());
    for (size_t i = 0; i < rings.size(); ++i) {
        if (rings[i].signedArea() <= 0.0) continue;
        outers[i] = Region{{rings[i]}};
        full[i] = true;
        for (const ClosedContour& c : inner.boundaries) {
            if (outers[i].contains(c.segments.front().start)) {
                full[i] = false;
                break;
            }
        }
    }
    for (size_t i = 0; i < rings.size(); ++i) {
        if (rings[i].signedArea() > 0.0) continue;
        const Vec2 p = rings[i].segments.front().start;
        for (size_t j = 0; j < rings.size(); ++j) {
            if (!outers[j].empty() && outers[j].contains(p)) full[i] = full[i] || full[j];
        }
    }
    return full;
}

}  // namespace

namespace {

bool sameRegion(const Region& a, const Region& b) {
    if (a.boundaries.size() != b.boundaries.size()) return false;
    for (size_t i = 0; i < a.boundaries.size(); ++i) {
        const std::vector<PlanarSegment>& x = a.boundaries[i].segments;
        const std::vector<PlanarSegment>& y = b.boundaries[i].segments;
        if (x.size() != y.size()) return false;
        for (size_t k = 0; k < x.size(); ++k) {
            if (x[k].kind != y[k].kind || x[k].start != y[k].start || x[k].end != y[k].end ||
                x[k].center != y[k].center || x[k].sweep != y[k].sweep) {
                return false;
            }
        }
    }
    return true;
}

}  // namespace

const std::vector<ClearingPass>* ClearingCache::find(const Region& region, double step, bool climb,
                                                     const Vec2& from) const {
    for (const Entry& e : m_entries) {
        if (e.step == step && e.climb == climb && e.from == from && sameRegion(e.region, region))
            return &e.passes;
    }
    return nullptr;
}

void ClearingCache::add(const Region& region, double step, bool climb, const Vec2& from,
                        const std::vector<ClearingPass>& passes) {
    if (m_entries.size() >= kEntries) m_entries.erase(m_entries.begin());
    m_entries.push_back(Entry{region, step, climb, from, passes});
}

std::optional<CycleError> planClearing(int cycle, const Region& region, double step, bool climb,
                                       const Vec2& from, std::vector<ClearingPass>& out,
                                       ClearingCache* cache) {
    out.clear();
    if (cache != nullptr) {
        if (const std::vector<ClearingPass>* known = cache->find(region, step, climb, from)) {
            out = *known;
            return std::nullopt;
        }
    }
    // The levels of the offsets, outermost first; a point of level k has 0 ... k steps of room
    // around it inside the outermost region. Each level is the one before shrunk by one step
    // (shrinking by discs adds up): its arcs grow by one step instead of k, so their chords
    // for the engine stay few.
    std::vector<Region> levels;
    for (Region level = region; !level.empty(); level = offsetRegion(levels.back(), -step)) {
        if (levels.size() >= kMaxRings) return tooManyMoves(cycle);
        levels.push_back(std::move(level));
    }
    Vec2 at = from;
    bool first = true;
    size_t atLevel = 0;
    for (size_t k = levels.size(); k-- > 0;) {
        const std::vector<ClosedContour>& rings = levels[k].boundaries;
        const std::vector<bool> full =
            fullWidthRings(levels[k], k + 1 < levels.size() ? levels[k + 1] : Region{});
        std::vector<size_t> left(rings.size());
        for (size_t i = 0; i < left.size(); ++i)
            left[i] = i;
        while (!left.empty()) {
            size_t best = 0;
            double bestDistance = std::numeric_limits<double>::infinity();
            for (size_t i = 0; i < left.size(); ++i) {
                const double d = rings[left[i]].distanceTo(at);
                if (d < bestDistance) {
                    bestDistance = d;
                    best = i;
                }
            }
            const ClosedContour& ring = rings[left[best]];
            ClearingPass p;
            p.path = startingNearest(climb ? ring : ring.reversed(), at);
            p.fullWidth = full[left[best]];
            left.erase(left.begin() + static_cast<std::ptrdiff_t>(best));
            const Vec2 start = p.path.segments.front().start;
            // A disc of radius (level x step) about a point of that level lies inside the
            // outermost region, so a straight move that short stays inside it.
            const double room = static_cast<double>(std::max(k, atLevel)) * step;
            p.straightLink = !first && (start - at).norm() <= room + 1e-9;
            at = start;
            atLevel = k;
            first = false;
            out.push_back(std::move(p));
        }
    }
    if (cache != nullptr) cache->add(region, step, climb, from, out);
    return std::nullopt;
}

Vec2 planningStart(const CycleContext& ctx) {
    if (ctx.formula) return ctx.formula->contours.front().contour.segments.front().start;
    return ctx.contours.front().contour.segments.front().start;
}

namespace {

void followSegments(CyclePath& path, const std::vector<PlanarSegment>& segments, const Feed& feed) {
    const double w = path.w();
    for (const PlanarSegment& s : segments) {
        if (s.kind == PlanarSegment::Kind::Line) {
            path.moveUv(s.end, feed);
        } else {
            path.arc({s.end.x(), s.end.y(), w}, s.center, s.sweep, feed);
        }
    }
}

// The segment from its start to `p` on it.
PlanarSegment segmentUpTo(const PlanarSegment& s, const Vec2& p) {
    if (s.kind == PlanarSegment::Kind::Line) return PlanarSegment::line(s.start, p);
    const Vec2 a = s.start - s.center;
    const Vec2 b = p - s.center;
    double turn = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    if (turn * s.sweep < 0.0)
        turn += s.sweep > 0.0 ? 2.0 * std::numbers::pi : -2.0 * std::numbers::pi;
    return PlanarSegment::arc(s.start, s.center, turn);
}

// Along a closed path from its start to `p` on it, and that way's length.
std::vector<PlanarSegment> pathTo(const ClosedContour& ring, const Vec2& p, double& length) {
    std::vector<PlanarSegment> out;
    length = 0.0;
    for (const PlanarSegment& s : ring.segments) {
        if (s.distanceTo(p) <= 1e-6) {
            const PlanarSegment last = segmentUpTo(s, p);
            if (last.length() > 1e-9) out.push_back(last);
            length += last.length();
            return out;
        }
        out.push_back(s);
        length += s.length();
    }
    return out;
}

}  // namespace

void followPath(CyclePath& path, const ClosedContour& contour, const Feed& feed) {
    followSegments(path, contour.segments, feed);
}

std::vector<size_t> areasOfPasses(const std::vector<ClearingPass>& passes, const Region& region) {
    const size_t none = region.boundaries.size();
    std::vector<size_t> areas;
    for (const ClearingPass& pass : passes) {
        const Vec2 p = pass.path.segments.front().start;
        size_t best = none;
        double bestArea = 0.0;
        for (size_t i = 0; i < region.boundaries.size(); ++i) {
            const double a = region.boundaries[i].signedArea();
            if (a <= 0.0 || (best != none && a >= bestArea)) continue;
            if (Region{{region.boundaries[i]}}.contains(p)) {
                best = i;
                bestArea = a;
            }
        }
        areas.push_back(best);
    }
    return areas;
}

namespace {

// The point at the fraction `t` of a segment's length.
Vec2 pointAlong(const PlanarSegment& s, double t) {
    if (s.kind == PlanarSegment::Kind::Line) return s.start + t * (s.end - s.start);
    const Vec2 r = s.start - s.center;
    const double a = t * s.sweep;
    return s.center + Vec2(std::cos(a) * r.x() - std::sin(a) * r.y(),
                           std::sin(a) * r.x() + std::cos(a) * r.y());
}

// The fraction of a segment's length at `p` on it.
double fractionAt(const PlanarSegment& s, const Vec2& p) {
    if (s.kind == PlanarSegment::Kind::Line) {
        const Vec2 d = s.end - s.start;
        return (p - s.start).dot(d) / d.squaredNorm();
    }
    return segmentUpTo(s, p).sweep / s.sweep;
}

// Whether some stretch of `path` lies in `area` (its boundary counts: the tool centre there
// cuts the area's material). The path is cut where it meets the area's boundaries and at
// their corners on it; a stretch between cuts lies wholly in or out, so its middle decides.
bool entersArea(const std::vector<PlanarSegment>& path, const Region& area) {
    for (const PlanarSegment& s : path) {
        if (s.length() <= 1e-9) continue;
        std::vector<double> cuts{0.0, 1.0};
        for (const ClosedContour& c : area.boundaries) {
            for (const PlanarSegment& b : c.segments) {
                for (const Vec2& p : carrierIntersections(s, b)) {
                    if (s.distanceTo(p) <= 1e-9 && b.distanceTo(p) <= 1e-9)
                        cuts.push_back(fractionAt(s, p));
                }
                if (s.distanceTo(b.start) <= 1e-9) cuts.push_back(fractionAt(s, b.start));
            }
        }
        std::sort(cuts.begin(), cuts.end());
        for (size_t i = 0; i + 1 < cuts.size(); ++i) {
            if (cuts[i + 1] - cuts[i] > 1e-9 &&
                area.contains(pointAlong(s, 0.5 * (cuts[i] + cuts[i + 1])))) {
                return true;
            }
        }
    }
    return false;
}

// The rest area `index` of `rest`: its outer boundary with the holes inside it.
Region restArea(const Region& rest, size_t index) {
    Region area{{rest.boundaries[index]}};
    const Region outer = area;
    for (const ClosedContour& c : rest.boundaries) {
        if (c.signedArea() < 0.0 && outer.contains(c.segments.front().start))
            area.boundaries.push_back(c);
    }
    return area;
}

}  // namespace

void linkAlongContour(std::vector<ClearingPass>& passes, const Region& room, const Region& rest) {
    const std::vector<size_t> areas = areasOfPasses(passes, rest);
    std::vector<size_t> lastPass(rest.boundaries.size() + 1, 0);
    for (size_t i = 0; i < passes.size(); ++i)
        lastPass[areas[i]] = i;
    for (size_t i = 1; i < passes.size(); ++i) {
        ClearingPass& pass = passes[i];
        if (pass.straightLink) continue;
        const Vec2 from = passes[i - 1].path.segments.front().start;
        const Vec2 to = pass.path.segments.front().start;
        // Areas with passes still to come, other than the one the link leads into.
        std::vector<Region> pending;
        for (size_t a = 0; a < rest.boundaries.size(); ++a) {
            if (rest.boundaries[a].signedArea() > 0.0 && a != areas[i] && lastPass[a] >= i)
                pending.push_back(restArea(rest, a));
        }
        auto clear = [&](const std::vector<PlanarSegment>& way) {
            return std::none_of(pending.begin(), pending.end(),
                                [&](const Region& area) { return entersArea(way, area); });
        };
        for (const ClosedContour& boundary : room.boundaries) {
            if (boundary.distanceTo(from) > 1e-6 || boundary.distanceTo(to) > 1e-6) continue;
            const ClosedContour ring = startingNearest(boundary, from);
            double forward = 0.0;
            double backward = 0.0;
            std::vector<PlanarSegment> ahead = pathTo(ring, to, forward);
            std::vector<PlanarSegment> behind = pathTo(ring.reversed(), to, backward);
            if (backward < forward) std::swap(ahead, behind);
            for (std::vector<PlanarSegment>* way : {&ahead, &behind}) {
                if (!clear(*way)) continue;
                pass.contourLink = std::move(*way);
                pass.straightLink = true;
                break;
            }
            break;
        }
    }
}

namespace {

// Whether a disc of `radius` about `centre` lies inside `region`.
bool discInside(const Region& region, const Vec2& centre, double radius) {
    if (!region.contains(centre)) return false;
    for (const ClosedContour& c : region.boundaries) {
        if (c.distanceTo(centre) < radius - 1e-9) return false;
    }
    return true;
}

// Down to `toW` on a helix about `centre` from the current point (on its circle), then back to
// that point along the chord (inside the helix's disc).
void helixDown(CyclePath& path, const Vec2& centre, double toW, double tanAngle, bool ccw,
               const Feed& feed) {
    const Vec2 start = path.uv();
    const double radius = (start - centre).norm();
    const double pitch = 2.0 * std::numbers::pi * radius * tanAngle;
    const double drop = std::fabs(path.w() - toW);
    const double down = toW < path.w() ? -1.0 : 1.0;
    const double dir = ccw ? 1.0 : -1.0;
    double left = drop;
    while (left > 1e-9) {
        const double turn = std::min(1.0, left / pitch);
        left -= turn * pitch;
        const Vec2 from = path.uv() - centre;
        const double sweep = dir * 2.0 * std::numbers::pi * turn;
        const Vec2 end = centre + Vec2(std::cos(sweep) * from.x() - std::sin(sweep) * from.y(),
                                       std::sin(sweep) * from.x() + std::cos(sweep) * from.y());
        const double w = left > 1e-9 ? toW - down * left : toW;
        path.arc({end.x(), end.y(), w}, centre, sweep, feed);
    }
    if ((path.uv() - start).norm() > 1e-9) path.moveUv(start, feed);
}

// The first `length` of a closed path from its start (the last piece cut there).
std::vector<PlanarSegment> pathStart(const ClosedContour& contour, double length) {
    std::vector<PlanarSegment> piece;
    double left = length;
    for (const PlanarSegment& s : contour.segments) {
        if (left <= 1e-9) break;
        const double l = s.length();
        if (l <= left + 1e-9) {
            piece.push_back(s);
            left -= l;
            continue;
        }
        const double f = left / l;
        piece.push_back(s.kind == PlanarSegment::Kind::Arc
                            ? PlanarSegment::arc(s.start, s.center, s.sweep * f)
                            : PlanarSegment::line(s.start, s.start + f * (s.end - s.start)));
        left = 0.0;
    }
    return piece;
}

// Follows `piece` forwards or backwards while the tool axis goes linearly to `toW`.
void stroke(CyclePath& path, const std::vector<PlanarSegment>& piece, bool forward, double toW,
            const Feed& feed) {
    double total = 0.0;
    for (const PlanarSegment& s : piece)
        total += s.length();
    const double fromW = path.w();
    double done = 0.0;
    for (size_t i = 0; i < piece.size(); ++i) {
        const PlanarSegment s = forward ? piece[i] : piece[piece.size() - 1 - i].reversed();
        done += s.length();
        const double w = fromW + (toW - fromW) * (total > 0.0 ? done / total : 1.0);
        if (s.kind == PlanarSegment::Kind::Arc) {
            path.arc({s.end.x(), s.end.y(), w}, s.center, s.sweep, feed);
        } else {
            path.move({s.end.x(), s.end.y(), w}, feed);
        }
    }
}

// Down to `toW` to and fro along the path's first `length`, each stroke descending at most
// tan(ANGLE) per unit of path, all strokes alike; then back to the start at the depth.
void reciprocateDown(CyclePath& path, const ClosedContour& contour, double length, double toW,
                     double tanAngle, const Feed& feed) {
    const std::vector<PlanarSegment> piece = pathStart(contour, length);
    const double drop = std::fabs(path.w() - toW);
    const auto strokes =
        static_cast<size_t>(std::max(1.0, std::ceil(drop / (length * tanAngle) - 1e-9)));
    const double fromW = path.w();
    bool forward = true;
    for (size_t i = 1; i <= strokes; ++i) {
        stroke(path, piece, forward,
               fromW + (toW - fromW) * static_cast<double>(i) / static_cast<double>(strokes), feed);
        forward = !forward;
    }
    if (!forward) stroke(path, piece, false, toW, feed);
}

// Over the point `approachRadius` back along u from the pass's start, down to the arc's top (at
// rapid as far as the re-entry height), then the quarter arc in the plane of u and the tool axis
// about the point that high above the start, ending on the start tangent to the floor.
void approachOnArc(CyclePath& path, const ClearingPass& pass, const ContourData& data, double w,
                   double reentryW, const Feed& feed) {
    const Vec2 start = pass.path.segments.front().start;
    const Vec2 along(pass.approachDirection, 0.0);
    const double top = w + data.up * pass.approachRadius;
    path.rapidUv(start - pass.approachRadius * along);
    path.rapidW((reentryW - top) * data.up > 0.0 ? reentryW : top);
    path.moveW(top, feed);
    path.spatialArc({start.x(), start.y(), w}, {start.x(), start.y(), top}, feed);
}

}  // namespace

double reciprocatingStrokes(const ClearingPass& pass, double drop, double tanAngle) {
    if (pass.strokeLength <= 0.0 || tanAngle <= 0.0) return 0.0;
    return std::ceil(drop / (pass.strokeLength * tanAngle));
}

bool placeHelices(std::vector<ClearingPass>& passes, const Region& region, double radius,
                  double strokeLength) {
    for (ClearingPass& pass : passes) {
        if (pass.straightLink) continue;
        const ClosedContour& ring = pass.path;
        const Vec2 start = ring.segments.front().start;
        const Vec2 t = ring.segments.front().startTangent();
        const Vec2 normal(-t.y(), t.x());
        bool placed = false;
        for (double r = radius; r >= radius / 4.0 - 1e-12 && !placed; r /= 2.0) {
            for (double side : {1.0, -1.0}) {
                const Vec2 centre = start + side * r * normal;
                if (discInside(region, centre, r)) {
                    pass.helixCentre = centre;
                    pass.helixRadius = r;
                    placed = true;
                    break;
                }
            }
        }
        if (placed) continue;
        if (strokeLength <= 0.0) return false;
        double perimeter = 0.0;
        for (const PlanarSegment& seg : ring.segments)
            perimeter += seg.length();
        pass.strokeLength = std::min(strokeLength, perimeter / 2.0);
    }
    return true;
}

void placeApproachArcs(std::vector<ClearingPass>& passes, const Region& region, double radius) {
    for (ClearingPass& pass : passes) {
        if (pass.straightLink) continue;
        const Vec2 start = pass.path.segments.front().start;
        // Never against the pass: either way only when it starts across u.
        const double along = pass.path.segments.front().startTangent().x();
        std::vector<double> directions{along < -1e-9 ? -1.0 : 1.0};
        if (std::fabs(along) <= 1e-9) directions.push_back(-1.0);
        bool placed = false;
        for (double r = radius; r >= radius / 4.0 - 1e-12 && !placed; r /= 2.0) {
            for (double direction : directions) {
                if (containsLine(region, start - Vec2(r * direction, 0.0), start)) {
                    pass.approachRadius = r;
                    pass.approachDirection = direction;
                    placed = true;
                    break;
                }
            }
        }
    }
}

void runClearing(CyclePath& path, const std::vector<ClearingPass>& passes, const ContourData& data,
                 double w, double reentryW, const Feed& mill, const Feed& plunge,
                 const ClearingOptions& options) {
    Feed reduced = mill;
    reduced.value *= options.fullWidthFactor;
    for (const ClearingPass& pass : passes) {
        const Vec2 start = pass.path.segments.front().start;
        if (pass.straightLink) {
            followSegments(path, pass.contourLink, mill);
            path.moveUv(start, mill);
        } else {
            // Over islands and uncut material: up to the set-up clearance above the surface.
            if ((path.w() - data.aboveSurface()) * data.up < 0.0) path.rapidW(data.aboveSurface());
            if (pass.approachRadius > 0.0) {
                approachOnArc(path, pass, data, w, reentryW, plunge);
            } else {
                path.rapidUv(start);
                path.rapidW(reentryW);
                if (options.helixTan > 0.0 && pass.helixRadius > 0.0) {
                    helixDown(path, pass.helixCentre, w, options.helixTan, options.climb, plunge);
                } else if (options.helixTan > 0.0 && pass.strokeLength > 0.0) {
                    reciprocateDown(path, pass.path, pass.strokeLength, w, options.helixTan,
                                    plunge);
                } else {
                    path.moveW(w, plunge);
                }
            }
        }
        followPath(path, pass.path, pass.fullWidth ? reduced : mill);
    }
}

}  // namespace kerf::cycles::contour
