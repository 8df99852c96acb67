#include "motion/planner/curvature_step_window.h"

#include <algorithm>

namespace kerf::motion {

void CurvatureStepWindow::clear() {
    m_s.clear();
    m_rises.assign(1, AxisVector{});
    m_falls.assign(1, AxisVector{});
}

void CurvatureStepWindow::add(double s, const AxisVector& step) {
    m_s.push_back(s);
    AxisVector rises = m_rises.back();
    AxisVector falls = m_falls.back();
    for (size_t a = 0; a < step.size(); ++a) {
        rises[a] += std::max(0.0, step[a]);
        falls[a] += std::max(0.0, -step[a]);
    }
    m_rises.push_back(rises);
    m_falls.push_back(falls);
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

AxisVector CurvatureStepWindow::sumOf(size_t lo, size_t hi) const {
    AxisVector sum{};
    for (size_t a = 0; a < sum.size(); ++a) {
        sum[a] = std::max({0.0, m_rises[hi][a] - m_rises[lo][a], m_falls[hi][a] - m_falls[lo][a]});
    }
    return sum;
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
    if (fits(sumOf(lo, hi), upperBound)) return upperBound;
    first = lo;
    last = hi - 1;
    auto within = [&](double d, bool inclusive) {
        range(index, first, last, d, inclusive, lo, hi);
        return sumOf(lo, hi);
    };
    // A window radius d is feasible when the steps strictly within it allow v = d / T. That
    // is monotone in d; the answer lies between the largest feasible breakpoint and the next.
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
