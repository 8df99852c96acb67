#include "core/geometry/contour_region.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <numbers>
#include <optional>

#include <clipper.hpp>

#include "core/geometry/segment_intersection.h"

namespace kerf {

namespace {

using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;

constexpr double kPi = std::numbers::pi;
constexpr double kScale = 1e6;       // Clipper units per mm (1 nm)
constexpr double kFlatten = 0.5e-3;  // mm: largest gap between an arc and its chords
constexpr double kMatch = 2e-3;      // mm: a polygon point lies on an exact piece
constexpr double kSame = 1e-9;       // mm: shorter segments are left out

double cross(const Vec2& a, const Vec2& b) {
    return a.x() * b.y() - a.y() * b.x();
}

Vec2 rightOf(const Vec2& direction) {
    return {direction.y(), -direction.x()};
}

Vec2 rotated(const Vec2& p, double angle) {
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    return {c * p.x() - s * p.y(), s * p.x() + c * p.y()};
}

// Clamped to the engine's range, so that a point no caller should pass cannot overflow the grid.
IntPoint toInt(const Vec2& p) {
    static constexpr double kLimit = kMaxContourCoordinateMm * kScale;
    const auto grid = [](double v) {
        return std::llround(std::isfinite(v) ? std::clamp(v * kScale, -kLimit, kLimit) : 0.0);
    };
    return {grid(p.x()), grid(p.y())};
}

Vec2 toVec(const IntPoint& p) {
    return {static_cast<double>(p.X) / kScale, static_cast<double>(p.Y) / kScale};
}

// The angle of the chords that stay within `tolerance` of the arc `s` and of its offset by
// `distance` (which makes a counter-clockwise arc's radius grow by `distance`).
double chordAngle(const PlanarSegment& s, double distance, double tolerance = kFlatten) {
    const double r = s.radius();
    const double grown = r + (s.sweep > 0.0 ? distance : -distance);
    const double sagitta = tolerance * std::min(1.0, r / std::max(grown, 1e-12));
    return std::min(kPi / 8.0, 2.0 * std::acos(std::max(-1.0, 1.0 - sagitta / r)));
}

// Chords of at most `tolerance` from their arc after an offset by `distance` (which makes a
// counter-clockwise arc's radius grow by `distance`: its chords move apart by the same ratio).
void flattenInto(const ClosedContour& contour, double distance, Path& out,
                 double tolerance = kFlatten) {
    for (const PlanarSegment& s : contour.segments) {
        out.push_back(toInt(s.start));
        if (s.kind != PlanarSegment::Kind::Arc) continue;
        const double step = chordAngle(s, distance, tolerance);
        const int n = std::max(1, static_cast<int>(std::ceil(std::fabs(s.sweep) / step)));
        // One rotation applied n times instead of n sines and cosines: after the few thousand
        // steps of the largest arc the error is some 1e-13 of the radius.
        const double c = std::cos(s.sweep / n);
        const double sn = std::sin(s.sweep / n);
        Vec2 radial = s.start - s.center;
        for (int k = 1; k < n; ++k) {
            radial = Vec2(c * radial.x() - sn * radial.y(), sn * radial.x() + c * radial.y());
            out.push_back(toInt(s.center + radial));
        }
    }
}

Paths flattened(const Region& region, double distance) {
    Paths out;
    for (const ClosedContour& c : region.boundaries) {
        Path p;
        flattenInto(c, distance, p);
        if (p.size() >= 2) out.push_back(std::move(p));
    }
    return out;
}

// An axis-aligned box (the pieces' extents, grown by the matching tolerance).
struct Box {
    Vec2 low{0.0, 0.0}, high{0.0, 0.0};

    static Box around(const Vec2& centre, double radius) {
        const Vec2 r(radius + kMatch, radius + kMatch);
        return {centre - r, centre + r};
    }
    static Box of(const Vec2& a, const Vec2& b) {
        const Vec2 m(kMatch, kMatch);
        return {a.cwiseMin(b) - m, a.cwiseMax(b) + m};
    }
    void include(const Vec2& p) {
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
    }
};

// A piece of the exact result: a line, or an arc of a circle over an angular range.
struct Piece {
    bool arc = false;
    Vec2 a{0.0, 0.0}, b{0.0, 0.0};  // line
    Vec2 centre{0.0, 0.0};          // arc
    double radius = 0.0;
    double startAngle = 0.0;
    double sweep = 0.0;
    // The angular range with its tolerance as a cone about the arc's middle direction: a point
    // is within it when its direction is at most the half angle from `middle` (no atan2 in
    // the hot loop). `wholeCircle` when the half angle reaches pi.
    Vec2 middle{1.0, 0.0};
    double cosHalfAngle = -1.0;
    bool wholeCircle = true;
    Box box;

