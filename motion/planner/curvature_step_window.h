#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "motion/kinematics/machine_model.h"
#include "motion/planner/velocity_limits.h"

// The curvature steps along a run of path elements, for the step limit of the look-ahead.
// The moving-average filter (length T) turns them into jerk (a(t) - a(t - T)) / T: what counts
// is the signed sum of the steps of each axis that are within one filter length at the same
// time, i.e. of a run of consecutive steps spanning less than v T. That sum changes only when a
// step enters or leaves the filter, so its extremes are the runs that end at a step (it has
// just entered) or start at one (it is about to leave); each step's limit covers the runs it
// ends or starts, so together the limits cover every run the filter sees. Steps that alternate
// (vertex noise, a blend's step on and off) then no longer add up as if all had one sign.
// A step's limit is the highest v for which its runs within |s_k - s| < v T still fit
// (curvatureStepCap). The runs' sums are differences of prefix sums; a sparse table of the
// prefix sums' minima and maxima gives the largest of them in any window in O(1). The inequality
// holds per axis, so a window fits when the runs behind the step and those ahead of it each fit
// on their own: one binary search per side over that side's points (whose window ends at the
// point itself, no search of the other side's end), then one over the points of each side that
// the other side allows. O(log w) per step, O(log n) per point added. Planner thread.
namespace kerf::motion {

class CurvatureStepWindow {
public:
    void clear();
    // Appends the next point of the path (positions non-decreasing) with the step there
    // (signed jump of n_i per axis; zero where there is none).
    void add(double s, const AxisVector& step);
    size_t size() const { return m_s.size(); }
    double position(size_t index) const { return m_s[index]; }

    // The limit at point `index`, counting only the points in [first, last] (its run of
    // elements without a stop), never above `upperBound`.
    double cap(const MachineModel& model, size_t index, size_t first, size_t last,
               const PointJerkTerms& before, const PointJerkTerms& after, double upperBound) const;

private:
    // The points of [first, last] within `distance` of `index` (strictly nearer, or also at
    // exactly that distance): [lo, hi).
    void range(size_t index, size_t first, size_t last, double distance, bool inclusive, size_t& lo,
               size_t& hi) const;
    // The strict window of radius `distance` (a point's distance) ends before the first point
    // after `index` at that distance (windowEnd, `point` ahead), or starts after the last one
    // before it (windowStart, `point` behind).
    size_t windowEnd(size_t index, size_t point, double distance) const;
    size_t windowStart(size_t index, size_t point, double distance) const;
    // Per axis, the largest |sum| of the runs among the points [lo, hi) that end or start at
    // `index`; of those among [lo, index] that end there; of those among [index, hi) that
    // start there.
    AxisVector runSums(size_t index, size_t lo, size_t hi) const;
    AxisVector backSums(size_t index, size_t lo) const;
    AxisVector frontSums(size_t index, size_t hi) const;
    // One side of a step in the search of its limit: the farthest distance at which that side's
    // runs alone still allow v = d / T, the next point's distance, and the sums of the runs up to
    // the farthest feasible point.
    struct SideLimit {
        bool found = false;
        double reached = 0.0;
        double next = 1e300;
        AxisVector sums{};
    };
    // Per axis, the least and the largest prefix sum of [a, b] (indices of the prefix sums).
    void extremes(size_t a, size_t b, AxisVector& least, AxisVector& largest) const;

    std::vector<double> m_s;
    // The axes with a step since clear(), in the order they got one: the others' sums are 0.
    std::array<size_t, kAxisCount> m_axes{};
    std::array<bool, kAxisCount> m_active{};
    size_t m_axisCount = 0;
    // m_least[k][j] / m_largest[k][j]: per axis, the extremes of the prefix sums j .. j + 2^k - 1;
    // level 0 holds the prefix sums themselves ([j]: sum of the steps before point j).
    std::vector<std::vector<AxisVector>> m_least{std::vector<AxisVector>(1)};
    std::vector<std::vector<AxisVector>> m_largest{std::vector<AxisVector>(1)};
};

}  // namespace kerf::motion
