#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "canon_builder.h"
#include "core/geometry/arc_math.h"
#include "graphics/toolpath/arc_tessellation.h"
#include "graphics/toolpath/toolpath_data.h"
#include "graphics/toolpath/toolpath_lod.h"

namespace kerf::graphics {
namespace {

using test::CanonBuilder;

ToolpathData collect(const CanonBuilder& b, ToolpathOptions options = {}) {
    ToolpathCollector collector(options);
    b.feed(collector);
    return collector.take();
}

TEST(Toolpath, LinesGiveOnePointPerMoveAndExactBounds) {
    CanonBuilder b;
    b.rapid(0, 0, 5).rapid(10, 0, 5).line(10, 0, -2).line(30, 20, -2);
    const ToolpathData d = collect(b);
    EXPECT_EQ(d.pointCount(), 5u);  // start + 4 moves
    EXPECT_EQ(d.moveCount(), 4u);
    EXPECT_EQ(d.kinds[0], MoveKind::Rapid);
    EXPECT_EQ(d.kinds[3], MoveKind::Feed);
    EXPECT_DOUBLE_EQ(d.bounds.min.z(), -2.0);
    EXPECT_DOUBLE_EQ(d.bounds.max.x(), 30.0);
    EXPECT_DOUBLE_EQ(d.feedBounds.min.x(), 10.0);  // feed starts at (10, 0, 5)
    EXPECT_DOUBLE_EQ(d.feedBounds.max.z(), 5.0);
    // Segment -> move -> source line.
    EXPECT_EQ(d.moveOfSegment(4).value(), 3u);
    EXPECT_EQ(d.locations[*d.moveOfSegment(4)].line, 4u);
    EXPECT_FALSE(d.moveOfSegment(0).has_value());
}

TEST(Toolpath, ZeroLengthMovesExistWithoutPoints) {
    CanonBuilder b;
    b.line(0, 0, 0).line(1, 0, 0).line(1, 0, 0);
    const ToolpathData d = collect(b);
    EXPECT_EQ(d.moveCount(), 3u);
    EXPECT_EQ(d.pointCount(), 2u);
    auto [b0, e0] = d.pointsOfMove(0);
    EXPECT_EQ(b0, e0);
    EXPECT_EQ(d.moveOfSegment(1).value(), 1u);
}

TEST(Toolpath, ArcChordsStayWithinTolerance) {
    // Full circle of radius 10 about the origin, helix 5 mm down.
    CanonBuilder b;
    b.rapid(10, 0, 0).arc(10, 0, -5, 0, 0, 2 * kPi);
    ToolpathOptions options;
    options.arcChordToleranceMm = 0.01;
    const ToolpathData d = collect(b, options);
    auto [first, end] = d.pointsOfMove(1);
    const size_t chords = end - first;
    // Sagitta r (1 - cos(a/2)) <= 0.01  ->  a <= 2 acos(0.999)
    const auto expected = static_cast<size_t>(std::ceil(2 * kPi / (2 * std::acos(1 - 0.001))));
    EXPECT_EQ(chords, expected);
    for (size_t i = first; i < end; ++i) {
        const Vec3 p = d.point(i);
        EXPECT_NEAR(std::hypot(p.x(), p.y()), 10.0, 1e-4);
        // Midpoint of each chord is within tolerance of the circle.
        const Vec3 m = 0.5 * (p + d.point(i - 1));
        EXPECT_LE(10.0 - std::hypot(m.x(), m.y()), 0.01 + 1e-5);
    }
    EXPECT_NEAR(d.point(end - 1).z(), -5.0, 1e-6);
    // The chords' bounds are the circle's within the chord tolerance.
    EXPECT_NEAR(d.bounds.min.y(), -10.0, 0.01 + 1e-6);
    EXPECT_NEAR(d.bounds.max.y(), 10.0, 0.01 + 1e-6);
    EXPECT_EQ(d.kinds[1], MoveKind::Arc);
}

TEST(Toolpath, DegenerateAndHugeInputsDoNotCrash) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    CanonBuilder b;
    b.arc(0, 0, 0, 0, 0, 1.0)        // zero radius
        .arc(5, 0, 0, 0, 0, 0.0)     // zero sweep: a line
        .line(nan, 0, 0)             // skipped
        .rapid(inf, 1, 1)            // skipped
        .arc(1e12, 0, 0, 0, 0, 3.0)  // huge: capped chords
        .arc(0, 0, 0, nan, nan, 1.0)
        .line(-1e15, 1e15, 0);
    ToolpathOptions options;
    options.maxPointsPerArc = 64;
    const ToolpathData d = collect(b, options);
    EXPECT_EQ(d.skippedMoves, 2u);
    EXPECT_LE(d.pointCount(), 1u + 1 + 1 + 64 + 1 + 1);
    const ToolpathGeometry g = buildToolpathGeometry(d);
    EXPECT_EQ(g.segmentCount(0), d.segmentCount());
}

TEST(Toolpath, EmptyProgramHasOnePointAndNoGeometry) {
    ToolpathCollector collector;
    const ToolpathData d = collector.take();
    EXPECT_EQ(d.pointCount(), 1u);
    EXPECT_EQ(d.moveCount(), 0u);
    const ToolpathGeometry g = buildToolpathGeometry(d);
    EXPECT_TRUE(g.chunks.empty());
}

TEST(Toolpath, PointCapTruncates) {
    CanonBuilder b;
    for (int i = 0; i < 100; ++i)
        b.line(i + 1, 0, 0);
    ToolpathOptions options;
    options.maxPoints = 50;
    const ToolpathData d = collect(b, options);
    EXPECT_TRUE(d.truncated);
    EXPECT_EQ(d.pointCount(), 50u);
}

TEST(ToolpathLod, LevelZeroIsExactAndKindsSplitPolylines) {
    CanonBuilder b;
    b.rapid(0, 0, 5).line(0, 0, 0).line(10, 0, 0).arc(10, 10, 0, 10, 5, kPi).rapid(0, 0, 5);
    const ToolpathData d = collect(b);
    const ToolpathGeometry g = buildToolpathGeometry(d);
    ASSERT_EQ(g.chunks.size(), 1u);
    const PolylineSet& exact = g.chunks[0].levels[0];
    EXPECT_EQ(exact.segmentCount(), d.segmentCount());
    // rapid | feed feed | arc | rapid -> 4 polylines, one duplicated point per change of kind.
    EXPECT_EQ(exact.polylineCount(), 4u);
    EXPECT_EQ(exact.pointCount(), d.pointCount() + 3);
    EXPECT_EQ(exact.kind[0], static_cast<uint8_t>(MoveKind::Rapid));
    EXPECT_EQ(exact.kind.back(), static_cast<uint8_t>(MoveKind::Rapid));
}

TEST(ToolpathLod, CoarseLevelsStayWithinToleranceAndDropRepeats) {
    // A wavy row repeated 20 times on the same place, 2000 points per pass.
    CanonBuilder b;
    for (int pass = 0; pass < 20; ++pass) {
        for (int i = 0; i <= 2000; ++i) {
            const double x = (pass % 2 == 0) ? i * 0.01 : (2000 - i) * 0.01;
            b.line(x, 0.0, 0.5 * std::sin(x));
        }
    }
    const ToolpathData d = collect(b);
    LodOptions options;
    options.pointsPerChunk = 1u << 20;
    const ToolpathGeometry g = buildToolpathGeometry(d, options);
    ASSERT_EQ(g.chunks.size(), 1u);
    ASSERT_EQ(g.tolerances.size(), 9u);
    size_t previous = g.segmentCount(0);
    for (size_t level = 1; level < g.tolerances.size(); ++level) {
        // Coarser levels draw fewer segments than the exact path and than level 1 (not strictly
        // level by level: each level places its own simplification windows).
        const size_t count = g.segmentCount(level);
        EXPECT_LT(count, g.segmentCount(0) / 10) << level;
        EXPECT_LE(count, std::max(previous, g.segmentCount(1))) << level;
        previous = count;
        // Every kept vertex lies on the exact path, and every exact point lies within the level's
        // error bound of some kept segment (checked on the first pass).
        const PolylineSet& set = g.chunks[0].levels[level];
        for (size_t i = 0; i <= 2000; i += 37) {
            const Vec3 p = d.point(i + 1);
            double best = 1e9;
            for (size_t line = 0; line < set.polylineCount(); ++line) {
                for (auto k = static_cast<size_t>(set.offsets[line]) + 1;
                     k < static_cast<size_t>(set.offsets[line + 1]); ++k) {
                    const Vec3 a(set.xyz[3 * k - 3], set.xyz[3 * k - 2], set.xyz[3 * k - 1]);
                    const Vec3 c(set.xyz[3 * k], set.xyz[3 * k + 1], set.xyz[3 * k + 2]);
                    const Vec3 ab = c - a;
                    const double t =
                        std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-30), 0.0, 1.0);
                    best = std::min(best, (p - a - t * ab).norm());
                }
            }
            EXPECT_LE(best, g.tolerances[level] + 1e-5) << "level " << level;
        }
    }
    // Twenty passes over the same place: the coarsest level draws them about once.
    const size_t onePass = g.chunks[0].levels.back().segmentCount();
    EXPECT_LT(onePass, g.segmentCount(0) / 20);
}

