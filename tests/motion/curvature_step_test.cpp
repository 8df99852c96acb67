// The look-ahead's curvature-step limit (closed-form root, bound by prefix sums, widening walk)
// against the definition, by brute force: every run of steps that ends or starts at the step,
// summed directly, each velocity found by bisection of the jerk inequality.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "motion/planner/curvature_step_window.h"

namespace kerf::motion {
namespace {

constexpr double kJerk = 50000.0;
constexpr int kTaps = 17;  // T = 17 ms

MachineModel model3() {
    MachineModel model;
    for (size_t i = 0; i < 3; ++i) {
        model.axes[i].enabled = true;
        model.axes[i].velocity = 500.0;
        model.axes[i].accel = 2000.0;
        model.axes[i].jerk = kJerk;
    }
    model.periodS = 0.001;
    model.filterTaps = kTaps;
    return model;
}

// The inequality of velocity_limits.h, written out: for every axis with a step, on both sides,
// step v^2 / T + |u| J_t + 3 |n| A_t v + |n'| v^3 <= J.
bool fits(const MachineModel& model, const AxisVector& sum, const PointJerkTerms& before,
          const PointJerkTerms& after, double v) {
    for (size_t i = 0; i < 3; ++i) {
        if (sum[i] <= 0.0) continue;
        for (const PointJerkTerms* side : {&before, &after}) {
            double jerk = sum[i] * v * v / model.filterTimeS() +
                          side->tangent[i] * side->limits.jerk +
                          3.0 * side->curvature[i] * side->limits.accel * v +
                          side->curvatureRate[i] * v * v * v;
            if (jerk > model.axes[i].jerk) return false;
        }
    }
    return true;
}

double bisectedCap(const MachineModel& model, const AxisVector& sum, const PointJerkTerms& before,
                   const PointJerkTerms& after, double upper) {
    if (fits(model, sum, before, after, upper)) return upper;
    double lo = 0.0;
    double hi = upper;
    for (int k = 0; k < 200; ++k) {
        double mid = (lo + hi) / 2.0;
        (fits(model, sum, before, after, mid) ? lo : hi) = mid;
    }
    return lo;
}

struct StepRun {
    std::vector<double> s;
    std::vector<AxisVector> steps;
};

// The definition, summed directly: at velocity v the filter holds the steps within v T of one
// another at once, and its jerk from them is their signed sum times v^2 / T. The sum changes
// only when a step enters or leaves, so for one step the runs that count are those that end at
// it (it has just entered) and those that start at it (it is about to leave). A run lies within
// the window |s_k - s| < v T when its farthest point does; the limit is the highest v whose
// runs then fit.
double bruteForceCap(const MachineModel& model, const StepRun& run, size_t index,
                     const PointJerkTerms& before, const PointJerkTerms& after, double upper) {
    const double t = model.filterTimeS();
    struct Run {
        double reach = 0.0;
        AxisVector sum{};
    };
    std::vector<Run> runs;
    for (size_t k = 0; k < run.s.size(); ++k) {
        Run r;
        r.reach = std::fabs(run.s[k] - run.s[index]);
        size_t from = std::min(k, index);
        size_t to = std::max(k, index);
        for (size_t m = from; m <= to; ++m) {
            for (size_t a = 0; a < 3; ++a)
                r.sum[a] += run.steps[m][a];
        }
        runs.push_back(r);
    }
    std::vector<double> reaches;
    for (const Run& r : runs)
        reaches.push_back(r.reach);
    std::sort(reaches.begin(), reaches.end());
    reaches.erase(std::unique(reaches.begin(), reaches.end()), reaches.end());
    double best = 0.0;
    for (size_t i = 0; i < reaches.size(); ++i) {
        // For reaches[i] / T < v <= reaches[i + 1] / T the window holds the runs up to reaches[i].
        AxisVector largest{};
        for (const Run& r : runs) {
            if (r.reach > reaches[i]) continue;
            for (size_t a = 0; a < 3; ++a)
                largest[a] = std::max(largest[a], std::fabs(r.sum[a]));
        }
        double cap = bisectedCap(model, largest, before, after, upper);
        double next = i + 1 < reaches.size() ? reaches[i + 1] / t : 1e300;
        if (cap > reaches[i] / t) best = std::max(best, std::min(cap, next));
        if (next >= cap) break;  // wider windows only sum more
    }
    return best;
}

TEST(CurvatureStep, SingleStepMatchesHandComputation) {
    // Only the step: 4 / T v^2 = J  ->  v = sqrt(J T / 4) = sqrt(50000 * 0.017 / 4) = 14.577 mm/s.
    MachineModel model = model3();
    PointJerkTerms flat;
    flat.limits = {1000.0, 25000.0};
    AxisVector step{};
    step[0] = 4.0;
    EXPECT_NEAR(curvatureStepCap(model, step, flat, flat, 100.0), std::sqrt(212.5), 1e-9);
    // With |u| J_t = 25000 on one side the room halves: v = sqrt(25000 * 0.017 / 4).
    PointJerkTerms moving = flat;
    moving.tangent[0] = 1.0;
    EXPECT_NEAR(curvatureStepCap(model, step, flat, moving, 100.0), std::sqrt(106.25), 1e-9);
    // The upper bound wins when the step is small.
    step[0] = 1e-4;
    EXPECT_EQ(curvatureStepCap(model, step, flat, flat, 100.0), 100.0);
}

TEST(CurvatureStep, StepsUpAndDownWithinOneFilterLengthCountOnce) {
    // A blend: curvature +4 on, then off 0.01 mm later; the filter sees at most one of them at
    // full size (the jerk is (a(t) - a(t - T)) / T), so v = sqrt(J T / 4) = 14.577 mm/s, not
    // sqrt(J T / 8). Two rises in a row do add up: sqrt(J T / 8) = 10.308 mm/s.
    MachineModel model = model3();
    PointJerkTerms flat;
    flat.limits = {1000.0, 25000.0};
    AxisVector on{};
    on[2] = 4.0;
    AxisVector off{};
    off[2] = -4.0;
    CurvatureStepWindow window;
    window.add(0.0, on);
    window.add(0.01, off);
    EXPECT_NEAR(window.cap(model, 0, 0, 1, flat, flat, 100.0), std::sqrt(212.5), 1e-9);
    CurvatureStepWindow twice;
    twice.add(0.0, on);
    twice.add(0.01, on);
    EXPECT_NEAR(twice.cap(model, 0, 0, 1, flat, flat, 100.0), std::sqrt(106.25), 1e-9);
}

TEST(CurvatureStep, AlternatingStepsCountAsOne) {
    // Vertex noise: 40 steps of +4 and -4 in turn, 0.001 mm apart, all within one filter length.
    // Any run of them sums to -4, 0 or +4, so the filter's jerk is at most 4 v^2 / T:
    // v = sqrt(J T / 4) = 14.577 mm/s, as for one step (the sum of the rises, 80, would give
    // sqrt(J T / 80) = 3.26 mm/s).
    MachineModel model = model3();
    PointJerkTerms flat;
    flat.limits = {1000.0, 25000.0};
    CurvatureStepWindow window;
    for (int k = 0; k < 40; ++k) {
        AxisVector step{};
        step[1] = k % 2 == 0 ? 4.0 : -4.0;
        window.add(0.001 * k, step);
    }
    for (size_t index : {0u, 17u, 39u})
        EXPECT_NEAR(window.cap(model, index, 0, 39, flat, flat, 100.0), std::sqrt(212.5), 1e-9);
}

TEST(CurvatureStep, ClosedFormRootMatchesBisection) {
    MachineModel model = model3();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int binding = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        PointJerkTerms sides[2];
        for (PointJerkTerms& side : sides) {
            double share = unit(random);
            side.limits = {2000.0 * share, kJerk * share};
            for (size_t a = 0; a < 3; ++a) {
                side.tangent[a] = unit(random);
                side.curvature[a] = unit(random) < 0.5 ? 0.0 : 8.0 * unit(random);
                side.curvatureRate[a] = unit(random) < 0.5 ? 0.0 : 60.0 * unit(random);
            }
        }
        AxisVector sum{};
        for (size_t a = 0; a < 3; ++a)
            sum[a] = unit(random) < 0.3 ? 0.0 : std::pow(10.0, 4.0 * unit(random) - 2.0);
        double upper = 5.0 + 300.0 * unit(random);
        double expected = bisectedCap(model, sum, sides[0], sides[1], upper);
        double actual = curvatureStepCap(model, sum, sides[0], sides[1], upper);
        if (expected < upper) ++binding;
        ASSERT_NEAR(actual, expected, 1e-9 * std::max(1.0, expected)) << "trial " << trial;
    }
    EXPECT_GT(binding, 500);  // most trials have a limit below the bound
}

TEST(CurvatureStep, WindowMatchesBruteForceOnRandomPaths) {
    MachineModel model = model3();
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int searched = 0;
    int compared = 0;
    for (int trial = 0; trial < 150; ++trial) {
        // A run of elements: short segments and blends (0.002 - 0.4 mm), some of equal length
        // (ties between the two sides), steps on some axes only.
        StepRun run;
        double s = 0.0;
        double length = 0.002 + 0.4 * unit(random);
        size_t count = 20 + static_cast<size_t>(80 * unit(random));
        for (size_t k = 0; k < count; ++k) {
            if (unit(random) < 0.3) length = 0.002 + 0.4 * unit(random);
            AxisVector step{};
            for (size_t a = 0; a < 3; ++a) {
                double sign = unit(random) < 0.5 ? -1.0 : 1.0;
                if (unit(random) < 0.6) step[a] = sign * std::pow(10.0, 3.0 * unit(random) - 2.0);
            }
            run.s.push_back(s);
            run.steps.push_back(step);
            s += length;
        }
        CurvatureStepWindow window;
        // Points of another run before this one must not count.
        AxisVector huge{};
        huge.fill(1e6);
        window.add(-1.0, huge);
        window.add(-0.5, huge);
        for (size_t k = 0; k < count; ++k)
            window.add(run.s[k], run.steps[k]);
        window.add(s, huge);
        for (size_t index = 0; index < count; ++index) {
            PointJerkTerms sides[2];
            for (PointJerkTerms& side : sides) {
                side.limits = {1800.0, 45000.0 * unit(random)};
                for (size_t a = 0; a < 3; ++a) {
                    side.tangent[a] = 0.3 * unit(random);
                    side.curvature[a] = unit(random) < 0.5 ? 0.0 : 4.0 * unit(random);
                    side.curvatureRate[a] = unit(random) < 0.7 ? 0.0 : 16.0 * unit(random);
                }
            }
            double upper = 5.0 + 150.0 * unit(random);
            double expected = bruteForceCap(model, run, index, sides[0], sides[1], upper);
            double actual = window.cap(model, index + 2, 2, count + 1, sides[0], sides[1], upper);
            ASSERT_NEAR(actual, expected, 1e-9 * std::max(1.0, expected))
                << "trial " << trial << " index " << index;
            ++compared;
            if (expected < upper) ++searched;
        }
    }
    EXPECT_GT(searched, compared / 4);  // the search itself is exercised, not only the bound
}

}  // namespace
}  // namespace kerf::motion
