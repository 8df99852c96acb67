// Random convex polygons with rounded corners, written the FK way (each side by its direction and
// one point on it, each rounding only by its radius and tangency): the solver must find the
// geometry that the closed-form fillet construction gives, with no choice to make.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "core/geometry/arc_math.h"
#include "core/geometry/fk/fk_solver.h"

namespace kerf::fk {
namespace {

double angleDeg(const Vec2& v) {
    return radToDeg(std::atan2(v.y(), v.x()));
}

TEST(FkSolverProperty, RoundedConvexPolygons) {
    std::mt19937 random(2026);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int checked = 0;
    for (int trial = 0; trial < 300; ++trial) {
        const size_t n = 3 + static_cast<size_t>(unit(random) * 4.0);
        const Vec2 centre(unit(random) * 200.0 - 100.0, unit(random) * 200.0 - 100.0);
        const double size = 20.0 + unit(random) * 80.0;
        std::vector<double> angles;
        for (size_t i = 0; i < n; ++i)
            angles.push_back(unit(random) * kTwoPi);
        std::sort(angles.begin(), angles.end());
        std::vector<Vec2> v;
        for (double a : angles)
            v.push_back(centre + size * Vec2(std::cos(a), std::sin(a)));
        // Counter-clockwise on a circle: convex. Skip nearly degenerate corners.
        bool usable = true;
        std::vector<Vec2> dir(n);
        for (size_t i = 0; i < n; ++i) {
            const Vec2 edge = v[(i + 1) % n] - v[i];
            usable = usable && edge.norm() > 1.0;
            dir[i] = edge.normalized();
        }
        for (size_t i = 0; i < n && usable; ++i) {
            usable = cross2(dir[(i + n - 1) % n], dir[i]) > 0.05;
        }
        if (!usable) continue;
        ++checked;
        // Corner k (at v[k]) turns from dir[k-1] to dir[k] by delta; its rounding touches both
        // sides r tan(delta / 2) from the corner. Radii leave half of each side at most.
        std::vector<double> radius(n), reach(n), delta(n);
        for (size_t k = 0; k < n; ++k) {
            const Vec2& in = dir[(k + n - 1) % n];
            const Vec2& out = dir[k];
            delta[k] = std::atan2(cross2(in, out), in.dot(out));
            const double room =
                0.5 * std::min((v[k] - v[(k + n - 1) % n]).norm(), (v[(k + 1) % n] - v[k]).norm());
            reach[k] = (0.1 + 0.8 * unit(random)) * room;
            radius[k] = reach[k] / std::tan(delta[k] / 2.0);
        }
        const Vec2 start = 0.5 * (v[0] + v[1]);
        FkSolver solver;
        solver.begin(start, std::nullopt);
        std::vector<FkResolved> resolved;
        auto feed = [&](const FkElement& e, size_t tag) {
            FkStep step = solver.add(e, tag, std::nullopt);
            ASSERT_FALSE(step.problem) << "trial " << trial << " tag " << tag;
            ASSERT_EQ(step.choices, 0u) << "trial " << trial;
            resolved.insert(resolved.end(), step.resolved.begin(), step.resolved.end());
        };
        FkElement first;
        first.an = FkValue{angleDeg(dir[0]), false, std::nullopt};
        feed(first, 0);
        for (size_t i = 1; i <= n; ++i) {
            const size_t k = i % n;  // the corner at v[k], then side k
            FkElement round;
            round.kind = FkKind::TangentArc;
            round.rotation = FkRotation::Ccw;
            round.radius = radius[k];
            feed(round, 2 * i - 1);
            FkElement side;
            side.kind = FkKind::TangentLine;
            side.an = FkValue{angleDeg(dir[k]), false, std::nullopt};
            if (k == 0) {
                side.x = FkValue{start.x(), false, std::nullopt};
                side.y = FkValue{start.y(), false, std::nullopt};
            } else {
                side.pointsOn[0] = 0.5 * (v[k] + v[(k + 1) % n]);
            }
            feed(side, 2 * i);
        }
        if (testing::Test::HasFatalFailure()) return;
        ASSERT_EQ(resolved.size(), 2 * n + 1) << "trial " << trial;
        EXPECT_FALSE(solver.finish().problem);
        for (size_t i = 1; i <= n; ++i) {
            const size_t k = i % n;
            const Vec2 touchIn = v[k] - reach[k] * dir[(k + n - 1) % n];
            const Vec2 touchOut = v[k] + reach[k] * dir[k];
            const PlanarSegment& before = resolved[2 * i - 2].segment;
            const PlanarSegment& arc = resolved[2 * i - 1].segment;
            const double tol = 1e-6 * (1.0 + size);
            EXPECT_LT((before.end - touchIn).norm(), tol) << "trial " << trial << " corner " << k;
            EXPECT_LT((arc.end - touchOut).norm(), tol) << "trial " << trial << " corner " << k;
            EXPECT_NEAR(arc.sweep, delta[k], 1e-6) << "trial " << trial << " corner " << k;
            EXPECT_NEAR(arc.radius(), radius[k], tol);
        }
        EXPECT_LT((resolved.back().segment.end - start).norm(), 1e-6 * (1.0 + size));
    }
    EXPECT_GT(checked, 100);  // most random polygons are usable
}

// Random FK data, mostly nonsense: the solver answers every block (a step, a choice or a
// problem), never hangs, and what it resolves is finite and connected.
TEST(FkSolverProperty, RandomDataGiveFiniteConnectedElementsOrAProblem) {
    std::mt19937 random(321);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto value = [&](double range) { return FkValue{(unit(random) - 0.5) * range, false, {}}; };
    auto maybe = [&](double p) { return unit(random) < p; };
    size_t resolvedCount = 0, problems = 0;
    for (int trial = 0; trial < 1000; ++trial) {
        FkSolver solver;
        Vec2 at(0.0, 0.0);
        solver.begin(at, std::nullopt);
        std::optional<Vec2> pole;
        bool stopped = false;
        auto check = [&](const FkStep& step) {
            for (const FkResolved& r : step.resolved) {
                const PlanarSegment& s = r.segment;
                ASSERT_TRUE(s.start.allFinite() && s.end.allFinite() && s.center.allFinite() &&
                            std::isfinite(s.sweep))
                    << "trial " << trial;
                EXPECT_LT((s.start - at).norm(), 1e-6 * (1.0 + at.norm())) << "trial " << trial;
                at = s.end;
                ++resolvedCount;
            }
            if (step.problem) {
                ++problems;
                stopped = true;
            }
            if (step.choices > 0) {
                EXPECT_EQ(step.choices, solver.alternatives().size());
            }
        };
        for (int block = 0; block < 12 && !stopped; ++block) {
            if (solver.awaitingChoice()) {
                check(solver.select(1 + static_cast<int>(unit(random) * 3.0)));
                continue;
            }
            if (maybe(0.2)) pole = Vec2(value(40.0).value, value(40.0).value);
            FkElement e;
            e.kind = static_cast<FkKind>(static_cast<int>(unit(random) * 4.0) % 4);
            e.blockNumber = block;
            if (maybe(0.3)) e.x = value(100.0);
            if (maybe(0.3)) e.y = value(100.0);
            if (maybe(0.15) && pole) e.pr = FkValue{unit(random) * 50.0, false, {}};
            if (maybe(0.15) && pole) e.pa = value(720.0);
            if (maybe(0.3)) e.an = value(720.0);
            if (maybe(0.1)) e.length = 1.0 + unit(random) * 30.0;
            if (e.isArc()) {
                e.rotation = static_cast<FkRotation>(static_cast<int>(unit(random) * 3.0) % 3);
                if (maybe(0.5)) e.radius = 1.0 + unit(random) * 40.0;
                if (maybe(0.3)) e.ccx = value(100.0);
                if (maybe(0.3)) e.ccy = value(100.0);
                if (maybe(0.1)) e.endAngleAboutCentre = value(720.0).value;
            }
            if (maybe(0.2)) {
                e.pdx = value(100.0);
                e.pdy = value(100.0);
                e.distance = unit(random) * 20.0;
            }
            if (maybe(0.2)) e.pointsOn[0] = Vec2(value(100.0).value, value(100.0).value);
            if (maybe(0.1) && block > 0) e.x = FkValue{value(20.0).value, true, block - 1};
            check(solver.add(e, static_cast<size_t>(block), pole));
        }
        if (!stopped) check(solver.finish());
    }
    // The generator is not only producing errors.
    EXPECT_GT(resolvedCount, 50u);
    EXPECT_GT(problems, 100u);
}

}  // namespace
}  // namespace kerf::fk
