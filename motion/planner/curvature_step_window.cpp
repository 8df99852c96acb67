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

size_t CurvatureStepWindow::windowEnd(size_t index, size_t point, double distance) const {
    // Usually the point before is nearer; points at the same distance are outside too.
    const double here = m_s[index];
    if (point == index + 1 || m_s[point - 1] - here < distance) return point;
    auto begin = m_s.begin();
    return static_cast<size_t>(std::partition_point(begin + static_cast<std::ptrdiff_t>(index) + 1,
                                                    begin + static_cast<std::ptrdiff_t>(point),
                                                    [&](double s) { return s - here < distance; }) -
                               begin);
}

size_t CurvatureStepWindow::windowStart(size_t index, size_t point, double distance) const {
    const double here = m_s[index];
    if (point + 1 == index || here - m_s[point + 1] < distance) return point + 1;
    auto begin = m_s.begin();
    return static_cast<size_t>(
        std::partition_point(begin + static_cast<std::ptrdiff_t>(point) + 1,
                             begin + static_cast<std::ptrdiff_t>(index),
                             [&](double s) { return !(here - s < distance); }) -
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

AxisVector CurvatureStepWindow::backSums(size_t index, size_t lo) const {
    // With P the prefix sums: a run lo' .. index sums to P[index + 1] - P[lo'] (lo' in
    // [lo, index]).
    const AxisVector& end = m_least[0][index + 1];
    AxisVector least{};
    AxisVector largest{};
    extremes(lo, index, least, largest);
    AxisVector sums{};
    for (size_t n = 0; n < m_axisCount; ++n) {
        const size_t a = m_axes[n];
        sums[a] = std::max(end[a] - least[a], largest[a] - end[a]);
    }
    return sums;
}

AxisVector CurvatureStepWindow::frontSums(size_t index, size_t hi) const {
    // A run index .. hi' sums to P[hi' + 1] - P[index] (hi' + 1 in [index + 1, hi]).
    const AxisVector& start = m_least[0][index];
    AxisVector least{};
    AxisVector largest{};
    extremes(index + 1, hi, least, largest);
    AxisVector sums{};
    for (size_t n = 0; n < m_axisCount; ++n) {
        const size_t a = m_axes[n];
        sums[a] = std::max(largest[a] - start[a], start[a] - least[a]);
    }
    return sums;
}

AxisVector CurvatureStepWindow::runSums(size_t index, size_t lo, size_t hi) const {
    AxisVector sums = backSums(index, lo);
    const AxisVector front = frontSums(index, hi);
    for (size_t n = 0; n < m_axisCount; ++n) {
        const size_t a = m_axes[n];
        sums[a] = std::max(sums[a], front[a]);
    }
    return sums;
}

double CurvatureStepWindow::cap(const MachineModel& model, size_t index, size_t first, size_t last,
                                const PointJerkTerms& before, const PointJerkTerms& after,
                                double upperBound) const {
    const double t = model.filterTimeS();
    auto fits = [&](const AxisVector& sum, double v) {
        return curvatureStepFits(model, sum, before, after, v);
    };
    // Everything within reach of the highest velocity fits: nothing to search. Otherwise no
    // point beyond that reach can matter either.
    size_t lo = 0;
    size_t hi = 0;
    range(index, first, last, upperBound * t, true, lo, hi);
    if (fits(runSums(index, lo, hi), upperBound)) return upperBound;
    first = lo;
    last = hi - 1;
    const double here = m_s[index];
    // A window radius d is feasible when the runs strictly within it allow v = d / T: on both
    // sides at once, as the inequality holds per axis for the larger of the two sides' sums.
    // Each side alone is monotone in d; its farthest feasible point is found by a binary search
    // over its own points, where the window's end on that side is the point itself.
    SideLimit ahead;
    size_t aheadEnd = index + 1;  // one past the farthest point ahead feasible on its own
    {
        size_t b = last + 1;
        while (aheadEnd < b) {
            const size_t mid = aheadEnd + (b - aheadEnd) / 2;
            const double d = m_s[mid] - here;
            const size_t end = windowEnd(index, mid, d);
            if (fits(frontSums(index, end), d / t))
                aheadEnd = mid + 1;
            else
                b = mid;
        }
        ahead.found = aheadEnd > index + 1;
        if (ahead.found) ahead.reached = m_s[aheadEnd - 1] - here;
        if (aheadEnd <= last) ahead.next = m_s[aheadEnd] - here;
        ahead.sums = frontSums(index, aheadEnd);
    }
    SideLimit behind;
    size_t behindStart = first;  // the farthest point behind feasible on its own (or index)
    {
        size_t b = index;
        while (behindStart < b) {
            const size_t mid = behindStart + (b - behindStart) / 2;
            const double d = here - m_s[mid];
            const size_t start = windowStart(index, mid, d);
            if (fits(backSums(index, start), d / t))
                b = mid;
            else
                behindStart = mid + 1;
        }
        behind.found = behindStart < index;
        if (behind.found) behind.reached = here - m_s[behindStart];
        if (behindStart > first) behind.next = here - m_s[behindStart - 1];
        behind.sums = backSums(index, behindStart);
    }
    // Whether the other side allows d: up to its farthest feasible point it does (monotone),
    // from its next point on it does not; in between its window holds exactly the points up to
    // the farthest one.
    auto allows = [&](const SideLimit& side, double d) {
        if (side.found && d <= side.reached) return true;
        if (d >= side.next) return false;
        return fits(side.sums, d / t);
    };
    // The largest breakpoint feasible on both sides; the answer lies between it and the next.
    double best = 0.0;
    {
        // Ahead: the farthest point within aheadEnd that the back side allows.
        size_t a = index + 1;
        size_t b = aheadEnd;
        if (b > a && allows(behind, m_s[b - 1] - here)) a = b;
        while (a < b) {
            const size_t mid = a + (b - a) / 2;
            if (allows(behind, m_s[mid] - here))
                a = mid + 1;
            else
                b = mid;
        }
        if (a > index + 1) best = std::max(best, m_s[a - 1] - here);
    }
    {
        // Behind: the farthest point from behindStart on that the front side allows.
        size_t a = behindStart;
        size_t b = index;
        if (a < b && allows(ahead, here - m_s[a])) b = a;
        while (a < b) {
            const size_t mid = a + (b - a) / 2;
            if (allows(ahead, here - m_s[mid]))
                b = mid;
            else
                a = mid + 1;
        }
        if (b < index) best = std::max(best, here - m_s[b]);
    }
    range(index, first, last, best, true, lo, hi);
    return std::max(best / t,
                    curvatureStepCap(model, runSums(index, lo, hi), before, after, upperBound));
}

}  // namespace kerf::motion
