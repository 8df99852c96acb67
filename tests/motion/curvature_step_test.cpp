// The look-ahead's curvature-step limit (closed-form root, prefix sums and binary search) against
// the definition, by brute force: the steps nearest first, widening the window one step at a
// time (per axis the larger of the rises and the falls in it), each velocity found by bisection
// of the jerk inequality.
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

double bruteForceCap(const MachineModel& model, const StepRun& run, size_t index,
                     const PointJerkTerms& before, const PointJerkTerms& after, double upper) {
    const double t = model.filterTimeS();
    std::vector<size_t> others;
    for (size_t k = 0; k < run.s.size(); ++k) {
        if (k != index) others.push_back(k);
    }
    auto distance = [&](size_t k) { return std::fabs(run.s[k] - run.s[index]); };
    std::stable_sort(others.begin(), others.end(),
                     [&](size_t a, size_t b) { return distance(a) < distance(b); });
    struct Sums {
        AxisVector rises{};
        AxisVector falls{};
        AxisVector larger() const {
            AxisVector out{};
            for (size_t a = 0; a < 3; ++a)
                out[a] = std::max(rises[a], falls[a]);
            return out;
        }
    };
    auto add = [&](Sums& sums, size_t k) {
        for (size_t a = 0; a < 3; ++a) {
            double step = run.steps[k][a];
            (step > 0.0 ? sums.rises : sums.falls)[a] += std::fabs(step);
        }
    };
    Sums wide;
    add(wide, index);
    for (size_t k : others) {
        if (distance(k) <= upper * t) add(wide, k);
    }
    if (bisectedCap(model, wide.larger(), before, after, upper) >= upper) return upper;
    Sums sums;
    add(sums, index);
    double best = 0.0;
    for (size_t n = 0;; ++n) {
        double cap = bisectedCap(model, sums.larger(), before, after, upper);
        double next = n < others.size() ? distance(others[n]) : 1e300;
        best = std::max(best, std::min(cap, next / t));
        if (next / t >= cap) return best;
        add(sums, others[n]);
    }
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
