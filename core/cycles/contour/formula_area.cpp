#include "core/cycles/contour/formula_area.h"

#include <algorithm>
#include <cmath>

namespace kerf::cycles::contour {

namespace {

constexpr double kDepthTolerance = 1e-9;

double reach(const FormulaContour& c, double cycleDepth) {
    return c.depth > 0.0 ? c.depth : cycleDepth;
}

// Whether a subcontour takes part between the depths `top` and `bottom`.
bool present(const FormulaContour& c, double top, double bottom, double cycleDepth) {
    if (c.island) return c.depth <= top + kDepthTolerance;
    return reach(c, cycleDepth) >= bottom - kDepthTolerance;
}

Region symmetricDifference(const Region& a, const Region& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return unite(subtract(a, b), subtract(b, a));
}

Region combine(FormulaStep::Kind kind, const Region& a, const Region& b) {
    switch (kind) {
        case FormulaStep::Kind::Union:
            return a.empty() ? b : b.empty() ? a : unite(a, b);
        case FormulaStep::Kind::Intersection:
            return a.empty() || b.empty() ? Region{} : intersect(a, b);
        case FormulaStep::Kind::Difference:
            return a.empty() || b.empty() ? a : subtract(a, b);
        case FormulaStep::Kind::SymmetricDifference:
            return symmetricDifference(a, b);
        case FormulaStep::Kind::Contour:
            break;
    }
    return a;
}

Region evaluate(const ContourFormula& formula, const std::vector<Region>& areas,
                const std::vector<bool>& taking) {
    std::vector<Region> stack;
    for (const FormulaStep& step : formula.steps) {
        if (step.kind == FormulaStep::Kind::Contour) {
            stack.push_back(taking[step.contour] ? areas[step.contour] : Region{});
            continue;
        }
        if (stack.size() < 2) return Region{};  // the interpreter builds whole formulas
        Region right = std::move(stack.back());
        stack.pop_back();
        stack.back() = combine(step.kind, stack.back(), right);
    }
    return stack.empty() ? Region{} : std::move(stack.back());
}

}  // namespace

std::vector<AreaLevel> formulaLevels(const ContourFormula& formula, double cycleDepth) {
    std::vector<Region> areas;
    areas.reserve(formula.contours.size());
    std::vector<double> bottoms;
    double deepest = 0.0;
    for (const FormulaContour& c : formula.contours) {
        areas.push_back(regionOf(c.contour));
        if (!c.island) deepest = std::max(deepest, reach(c, cycleDepth));
    }
    for (const FormulaContour& c : formula.contours) {
        const double b = c.island ? c.depth : reach(c, cycleDepth);
        if (b > kDepthTolerance && b <= deepest + kDepthTolerance) bottoms.push_back(b);
    }
    std::sort(bottoms.begin(), bottoms.end());
    bottoms.erase(std::unique(bottoms.begin(), bottoms.end(),
                              [](double a, double b) { return b - a <= kDepthTolerance; }),
                  bottoms.end());

    std::vector<AreaLevel> levels;
    double top = 0.0;
    std::vector<bool> taking(formula.contours.size());
    for (double bottom : bottoms) {
        for (size_t i = 0; i < formula.contours.size(); ++i)
            taking[i] = present(formula.contours[i], top, bottom, cycleDepth);
        Region area = evaluate(formula, areas, taking);
        if (!levels.empty() && !area.empty()) area = intersect(area, levels.back().area);
        if (area.empty()) break;
        // Nested areas with the same size are the same area: one level reaching deeper.
        if (!levels.empty() && std::fabs(area.area() - levels.back().area.area()) < 1e-6) {
            levels.back().bottom = bottom;
        } else {
            levels.push_back(AreaLevel{bottom, std::move(area)});
        }
        top = bottom;
    }
    return levels;
}

}  // namespace kerf::cycles::contour
