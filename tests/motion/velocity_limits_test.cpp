// The element velocity limit on circles and helices against the definition: at the limit, every
// point of the full turn and every sign of the tangential acceleration and jerk keeps each
// axis within its acceleration and jerk (a_i = u_i a + n_i v^2, j_i = u_i j + 3 n_i v a + n'_i v^3,
// with u, n, n' by finite differences of positionAt), and the limit is tight.
#include "motion/planner/velocity_limits.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "core/geometry/arc_math.h"

namespace kerf::motion {
namespace {

MachineModel model3(double accel, double jerk) {
    MachineModel model;
    for (size_t i = 0; i < 3; ++i) {
        model.axes[i].enabled = true;
        model.axes[i].velocity = 500.0;
        model.axes[i].accel = accel;
        model.axes[i].jerk = jerk;
    }
    model.periodS = 0.001;
    model.filterTaps = 1;
    return model;
}

// Largest ratio of |a_i| / A_i and |j_i| / J_i over the element at velocity v, for tangential
// acceleration and jerk of either sign.
double worstRatio(const MachineModel& model, const PathGeometry& g, const Limits& limits,
                  double v) {
    const double h = 1e-3 * g.length;
    double worst = 0.0;
    for (int step = 0; step <= 2000; ++step) {
        double s = std::clamp(g.length * step / 2000.0, 2.0 * h, g.length - 2.0 * h);
        AxisVector p[5];
        for (int k = 0; k < 5; ++k)
            p[k] = positionAt(g, s + (k - 2) * h);
        for (size_t i = 0; i < 3; ++i) {
            double u = (p[3][i] - p[1][i]) / (2.0 * h);
            double n = (p[3][i] - 2.0 * p[2][i] + p[1][i]) / (h * h);
            double dn = (p[4][i] - 2.0 * p[3][i] + 2.0 * p[1][i] - p[0][i]) / (2.0 * h * h * h);
            for (double sa : {-1.0, 1.0}) {
                double a = u * sa * limits.accel + n * v * v;
                worst = std::max(worst, std::fabs(a) / model.axes[i].accel);
                for (double sj : {-1.0, 1.0}) {
                    double j =
                        u * sj * limits.jerk + 3.0 * n * v * sa * limits.accel + dn * v * v * v;
                    worst = std::max(worst, std::fabs(j) / model.axes[i].jerk);
                }
            }
        }
    }
    return worst;
}

TEST(VelocityLimits, ArcInAnAxisPlaneMatchesHandComputation) {
    // R = 0.25 mm in XY, A = 2000 mm/s^2, 30 % tangential share (600 mm/s^2), jerk out of the
    // way: the X acceleration 600 sin + v^2/R cos peaks at sqrt(600^2 + (v^2/R)^2) = 2000, so
    // v = sqrt(0.25 sqrt(2000^2 - 600^2)) = 21.840 mm/s (adding the peaks would give 18.71).
    MachineModel model = model3(2000.0, 1e12);
    AxisVector from{};
    AxisVector to{};
    to[1] = 0.5;
    PathGeometry arc = makeHelix(from, to, {0.0, 0.25, 0.0}, Axis::X, Axis::Y, Axis::Z, kPi);
    Limits limits{600.0, 1e9};
    double cap = elementVelocityCap(model, arc, axisBounds(arc), limits, 1.0);
    EXPECT_NEAR(cap, std::sqrt(0.25 * std::sqrt(2000.0 * 2000.0 - 600.0 * 600.0)), 1e-6);
}

TEST(VelocityLimits, AShortArcCountsOnlyItsOwnSweep) {
    // R = 1 mm in XY from phi = -0.1 to +0.1 (around (1, 0), moving along +Y), A = 2000 mm/s^2,
    // tangential 90 % (1800 mm/s^2), jerk out of the way. On X, a = 1800 sin(phi) + v^2 cos(phi)
    // over |phi| <= 0.1 only: (2000 - 1800 sin 0.1) / cos 0.1 = 1829.4, v = 42.77 mm/s (the
    // full circle's peak sqrt(2000^2 - 1800^2) = 871.8 would allow only 29.53 mm/s). On Y,
    // 1800 cos(phi) + v^2 |sin(phi)| <= 2000 allows more: (2000 - 1800 cos 0.1) / sin 0.1.
    MachineModel model = model3(2000.0, 1e12);
    AxisVector from{};
    from[0] = std::cos(-0.1);
    from[1] = std::sin(-0.1);
    AxisVector to{};
    to[0] = std::cos(0.1);
    to[1] = std::sin(0.1);
    PathGeometry arc = makeHelix(from, to, {0.0, 0.0, 0.0}, Axis::X, Axis::Y, Axis::Z, 0.2);
    Limits limits{1800.0, 1e9};
    double cap = elementVelocityCap(model, arc, axisBounds(arc), limits, 1.0);
    EXPECT_NEAR(cap, std::sqrt((2000.0 - 1800.0 * std::sin(0.1)) / std::cos(0.1)), 1e-6);
}

PathGeometry helix(double radius, double sweep, double rise) {
    AxisVector from{};
    AxisVector to{};
    to[0] = radius * (std::cos(sweep) - 1.0);
    to[1] = radius * std::sin(sweep);
    to[2] = rise;
    return makeHelix(from, to, {-radius, 0.0, 0.0}, Axis::X, Axis::Y, Axis::Z, sweep);
}

TEST(VelocityLimits, RandomArcsAndHelicesStayWithinTheAxisLimits) {
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_real_distribution<double> share(0.02, 0.9);
    MachineModel model = model3(2000.0, 1e6);
    for (int trial = 0; trial < 40; ++trial) {
        double radius = 0.05 + 2.0 * (unit(rng) + 1.0);
        PathGeometry g = helix(radius, 2.0 * kPi * unit(rng), 0.5 * unit(rng));
        if (trial % 2 == 1) {
            // Tilted out of the axis planes, so that every axis sees part of the circle.
            g = makeTangentArc(AxisVector{}, {0.6, 0.0, 0.8},
                               AxisVector{radius * unit(rng), radius, radius * unit(rng)});
        }
        double s = share(rng);
        Limits limits{2000.0 * s, 1e6 * s};
        double cap = elementVelocityCap(model, g, axisBounds(g), limits, 1e9);
        SCOPED_TRACE("trial " + std::to_string(trial) + " cap " + std::to_string(cap));
        ASSERT_GT(cap, 0.0);
        EXPECT_LE(worstRatio(model, g, limits, cap), 1.0 + 1e-4);
    }
}

TEST(VelocityLimits, TheLimitOfAShortArcIsTight) {
    // Arcs of a fitted curve turn by a fraction of a radian: the limit takes the phases of their
    // own sweep, so 1 % faster must break a limit there too (the full circle's peaks were up to
    // 30 % below it on a curve's crest).
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    MachineModel model = model3(2000.0, 1e6);
    for (int trial = 0; trial < 40; ++trial) {
        double radius = 0.25 + 20.0 * unit(rng);
        double start = 2.0 * kPi * unit(rng);
        double sweep = 0.01 + 0.5 * unit(rng);
        AxisVector from{};
        AxisVector to{};
        from[0] = radius * std::cos(start);
        from[2] = radius * std::sin(start);
        to[0] = radius * std::cos(start + sweep);
        to[2] = radius * std::sin(start + sweep);
        PathGeometry g = makeHelix(from, to, {0.0, 0.0, 0.0}, Axis::Z, Axis::X, Axis::Y, sweep);
        double share = kTangentialShares[trial % 4];
        Limits limits{2000.0 * share, 1e6 * share};
        double cap = elementVelocityCap(model, g, axisBounds(g), limits, 1e9);
        SCOPED_TRACE("trial " + std::to_string(trial) + " cap " + std::to_string(cap));
        EXPECT_LE(worstRatio(model, g, limits, cap), 1.0 + 1e-4);
        EXPECT_GT(worstRatio(model, g, limits, cap * 1.01), 1.0);
    }
}

TEST(VelocityLimits, TheLimitOfAFullTurnIsTight) {
    // Over a whole turn every phase occurs: 1 % faster must break an acceleration or jerk limit.
    MachineModel model = model3(2000.0, 1e6);
    for (double radius : {0.1, 0.25, 1.0, 5.0}) {
        for (double share : {0.1, 0.3, 0.6, 0.9}) {
            PathGeometry g = helix(radius, 2.0 * kPi - 1e-6, 0.2);
            Limits limits{2000.0 * share, 1e6 * share};
            double cap = elementVelocityCap(model, g, axisBounds(g), limits, 1e9);
            SCOPED_TRACE("R " + std::to_string(radius) + " share " + std::to_string(share));
            EXPECT_LE(worstRatio(model, g, limits, cap), 1.0 + 1e-4);
            EXPECT_GT(worstRatio(model, g, limits, cap * 1.01), 1.0);
        }
    }
}

}  // namespace
}  // namespace kerf::motion
