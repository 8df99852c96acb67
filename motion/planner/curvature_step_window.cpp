#include "motion/planner/curvature_step_window.h"

#include <algorithm>
#include <bit>

namespace kerf::motion {

void CurvatureStepWindow::clear() {
    m_s.clear();
    // Keep the levels' capacity: the look-ahead refills the window at every planning pass.
    for (auto& level : m_least)
        level.clear();
    for (auto& level : m_largest)
        level.clear();
    m_least[0].push_back(AxisVector{});
    m_largest[0].push_back(AxisVector{});
    m_axisCount = 0;
    m_active = {};
}

void CurvatureStepWindow::add(double s, const AxisVector& step) {
    m_s.push_back(s);
    AxisVector prefix = m_least[0].back();
    for (size_t a = 0; a < step.size(); ++a) {
        if (step[a] == 0.0) continue;
        prefix[a] += step[a];
        if (!m_active[a]) {
            m_active[a] = true;
            m_axes[m_axisCount++] = a;
        }
    }
    m_least[0].push_back(prefix);
    m_largest[0].push_back(prefix);
    // The new prefix sum completes one span of each length 2^k that ends at it.
    const size_t count = m_least[0].size();
    for (size_t k = 1; (size_t{1} << k) <= count; ++k) {
        if (m_least.size() <= k) {
            m_least.emplace_back();
            m_largest.emplace_back();
        }
        const size_t j = count - (size_t{1} << k);
        const size_t half = size_t{1} << (k - 1);
        AxisVector least{};
        AxisVector largest{};
        for (size_t n = 0; n < m_axisCount; ++n) {
            const size_t a = m_axes[n];
            least[a] = std::min(m_least[k - 1][j][a], m_least[k - 1][j + half][a]);
            largest[a] = std::max(m_largest[k - 1][j][a], m_largest[k - 1][j + half][a]);
        }
        m_least[k].push_back(least);
        m_largest[k].push_back(largest);
    }
}

void CurvatureStepWindow::range(size_t index, size_t first, size_t last, double distance,
                                bool inclusive, size_t& lo, size_t& hi) const {
    const double here = m_s[index];
    auto near = [&](double d) { return inclusive ? d <= distance : d < distance; };
    // Positions are sorted: the window is one contiguous range around `index`.
    auto begin = m_s.begin();
    lo = static_cast<size_t>(std::partition_point(begin + static_cast<std::ptrdiff_t>(first),
                                                  begin + static_cast<std::ptrdiff_t>(index),
                                                  [&](double s) { return !near(here - s); }) -
                             begin);
    hi = static_cast<size_t>(std::partition_point(begin + static_cast<std::ptrdiff_t>(index) + 1,
                                                  begin + static_cast<std::ptrdiff_t>(last) + 1,
                                                  [&](double s) { return near(s - here); }) -
                             begin);
}

void CurvatureStepWindow::extremes(size_t a, size_t b, AxisVector& least,
                                   AxisVector& largest) const {
    // Two spans of length 2^k that together cover [a, b].
    const size_t k = static_cast<size_t>(std::bit_width(b - a + 1) - 1);
    const size_t c = b + 1 - (size_t{1} << k);
    for (size_t n = 0; n < m_axisCount; ++n) {
        const size_t i = m_axes[n];
        least[i] = std::min(m_least[k][a][i], m_least[k][c][i]);
        largest[i] = std::max(m_largest[k][a][i], m_largest[k][c][i]);
    }
}

AxisVector CurvatureStepWindow::runSums(size_t index, size_t lo, size_t hi) const {
    // With P the prefix sums: a run lo' .. index sums to P[index + 1] - P[lo'] (lo' in
    // [lo, index]), a run index .. hi' to P[hi' + 1] - P[index] (hi' + 1 in [index + 1, hi]).
    const AxisVector& start = m_least[0][index];
    const AxisVector& end = m_least[0][index + 1];
    AxisVector backLeast{};
    AxisVector backLargest{};
    AxisVector frontLeast{};
    AxisVector frontLargest{};
    extremes(lo, index, backLeast, backLargest);
    extremes(index + 1, hi, frontLeast, frontLargest);
    AxisVector sums{};
    for (size_t n = 0; n < m_axisCount; ++n) {
        const size_t a = m_axes[n];
        sums[a] = std::max({end[a] - backLeast[a], backLargest[a] - end[a],
                            frontLargest[a] - start[a], start[a] - frontLeast[a]});
    }
    return sums;
}

double CurvatureStepWindow::cap(const MachineModel& model, size_t index, size_t first, size_t last,
                                const PointJerkTerms& before, const PointJerkTerms& after,
                                double upperBound) const {
    const double t = model.filterTimeS();
    auto capOf = [&](const AxisVector& sum) {
        return curvatureStepCap(model, sum, before, after, upperBound);
    };
    // Everything within reach of the highest velocity fits: nothing to search. Otherwise no
    // point beyond that reach can matter either.
    size_t lo = 0;
    size_t hi = 0;
    range(index, first, last, upperBound * t, true, lo, hi);
    auto fits = [&](const AxisVector& sum, double v) {
        return curvatureStepFits(model, sum, before, after, v);
    };
    if (fits(runSums(index, lo, hi), upperBound)) return upperBound;
    first = lo;
    last = hi - 1;
    auto within = [&](double d, bool inclusive) {
        range(index, first, last, d, inclusive, lo, hi);
        return runSums(index, lo, hi);
    };
    // A window radius d is feasible when the runs strictly within it allow v = d / T. That is
    // monotone in d (a wider window holds more runs); the answer lies between the largest
    // feasible breakpoint and the next.
    auto feasible = [&](double d) { return fits(within(d, false), d / t); };
    double best = 0.0;
    // Forwards: distances m_s[k] - m_s[index] rise with k.
    size_t a = index + 1;
    size_t b = last + 1;
    while (a < b) {
        size_t mid = a + (b - a) / 2;
        if (feasible(m_s[mid] - m_s[index]))
            a = mid + 1;
        else
            b = mid;
    }
    if (a > index + 1) best = std::max(best, m_s[a - 1] - m_s[index]);
    // Backwards: distances m_s[index] - m_s[k] rise as k falls.
    a = first;
    b = index;
    while (a < b) {
        size_t mid = a + (b - a) / 2;
        if (feasible(m_s[index] - m_s[mid]))
            b = mid;
        else
            a = mid + 1;
    }
    if (a < index) best = std::max(best, m_s[index] - m_s[a]);
    return std::max(best / t, capOf(within(best, true)));
}

}  // namespace kerf::motion
