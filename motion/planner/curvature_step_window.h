#pragma once

#include <cstddef>
#include <vector>

#include "motion/kinematics/machine_model.h"
#include "motion/planner/velocity_limits.h"

// The curvature steps along a run of path elements, for the step limit of the look-ahead.
// The moving-average filter (length T) turns them into jerk (a(t) - a(t - T)) / T: what counts
// is the signed sum of the steps of each axis within one filter length, which lies between minus
// the sum of the falls and the sum of the rises there. So a step's velocity limit is the highest
// v for which the larger of the two, over the window |s_k - s| < v T, still fits
// (curvatureStepCap); a blend's steps up and down then no longer add up as if all had one sign.
// Prefix sums give any window's sums in O(1); the limit is found by binary search over the
// window's breakpoints: O(log n) per step. Planner thread.
namespace kerf::motion {

class CurvatureStepWindow {
public:
    void clear();
    // Appends the next point of the path (positions non-decreasing) with the step there
    // (signed jump of n_i per axis; zero where there is none).
    void add(double s, const AxisVector& step);
    size_t size() const { return m_s.size(); }

    // The limit at point `index`, counting only the points in [first, last] (its run of
    // elements without a stop), never above `upperBound`.
    double cap(const MachineModel& model, size_t index, size_t first, size_t last,
               const PointJerkTerms& before, const PointJerkTerms& after, double upperBound) const;

private:
    // The points of [first, last] within `distance` of `index` (strictly nearer, or also at
    // exactly that distance): [lo, hi).
    void range(size_t index, size_t first, size_t last, double distance, bool inclusive, size_t& lo,
               size_t& hi) const;
    // Per axis, the larger of the rises and the falls at the points [lo, hi).
    AxisVector sumOf(size_t lo, size_t hi) const;

    std::vector<double> m_s;
    std::vector<AxisVector> m_rises{AxisVector{}};  // [k]: sum of the rises before point k
    std::vector<AxisVector> m_falls{AxisVector{}};  // [k]: sum of the falls before point k
};

}  // namespace kerf::motion
