// Cycle 233 FACE MILLING WITH SIDE WALLS (spec §4): the face from the tool position at the call
// over Q218 x Q219, paths along the main (Q350 1) or secondary axis (2), up to three side walls
// (Q347-Q349) the tool stays R + Q368 from while roughing and finishes at R. Depths as in 232:
// equal roughing infeeds of at most Q202 to Q386 + Q369, then the floor at Q385.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "core/cycles/common_parameters.h"
#include "core/cycles/cycle_path.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/hole_levels.h"
#include "core/cycles/pocket/pocket_parameters.h"
#include "core/geometry/arc_math.h"

namespace kerf::cycles {

namespace {

using namespace common;

constexpr size_t kMaxPaths = 10000;

enum class Strategy : uint8_t { Meander, MeanderOnEdge, Lines, LinesToEdge, Spiral };

constexpr ParameterDescriptor limit(uint16_t q, const char* description) {
    return {.q = q, .description = description, .min = -2.0, .max = 2.0, .integer = true};
}

constexpr ParameterDescriptor kParameters[] = {
    pocket::kOperation,
    {.q = 389,
     .description = KERF_TR_NOOP("Strategy (0 meander outside, 1 meander on the edge, 2 line by "
                                 "line, 3 line by line to the edge, 4 spiral)"),
     .min = 0.0,
     .max = 4.0,
     .defaultValue = 0.0,
     .integer = true},
    {.q = 350,
     .description = KERF_TR_NOOP("Milling direction (1 main axis, 2 secondary axis)"),
     .min = 1.0,
     .max = 2.0,
     .defaultValue = 1.0,
     .integer = true},
    {.q = 218,
     .description = KERF_TR_NOOP("First side length (sign = direction)"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 100.0},
    {.q = 219,
     .description = KERF_TR_NOOP("Second side length (sign = direction)"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength,
     .defaultValue = 50.0},
    {.q = 227,
     .description = KERF_TR_NOOP("Starting point in the 3rd axis (surface)"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength},
    {.q = 386,
     .description = KERF_TR_NOOP("End point in the 3rd axis"),
     .unit = Unit::Millimetre,
     .min = -kLength,
     .max = kLength},
    pocket::kFloorAllowance,
    {.q = 202,
     .description = KERF_TR_NOOP("Maximum plunging depth"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 2.0},
    {.q = 370,
     .description = KERF_TR_NOOP("Maximum path overlap factor"),
     .unit = Unit::Factor,
     .min = 0.1,
     .max = 1.9999,
     .defaultValue = 1.0},
    pocket::kMillingFeed,
    pocket::kFinishingFeed,
    kPrePositionFeed,
    {.q = 357,
     .description = KERF_TR_NOOP("Lateral clearance to the workpiece"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 2.0},
    kSetUpClearance,
    kSecondClearance,
    limit(347, KERF_TR_NOOP("1st limit (0 none, -1/+1 main axis, -2/+2 secondary axis)")),
    limit(348, KERF_TR_NOOP("2nd limit (0 none, -1/+1 main axis, -2/+2 secondary axis)")),
    limit(349, KERF_TR_NOOP("3rd limit (0 none, -1/+1 main axis, -2/+2 secondary axis)")),
    {.q = 220,
     .description = KERF_TR_NOOP("Corner radius"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = kLength,
     .defaultValue = 0.0},
    pocket::kSideAllowance,
    pocket::kFinishingInfeed,
};

CycleError faceError(const char* messageTemplate) {
    return CycleError{"cycle-parameter", messageTemplate, {"233"}};
}

// The face in the frame of the paths: a along them, b across them (the stepover). `start` is
// the edge where the paths begin, `end` the other one; `dir` +1 when end > start.
struct Span {
    double start = 0.0;
    double end = 0.0;
    double dir = 1.0;
    bool wallAtStart = false;
    bool wallAtEnd = false;
};

struct Face {
    Span a;
    Span b;
    bool alongMain = true;  // Q350 1: a is the main axis
    Vec2 uv(double along, double across) const {
        return alongMain ? Vec2(along, across) : Vec2(across, along);
    }
};

// Q347-Q349: -1/+1 the wall at the lower/upper end of the main axis, -2/+2 of the secondary.
bool wallAt(const CycleValues& v, int axis, double side) {
    for (uint16_t q : {uint16_t{347}, uint16_t{348}, uint16_t{349}}) {
        const int value = v.integer(q);
        if (std::abs(value) == axis && (value > 0) == (side > 0)) return true;
    }
    return false;
}

Span spanOf(const CycleValues& v, int axis, double from, double length) {
    Span s{from, from + length, length >= 0.0 ? 1.0 : -1.0};
    s.wallAtStart = wallAt(v, axis, -s.dir);
    s.wallAtEnd = wallAt(v, axis, s.dir);
    return s;
}

// Q220: where a wall across the paths meets a wall along them, the corner between them is
// rounded with `radius`; a tool centre kept `distance` from the walls then stays on the arc of
// radius - distance about the corner's centre (nothing changes while radius <= distance). The
// paths' end `a` (at the wall across them, `end` or start) for the path at `b`.
double cornerTrimmed(const Face& f, double a, double b, bool end, double radius, double distance) {
    if (radius <= distance) return a;
    const double wallA = end ? f.a.end : f.a.start;
    const double towardA = end ? f.a.dir : -f.a.dir;
    for (const bool bEnd : {false, true}) {
        if (!(bEnd ? f.b.wallAtEnd : f.b.wallAtStart)) continue;
        const double towardB = bEnd ? f.b.dir : -f.b.dir;
        const double cb = (bEnd ? f.b.end : f.b.start) - towardB * radius;
        const double beyond = (b - cb) * towardB;
        if (beyond <= 0.0) continue;
        const double r = radius - distance;
        a = wallA - towardA * radius + towardA * std::sqrt(std::max(0.0, r * r - beyond * beyond));
    }
    return a;
}

// Depth levels: equal roughing infeeds to the floor allowance, then the floor.
std::optional<CycleError> depthLevels(const CycleValues& v, const CycleContext& ctx,
                                      std::vector<double>& levels, bool& floorPass) {
    const double top = v.number(227);
    const double bottom = v.number(386);
    const int operation = v.integer(215);
    const double allowance = std::min(v.number(369), top - bottom);
    const double rough = top - bottom - allowance;
    double maxInfeed = v.number(202) > 0.0 ? v.number(202) : rough;
    const double lcuts = ctx.tool.cuttingLength;
    if (lcuts > 0.0 && lcuts < maxInfeed) maxInfeed = lcuts;  // spec: LCUTS limits the infeed
    if (operation != 2 && rough > 1e-9) {
        const double n = std::ceil(rough / maxInfeed - 1e-9);
        if (n > static_cast<double>(kMaxPaths)) return tooManyMoves(233);
        for (int i = 1; i <= static_cast<int>(n); ++i)
            levels.push_back(top - rough * i / n);
    }
    floorPass = operation != 1 && allowance > 1e-9;
    if (floorPass) levels.push_back(bottom);
    return std::nullopt;
}

// The face spiralled from its boundary inwards, each ring one stepover inside the last.
void spiral(CyclePath& path, const Face& f, double aFrom, double aTo, double bFrom, double bTo,
            double step, int rings, const Feed& feed) {
    const double da = f.a.dir;
    const double db = f.b.dir;
    for (int k = 0;; ++k) {
        const double a0 = aFrom + da * k * step;
        const double a1 = aTo - da * k * step;
        const double b0 = bFrom + db * k * step;
        const double b1 = bTo - db * k * step;
        path.moveUv(f.uv(a0, b0), feed);
        path.moveUv(f.uv(a1, b0), feed);
        path.moveUv(f.uv(a1, b1), feed);
        if (k == rings) break;  // the last ring is a line along the longer side (or a point)
        path.moveUv(f.uv(a0, b1), feed);
        path.moveUv(f.uv(a0, b0 + db * step), feed);
    }
}

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const double top = v.number(227);
    const double bottom = v.number(386);
    if (top == bottom) return std::nullopt;  // depth 0: not executed
    if (top < bottom) {
        return faceError(
            KERF_TR_NOOP("cycle {1}: the starting point Q227 must be above the end "
                         "point Q386"));
    }
    const double radius = ctx.tool.radius;
    const double cutter = radius - std::max(0.0, ctx.tool.radius2);
    if (cutter <= 0.0) {
        return faceError(KERF_TR_NOOP("cycle {1} needs a tool radius R greater than R2"));
    }
    const auto strategy = static_cast<Strategy>(v.integer(389));
    const bool walls = v.integer(347) != 0 || v.integer(348) != 0 || v.integer(349) != 0;
    if (strategy == Strategy::Spiral && walls) {
        return faceError(
            KERF_TR_NOOP("cycle {1}: limits Q347-Q349 are not possible with the "
                         "spiral strategy Q389 = 4"));
    }
    Face f;
    f.alongMain = v.integer(350) == 1;
    const Span mainSpan = spanOf(v, 1, ctx.start.x(), v.number(218));
    const Span secondSpan = spanOf(v, 2, ctx.start.y(), v.number(219));
    f.a = f.alongMain ? mainSpan : secondSpan;
    f.b = f.alongMain ? secondSpan : mainSpan;
    // The paths start beside the workpiece: on the other end when a wall closes the start. With
    // walls at both ends of the paths the tool comes in across them, from the open side.
    const bool enclosed = f.a.wallAtStart && f.a.wallAtEnd;
    if (enclosed) {
        if (f.b.wallAtStart) f.b = {f.b.end, f.b.start, -f.b.dir, false, true};
    } else if (f.a.wallAtStart) {
        f.a = {f.a.end, f.a.start, -f.a.dir, false, true};
    }
    const double side = v.number(368);
    const double corner = v.number(220);
    const double lateral = v.number(357);
    const double outside = radius + lateral;
    const bool overtravel = strategy == Strategy::Meander || strategy == Strategy::Lines;
    // Tool-centre extremes: R + Q368 from a wall, beyond the edge where there is none.
    const double aStart =
        enclosed ? f.a.start + f.a.dir * (radius + side) : f.a.start - f.a.dir * outside;
    const double aFar = f.a.wallAtEnd ? f.a.end - f.a.dir * (radius + side)
                                      : f.a.end + f.a.dir * (lateral + (overtravel ? radius : 0.0));
    const double aNear =
        strategy == Strategy::MeanderOnEdge && !enclosed ? f.a.start - f.a.dir * lateral : aStart;
    const double bFirst = f.b.start + (f.b.wallAtStart ? f.b.dir * (radius + side) : 0.0);
    const double bLast = f.b.end - (f.b.wallAtEnd ? f.b.dir * (radius + side) : 0.0);
    if ((bLast - bFirst) * f.b.dir < -1e-9 || (aFar - f.a.start) * f.a.dir < -1e-9) {
        return faceError(
            KERF_TR_NOOP("cycle {1}: the tool is too large for the face between "
                         "its walls"));
    }
    std::vector<double> levels;
    bool floorPass = false;
    if (auto e = depthLevels(v, ctx, levels, floorPass)) return e;
    const double width = std::fabs(bLast - bFirst);
    double intervals = std::ceil(width / (v.number(370) * cutter) - 1e-9);
    if (strategy == Strategy::Spiral) {
        const double half = std::min(width, std::fabs(f.a.end - f.a.start)) / 2.0;
        intervals = std::ceil(half / (v.number(370) * cutter) - 1e-9);
    }
    if ((intervals + 1.0) * static_cast<double>(levels.size() + 1) >
        static_cast<double>(kMaxPaths)) {
        return tooManyMoves(233);
    }
    const int n = static_cast<int>(intervals);
    const double clearance = v.number(200);
    const Feed prePosition = v.feed(253);

    // Positioning logic to start point 1, beside the workpiece (across the paths when enclosed).
    const Vec2 start1 = f.uv(aStart, enclosed ? bFirst - f.b.dir * outside : bFirst);
    if (path.w() <= top + v.number(204)) path.rapidW(top + v.number(204));
    path.rapidUv(start1);
    path.rapidW(top + clearance);
    for (size_t level = 0; level < levels.size(); ++level) {
        const double w = levels[level];
        const Feed mill = floorPass && level + 1 == levels.size() ? v.feed(385) : v.feed(207);
        if (level > 0) {
            path.rapidW(levels[level - 1] + clearance);
            path.rapidUv(start1);
        }
        path.moveW(w, prePosition);
        if (strategy == Strategy::Spiral) {
            const double halfA = std::fabs(f.a.end - f.a.start) / 2.0;
            const double halfB = width / 2.0;
            const double step = std::min(halfA, halfB) / std::max(1, n);
            spiral(path, f, f.a.start, f.a.end, bFirst, bLast, step, n, mill);
            continue;
        }
        const double step = n > 0 ? (bLast - bFirst) / n : 0.0;
        const bool meander = strategy == Strategy::Meander || strategy == Strategy::MeanderOnEdge;
        // The ends of the path at `b`: at a wall, short of a rounded corner (Q220).
        auto farEnd = [&](double b) {
            return f.a.wallAtEnd ? cornerTrimmed(f, aFar, b, true, corner, radius + side) : aFar;
        };
        auto nearEnd = [&](double a, double b) {
            return enclosed ? cornerTrimmed(f, a, b, false, corner, radius + side) : a;
        };
        for (int k = 0; k <= n; ++k) {
            const double b = bFirst + step * k;
            const bool back = meander && k % 2 == 1;
            if (k > 0) {
                if (strategy == Strategy::Lines || strategy == Strategy::LinesToEdge) {
                    path.rapidW(w + clearance);
                    path.rapidUv(f.uv(nearEnd(aStart, b), b));
                    path.moveW(w, prePosition);
                } else {
                    // The stepover from the end of the last path to the start of this one.
                    const double a = back ? farEnd(b) : nearEnd(aNear, b);
                    path.moveUv(f.uv(a, b),
                                strategy == Strategy::MeanderOnEdge ? v.feed(207) : prePosition);
                }
            } else if (enclosed) {
                path.moveUv(f.uv(nearEnd(aStart, b), b), prePosition);
            }
            path.moveUv(f.uv(back ? nearEnd(aNear, b) : farEnd(b), b), mill);
        }
    }

    // Side finishing: each wall at R, at Q338 infeeds to the floor, from beside the workpiece.
    if (v.integer(215) != 1 && side > 0.0 && walls) {
        std::vector<double> finishLevels;
        const double depth = top - bottom;
        const double infeed = v.number(338) > 0.0 ? v.number(338) : depth;
        const double count = std::ceil(depth / infeed - 1e-9);
        if (count > static_cast<double>(kMaxPaths)) return tooManyMoves(233);
        for (int i = 1; i <= static_cast<int>(count); ++i)
            finishLevels.push_back(i == static_cast<int>(count) ? bottom : top - infeed * i);
        // The ends of a wall pass: R from a wall across it, beside the workpiece otherwise.
        auto ends = [&](const Span& s, double& from, double& to) {
            from = s.wallAtStart ? s.start + s.dir * radius : s.start - s.dir * outside;
            to = s.wallAtEnd ? s.end - s.dir * radius : s.end + s.dir * outside;
        };
        struct Wall {
            bool across;    // a wall at an end of the paths (it runs along b)
            double at;      // its own coordinate
            double toward;  // from the face towards it
        };
        std::vector<Wall> list;
        if (f.a.wallAtStart) list.push_back({true, f.a.start, -f.a.dir});
        if (f.a.wallAtEnd) list.push_back({true, f.a.end, f.a.dir});
        if (f.b.wallAtStart) list.push_back({false, f.b.start, -f.b.dir});
        if (f.b.wallAtEnd) list.push_back({false, f.b.end, f.b.dir});
        for (const Wall& wall : list) {
            const Span& along = wall.across ? f.b : f.a;
            double from = 0.0;
            double to = 0.0;
            ends(along, from, to);
            // (the wall's axis, along it) to the plane.
            auto point = [&](double x, double t) { return wall.across ? f.uv(x, t) : f.uv(t, x); };
            const double line = wall.at - wall.toward * radius;  // the tool centre's line
            // The pass: the wall's line, at a rounded corner (Q220 > R) on round it onto the
            // other wall's line (a quarter arc of Q220 - R about the corner's centre).
            std::vector<PlanarSegment> pass;
            const double centre = wall.at - wall.toward * corner;
            auto cornerArc = [&](double crossWall, double crossToward, bool into) {
                const double c = crossWall - crossToward * corner;
                const Vec2 onWall = point(line, c);
                const Vec2 onCross = point(centre, crossWall - crossToward * radius);
                const Vec2 m = point(centre, c);
                const Vec2 p0 = into ? onWall : onCross;
                const Vec2 p1 = into ? onCross : onWall;
                const double turn = cross2(p0 - m, p1 - m) > 0.0 ? 1.0 : -1.0;
                pass.push_back(PlanarSegment::arc(p0, m, turn * std::numbers::pi / 2.0));
                return c;
            };
            const bool rounded = corner > radius;
            double a = from;
            if (rounded && along.wallAtStart) a = cornerArc(along.start, -along.dir, false);
            double b = to;
            if (rounded && along.wallAtEnd) b = along.end - along.dir * corner;
            if ((b - a) * along.dir > 1e-9)
                pass.push_back(PlanarSegment::line(point(line, a), point(line, b)));
            if (rounded && along.wallAtEnd) cornerArc(along.end, along.dir, true);
            if (pass.empty()) continue;
            path.rapidW(top + clearance);
            path.rapidUv(pass.front().start);
            bool forward = true;
            for (double w : finishLevels) {
                path.moveW(w, prePosition);
                for (size_t i = 0; i < pass.size(); ++i) {
                    const PlanarSegment s =
                        forward ? pass[i] : pass[pass.size() - 1 - i].reversed();
                    if (s.kind == PlanarSegment::Kind::Arc) {
                        path.arc({s.end.x(), s.end.y(), w}, s.center, s.sweep, v.feed(385));
                    } else {
                        path.moveUv(s.end, v.feed(385));
                    }
                }
                forward = !forward;
            }
        }
    }
    path.rapidW(top + std::max(clearance, v.number(204)));
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle233{.number = 233,
                                .name = KERF_TR_NOOP("FACE MILLING"),
                                .group = CycleGroup::Special,
                                .parameters = kParameters,
                                .expand = expand};

}  // namespace kerf::cycles