    bool holds(const Vec2& p) const {
        if (!arc) {
            const Vec2 d = b - a;
            const double length = d.norm();
            const double along = length > 0.0 ? (p - a).dot(d) / length : 0.0;
            if (along < -kMatch || along > length + kMatch) return false;
            const Vec2 foot =
                length > 0.0 ? Vec2(a + std::clamp(along, 0.0, length) * d / length) : a;
            return (p - foot).norm() <= kMatch;
        }
        const Vec2 v = p - centre;
        const double distance = v.norm();
        if (std::fabs(distance - radius) > kMatch) return false;
        return wholeCircle || v.dot(middle) >= cosHalfAngle * distance;
    }
    Vec2 project(const Vec2& p) const {
        if (!arc) {
            const Vec2 d = (b - a).normalized();
            return a + (p - a).dot(d) * d;
        }
        const Vec2 v = p - centre;
        return v.norm() > 0.0 ? Vec2(centre + radius * v.normalized()) : p;
    }
    PlanarSegment carrier() const {
        if (!arc) return PlanarSegment::line(a, b);
        const Vec2 start = centre + radius * Vec2(std::cos(startAngle), std::sin(startAngle));
        return PlanarSegment::arc(start, centre, sweep);
    }
};

// `angleSlack`: offset chords overshoot their arc's ends a little, so far beyond them a point
// still counts.
Piece linePiece(const Vec2& a, const Vec2& b) {
    Piece p;
    p.a = a;
    p.b = b;
    p.box = Box::of(a, b);
    return p;
}

// The box of the arc `p` over its middle direction +- `halfAngle` (< pi): its ends and the
// quadrant points in between.
Box arcBox(const Piece& p, double halfAngle) {
    const double middleAngle = std::atan2(p.middle.y(), p.middle.x());
    auto at = [&](double angle) {
        return Vec2(p.centre + p.radius * Vec2(std::cos(angle), std::sin(angle)));
    };
    Box box = Box::of(at(middleAngle - halfAngle), at(middleAngle + halfAngle));
    for (int quadrant = -4; quadrant <= 4; ++quadrant) {
        const double angle = quadrant * kPi / 2.0;
        if (std::fabs(std::remainder(angle - middleAngle, 2.0 * kPi)) <= halfAngle) {
            const Vec2 m(kMatch, kMatch);
            box.include(at(angle) - m);
            box.include(at(angle) + m);
        }
    }
    return box;
}

void addArcPiece(std::vector<Piece>& out, const Vec2& centre, double radius, const Vec2& from,
                 double sweep, double angleSlack) {
    if (radius <= kMatch || std::fabs(sweep) < 1e-12) return;
    Piece p;
    p.arc = true;
    p.centre = centre;
    p.radius = radius;
    p.startAngle = std::atan2(from.y(), from.x());
    p.sweep = sweep;
    const double halfAngle =
        std::fabs(sweep) / 2.0 + kMatch / std::max(radius, kMatch) + angleSlack;
    p.wholeCircle = halfAngle >= kPi;
    const double middleAngle = p.startAngle + sweep / 2.0;
    p.middle = Vec2(std::cos(middleAngle), std::sin(middleAngle));
    p.cosHalfAngle = std::cos(halfAngle);
    p.box = p.wholeCircle ? Box::around(centre, radius) : arcBox(p, halfAngle);
    out.push_back(p);
}

// The exact pieces the boundary of `region` offset by `distance` is made of: lines moved along
// their normal, arcs with a changed radius and, at the corners, arcs of radius |distance|.
void addPieces(const Region& region, double distance, std::vector<Piece>& out) {
    const double side = distance >= 0.0 ? 1.0 : -1.0;
    for (const ClosedContour& contour : region.boundaries) {
        const size_t n = contour.segments.size();
        for (size_t i = 0; i < n; ++i) {
            const PlanarSegment& s = contour.segments[i];
            if (s.kind == PlanarSegment::Kind::Line) {
                if ((s.end - s.start).norm() < kSame) continue;
                const Vec2 shift = distance * rightOf(s.startTangent());
                out.push_back(linePiece(s.start + shift, s.end + shift));
            } else {
                const double r = s.radius() + (s.sweep > 0.0 ? distance : -distance);
                addArcPiece(out, s.center, r, s.start - s.center, s.sweep,
                            2.0 * chordAngle(s, distance));
            }
            if (distance == 0.0) continue;
            const PlanarSegment& next = contour.segments[(i + 1) % n];
            const Vec2 in = side * rightOf(s.endTangent());
            const Vec2 out2 = side * rightOf(next.startTangent());
            const double turn = std::atan2(cross(in, out2), in.dot(out2));
            addArcPiece(out, s.end, std::fabs(distance), in, turn, 0.0);
        }
    }
}

// The pieces by where they lie: a uniform grid of about one cell per piece, each cell listing
// (in increasing order) the pieces whose box meets it, so that a polygon point is tested against
// the few pieces near it instead of all of them.
class PieceGrid {
public:
    explicit PieceGrid(const std::vector<Piece>& pieces) {
        if (pieces.empty()) return;
        Box all = pieces.front().box;
        for (const Piece& p : pieces) {
            all.include(p.box.low);
            all.include(p.box.high);
        }
        m_low = all.low;
        const Vec2 size = (all.high - all.low).cwiseMax(Vec2(kMatch, kMatch));
        const double side = std::ceil(std::sqrt(static_cast<double>(pieces.size())));
        m_columns = static_cast<int>(side);
        m_rows = static_cast<int>(side);
        m_cell = Vec2(size.x() / m_columns, size.y() / m_rows);
        m_cells.resize(static_cast<size_t>(m_columns) * static_cast<size_t>(m_rows));
        for (size_t i = 0; i < pieces.size(); ++i) {
            const auto [c0, r0] = cellOf(pieces[i].box.low);
            const auto [c1, r1] = cellOf(pieces[i].box.high);
            for (int r = r0; r <= r1; ++r) {
                for (int c = c0; c <= c1; ++c)
                    m_cells[index(c, r)].push_back(static_cast<uint32_t>(i));
            }
        }
    }