TEST(ToolpathLod, ChooseLevelFollowsPixelSize) {
    const std::vector<double> tolerances{0.0, 0.01, 0.04, 0.16, 0.64};  // deviation bounds
    EXPECT_EQ(chooseLevel(tolerances, 0.001, 0.75), 0);
    EXPECT_EQ(chooseLevel(tolerances, 0.014, 0.75), 1);
    EXPECT_EQ(chooseLevel(tolerances, 0.06, 0.75), 2);
    EXPECT_EQ(chooseLevel(tolerances, 100.0, 0.75), 4);
    EXPECT_EQ(chooseLevel(tolerances, std::numeric_limits<double>::quiet_NaN(), 0.75), 0);
}

TEST(ToolpathLod, ChunksCoverThePathContinuously) {
    CanonBuilder b;
    for (int i = 0; i < 1000; ++i)
        b.line(i + 1, (i % 2) * 1.0, 0);
    const ToolpathData d = collect(b);
    LodOptions options;
    options.pointsPerChunk = 300;
    const ToolpathGeometry g = buildToolpathGeometry(d, options);
    ASSERT_EQ(g.chunks.size(), 4u);
    EXPECT_EQ(g.segmentCount(0), 1000u);
    for (size_t c = 1; c < g.chunks.size(); ++c) {
        EXPECT_EQ(g.chunks[c].firstPoint, g.chunks[c - 1].lastPoint);
    }
}

}  // namespace
}  // namespace kerf::graphics