    const std::vector<uint32_t>& near(const Vec2& p) const {
        if (m_cells.empty()) return m_none;
        const auto [c, r] = cellOf(p);
        return m_cells[index(c, r)];
    }

private:
    std::pair<int, int> cellOf(const Vec2& p) const {
        const auto clampTo = [](double v, int count) {
            return static_cast<int>(std::clamp(std::floor(v), 0.0, count - 1.0));
        };
        return {clampTo((p.x() - m_low.x()) / m_cell.x(), m_columns),
                clampTo((p.y() - m_low.y()) / m_cell.y(), m_rows)};
    }
    size_t index(int column, int row) const {
        return static_cast<size_t>(row) * static_cast<size_t>(m_columns) +
               static_cast<size_t>(column);
    }

    Vec2 m_low{0.0, 0.0};
    Vec2 m_cell{1.0, 1.0};
    int m_columns = 0;
    int m_rows = 0;
    std::vector<std::vector<uint32_t>> m_cells;
    std::vector<uint32_t> m_none;
};

struct Run {
    size_t firstEdge = 0;
    size_t edges = 0;
    std::vector<size_t> pieces;  // the pieces every edge of the run lies on
};

class Rebuilder {
public:
    Rebuilder(const std::vector<Vec2>& points, std::vector<Piece>& pieces, const PieceGrid& grid)
        : m_points(points), m_pieces(pieces), m_grid(grid) {}

    std::optional<ClosedContour> rebuild() {
        std::vector<Run> runs;
        runsFrom(0, runs);
        if (runs.size() > 1) runsFrom(runs[1].firstEdge, runs);
        if (runs.size() > 1) mergeEnds(runs);
        if (runs.size() == 1) return fullCircle(runs.front());
        const size_t count = runs.size();
        std::vector<Vec2> junctions(count);
        for (size_t j = 0; j < count; ++j) {
            const Run& before = runs[(j + count - 1) % count];
            junctions[j] = junction(m_pieces[before.pieces.front()],
                                    m_pieces[runs[j].pieces.front()], m_points[runs[j].firstEdge]);
        }
        ClosedContour out;
        for (size_t j = 0; j < count; ++j) {
            const Piece& piece = m_pieces[runs[j].pieces.front()];
            const Vec2& from = junctions[j];
            const Vec2& to = junctions[(j + 1) % count];
            if (!piece.arc) {
                if ((to - from).norm() >= kSame)
                    out.segments.push_back(PlanarSegment::line(from, to));
                continue;
            }
            const double sweep = sweepAlong(piece, runs[j], from, to);
            if (std::fabs(sweep) * piece.radius < kSame) continue;
            out.segments.push_back({PlanarSegment::Kind::Arc, from, to, piece.centre, sweep});
        }
        if (out.segments.empty()) return std::nullopt;
        return out;
    }

private:
    Vec2 point(size_t i) const { return m_points[i % m_points.size()]; }

    bool edgeOn(size_t piece, size_t edge) const {
        const Piece& p = m_pieces[piece];
        return p.holds(point(edge)) && edgeGoesOn(piece, edge);
    }
    // The rest of edgeOn for an edge whose start the piece is known to hold (it held the edge
    // before): the hot path of long runs along flattened arcs.
    bool edgeGoesOn(size_t piece, size_t edge) const {
        const Piece& p = m_pieces[piece];
        const Vec2 a = point(edge);
        const Vec2 b = point(edge + 1);
        return p.holds(b) && p.holds((a + b) / 2.0);
    }

    // Greedy: each run goes on while some piece holds all its edges (fewest runs).
    void runsFrom(size_t first, std::vector<Run>& runs) {
        runs.clear();
        const size_t m = m_points.size();
        for (size_t k = 0; k < m; ++k) {
            const size_t edge = (first + k) % m;
            if (!runs.empty()) {
                std::vector<size_t> still;
                for (size_t p : runs.back().pieces) {
                    if (edgeGoesOn(p, edge)) still.push_back(p);
                }
                if (!still.empty()) {
                    runs.back().pieces = std::move(still);
                    ++runs.back().edges;
                    continue;
                }
            }
            Run run{edge, 1, {}};
            for (uint32_t p : m_grid.near(point(edge))) {
                if (edgeOn(p, edge)) run.pieces.push_back(p);
            }
            if (run.pieces.empty()) {
                // Not on any exact piece (should not happen): keep the polygon edge itself.
                m_pieces.push_back(linePiece(point(edge), point(edge + 1)));
                run.pieces.push_back(m_pieces.size() - 1);
            }
            runs.push_back(std::move(run));
        }
    }

    void mergeEnds(std::vector<Run>& runs) const {
        Run& first = runs.front();
        const Run& last = runs.back();
        std::vector<size_t> common;
        for (size_t p : first.pieces) {
            if (std::find(last.pieces.begin(), last.pieces.end(), p) != last.pieces.end()) {
                common.push_back(p);
            }
        }
        if (common.empty()) return;
        first.pieces = std::move(common);
        first.firstEdge = last.firstEdge;
        first.edges += last.edges;
        runs.pop_back();
    }

    std::optional<ClosedContour> fullCircle(const Run& run) const {
        const Piece& piece = m_pieces[run.pieces.front()];
        if (!piece.arc) return std::nullopt;
        double turned = 0.0;
        for (size_t i = 0; i < m_points.size(); ++i) {
            const Vec2 a = point(i) - piece.centre;
            const Vec2 b = point(i + 1) - piece.centre;
            turned += std::atan2(cross(a, b), a.dot(b));
        }
        const Vec2 start = piece.project(m_points.front());
        ClosedContour out;
        out.segments.push_back({PlanarSegment::Kind::Arc, start, start, piece.centre,
                                turned >= 0.0 ? 2.0 * kPi : -2.0 * kPi});
        return out;
    }

    static Vec2 junction(const Piece& a, const Piece& b, const Vec2& near) {
        const std::vector<Vec2> hits = carrierIntersections(a.carrier(), b.carrier());
        const Vec2* best = nullptr;
        for (const Vec2& h : hits) {
            if (best == nullptr || (h - near).norm() < (*best - near).norm()) best = &h;
        }
        if (best != nullptr && (*best - near).norm() < 50.0 * kMatch) return *best;
        // Tangent pieces that just miss each other numerically: where they come closest.
        const Vec2 touch = closestApproach(a, b, near);
        return (a.project(touch) + b.project(touch)) / 2.0;
    }

    // A point where the carriers of two tangent pieces come closest (the tangent point).
    static Vec2 closestApproach(const Piece& a, const Piece& b, const Vec2& near) {
        if (a.arc && b.arc) {
            const Vec2 d = b.centre - a.centre;
            if (d.norm() < 1e-12) return near;
            const Vec2 u = d.normalized();
            const Vec2 p1 = a.centre + a.radius * u;
            const Vec2 p2 = a.centre - a.radius * u;
            return (p1 - near).norm() <= (p2 - near).norm() ? p1 : p2;
        }
        if (a.arc) return a.project(b.project(a.centre));
        if (b.arc) return b.project(a.project(b.centre));
        return near;
    }

    double sweepAlong(const Piece& piece, const Run& run, const Vec2& from, const Vec2& to) const {
        double turned = 0.0;
        Vec2 previous = from - piece.centre;
        for (size_t k = 1; k <= run.edges; ++k) {
            const Vec2 next = (k == run.edges ? to : point(run.firstEdge + k)) - piece.centre;
            turned += std::atan2(cross(previous, next), previous.dot(next));
            previous = next;
        }
        return turned;
    }

    const std::vector<Vec2>& m_points;
    std::vector<Piece>& m_pieces;
    const PieceGrid& m_grid;
};

double perimeter(const std::vector<Vec2>& points) {
    double sum = 0.0;
    for (size_t i = 0; i < points.size(); ++i)
        sum += (points[(i + 1) % points.size()] - points[i]).norm();
    return sum;
}

// The polygon itself, when no exact rebuild fits it.
ClosedContour polygonContour(const std::vector<Vec2>& points) {
    ClosedContour out;
    for (size_t i = 0; i < points.size(); ++i) {
        const Vec2& a = points[i];
        const Vec2& b = points[(i + 1) % points.size()];
        if ((b - a).norm() >= kSame) out.segments.push_back(PlanarSegment::line(a, b));
    }
    return out;
}

Region rebuildAll(const Paths& solution, std::vector<Piece> pieces) {
    const PieceGrid grid(pieces);
    Region out;
    for (const Path& path : solution) {
        if (path.size() < 3) continue;
        std::vector<Vec2> points;
        points.reserve(path.size());
        for (const IntPoint& p : path)
            points.push_back(toVec(p));
        // Slivers thinner than the matching tolerance are rounding noise between boundaries
        // that coincide (a rest region along a wall both tools reach).
        const double area = ClipperLib::Area(path) / (kScale * kScale);
        const double length = perimeter(points);
        if (2.0 * std::fabs(area) <= kMatch * length) continue;
        Rebuilder rebuilder(points, pieces, grid);
        std::optional<ClosedContour> contour = rebuilder.rebuild();
        // The exact pieces must enclose what the polygon encloses (within the flattening).
        const double slack = 2.0 * kMatch * length;
        if (!contour || std::fabs(contour->signedArea() - area) > slack) {
            contour = polygonContour(points);
        }
        out.boundaries.push_back(std::move(*contour));
    }
    return out;
}

Region boolean(ClipperLib::ClipType type, const Region& a, const Region& b) {
    ClipperLib::Clipper clipper;
    clipper.AddPaths(flattened(a, 0.0), ClipperLib::ptSubject, true);
    clipper.AddPaths(flattened(b, 0.0), ClipperLib::ptClip, true);
    Paths solution;
    try {
        clipper.Execute(type, solution, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    } catch (const std::exception&) {
        return {};  // Clipper's range exceeded: the callers' range check makes this unreachable
    }
    std::vector<Piece> pieces;
    addPieces(a, 0.0, pieces);
    addPieces(b, 0.0, pieces);
    return rebuildAll(solution, std::move(pieces));
}

}  // namespace

double Region::area() const {
    double sum = 0.0;
    for (const ClosedContour& c : boundaries)
        sum += c.signedArea();
    return sum;
}

bool Region::contains(const Vec2& p) const {
    int winding = 0;
    const IntPoint q = toInt(p);
    for (const ClosedContour& c : boundaries) {
        const double distance = c.distanceTo(p);
        if (distance <= kMatch) return true;
        // Chords within half the point's distance of their arcs put it on the same side as the
        // arcs do: far from the boundary a few chords decide.
        Path path;
        flattenInto(c, 0.0, path, distance / 2.0);
        if (ClipperLib::PointInPolygon(q, path) != 0) winding += c.signedArea() > 0.0 ? 1 : -1;
    }
    return winding > 0;
}

Region regionOf(const ClosedContour& contour) {
    Region out;
    out.boundaries.push_back(contour.signedArea() >= 0.0 ? contour : contour.reversed());
    return out;
}

Region unite(const Region& a, const Region& b) {
    return boolean(ClipperLib::ctUnion, a, b);
}

Region uniteAll(const std::vector<Region>& regions) {
    Region all;
    for (const Region& r : regions)
        all.boundaries.insert(all.boundaries.end(), r.boundaries.begin(), r.boundaries.end());
    return unite(all, Region{});
}

Region subtract(const Region& a, const Region& b) {
    return boolean(ClipperLib::ctDifference, a, b);
}

Region intersect(const Region& a, const Region& b) {
    return boolean(ClipperLib::ctIntersection, a, b);
}

Region offsetRegion(const Region& region, double distance) {
    // Farther than the engine's range everything vanishes inwards; outwards it is out of range.
    if (!std::isfinite(distance) || std::fabs(distance) > kMaxContourCoordinateMm) return {};
    ClipperLib::ClipperOffset offset(2.0, kFlatten * kScale / 2.0);
    offset.AddPaths(flattened(region, distance), ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    Paths solution;
    try {
        offset.Execute(solution, distance * kScale);
    } catch (const std::exception&) {
        return {};
    }
    std::vector<Piece> pieces;
    addPieces(region, distance, pieces);
    return rebuildAll(solution, std::move(pieces));
}

bool containsLine(const Region& region, const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    const double length2 = d.squaredNorm();
    if (length2 <= 0.0) return region.contains(a);
    // Cut where the line meets a boundary; each piece between cuts lies wholly inside or outside.
    const PlanarSegment line = PlanarSegment::line(a, b);
    std::vector<double> cuts{0.0, 1.0};
    for (const ClosedContour& c : region.boundaries) {
        for (const PlanarSegment& s : c.segments) {
            for (const Vec2& p : carrierIntersections(line, s)) {
                const double t = (p - a).dot(d) / length2;
                if (t > 0.0 && t < 1.0 && s.distanceTo(p) <= 1e-9) cuts.push_back(t);
            }
        }
    }
    std::sort(cuts.begin(), cuts.end());
    for (size_t i = 0; i + 1 < cuts.size(); ++i) {
        if (!region.contains(a + 0.5 * (cuts[i] + cuts[i + 1]) * d)) return false;
    }
    return region.contains(a) && region.contains(b);
}

bool selfIntersects(const ClosedContour& contour) {
    Path path;
    flattenInto(contour, 0.0, path);
    Paths simple;
    try {
        ClipperLib::SimplifyPolygon(path, simple, ClipperLib::pftNonZero);
    } catch (const std::exception&) {
        return true;  // not a contour the engine can take
    }
    if (simple.size() != 1) return true;
    const double before = std::fabs(ClipperLib::Area(path));
    const double after = std::fabs(ClipperLib::Area(simple.front()));
    return std::fabs(before - after) > 1e-6 * std::max(before, 1.0);
}

ClosedContour startingNearest(const ClosedContour& contour, const Vec2& p) {
    const size_t n = contour.segments.size();
    size_t best = 0;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < n; ++i) {
        const double d = contour.segments[i].distanceTo(p);
        if (d < bestDistance) {
            bestDistance = d;
            best = i;
        }
    }
    const PlanarSegment& s = contour.segments[best];
    std::vector<PlanarSegment> head, tail;
    if (s.kind == PlanarSegment::Kind::Line) {
        const Vec2 d = s.end - s.start;
        const double t =
            std::clamp((p - s.start).dot(d) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
        const Vec2 q = s.start + t * d;
        tail.push_back(PlanarSegment::line(s.start, q));
        head.push_back(PlanarSegment::line(q, s.end));
    } else {
        const double sign = s.sweep >= 0.0 ? 1.0 : -1.0;
        const Vec2 a = s.start - s.center;
        const Vec2 v = p - s.center;
        double rel = sign * std::atan2(cross(a, v), a.dot(v));
        if (rel < 0.0) rel += 2.0 * kPi;
        if (rel > std::fabs(s.sweep)) {
            // Beyond the arc's ends: the nearer end.
            rel = (p - s.start).norm() <= (p - s.end).norm() ? 0.0 : std::fabs(s.sweep);
        }
        const double cut = sign * rel;
        const Vec2 q = s.center + rotated(a, cut);
        tail.push_back({PlanarSegment::Kind::Arc, s.start, q, s.center, cut});
        head.push_back({PlanarSegment::Kind::Arc, q, s.end, s.center, s.sweep - cut});
    }
    ClosedContour out;
    auto keep = [&](const PlanarSegment& seg) {
        if (seg.length() >= kSame) out.segments.push_back(seg);
    };
    for (const PlanarSegment& seg : head)
        keep(seg);
    for (size_t k = 1; k < n; ++k)
        keep(contour.segments[(best + k) % n]);
    for (const PlanarSegment& seg : tail)
        keep(seg);
    return out;
}

}  // namespace kerf
