#include "core/cycles/drilling/hole_levels.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/base/fixed_format.h"
#include "core/base/translate.h"
#include "core/cycles/cycle_path.h"

namespace kerf::cycles {

namespace {
constexpr size_t kMaxInfeeds = 10000;
}

HoleLevels holeLevels(const CycleValues& values, double depth) {
    HoleLevels l;
    l.surface = values.number(203);
    l.up = depth > 0.0 ? -1.0 : 1.0;
    l.clearance = l.surface + l.up * values.number(200);
    l.top = l.surface + l.up * std::max(values.number(200), values.number(204));
    return l;
}

std::optional<CycleError> checkDepthSign(int cycle, uint16_t q, double depth,
                                         const CycleContext& context) {
    if (depth <= 0.0 || !context.positiveDepthIsError) return std::nullopt;
    return CycleError{"cycle-depth",
                      KERF_TR_NOOP("cycle {1}: the depth Q{2} = {3} is positive (the machine "
                                   "parameter displayDepthErr forbids it)"),
                      {std::to_string(cycle), std::to_string(q), formatFixed(depth, 4)}};
}

std::optional<CycleError> planInfeeds(int cycle, double total, double first, double decrement,
                                      double minimum, std::vector<double>& depths) {
    depths.clear();
    if (first <= 0.0 || first >= total) {
        depths.push_back(total);
        return std::nullopt;
    }
    double reached = 0.0;
    double infeed = first;
    while (reached < total - 1e-9) {
        if (depths.size() >= kMaxInfeeds) {
            return CycleError{"cycle-limit",
                              KERF_TR_NOOP("cycle {1}: more than {2} infeeds; increase the "
                                           "plunging depth"),
                              {std::to_string(cycle), std::to_string(kMaxInfeeds)}};
        }
        // An infeed reduced to nothing drills the rest in one go.
        if (infeed <= 1e-9) infeed = total - reached;
        reached = std::min(total, reached + infeed);
        depths.push_back(reached);
        if (decrement > 0.0) infeed = std::max(infeed - decrement, minimum);
    }
    return std::nullopt;
}

std::optional<CycleError> coneLength(int cycle, const ToolInfo& tool, double& length) {
    if (tool.pointAngleDeg <= 0.0 || tool.pointAngleDeg >= 180.0) {
        return CycleError{"cycle-tool",
                          KERF_TR_NOOP("cycle {1} needs the point angle T-ANGLE of the tool in "
                                       "the tool table"),
                          {std::to_string(cycle)}};
    }
    length = tool.radius / std::tan(tool.pointAngleDeg * std::numbers::pi / 360.0);
    return std::nullopt;
}

CycleError tooManyMoves(int cycle) {
    return {"cycle-limit",
            KERF_TR_NOOP("cycle {1} needs more than {2} moves"),
            {std::to_string(cycle), std::to_string(CyclePath::kMoveLimit)}};
}

}  // namespace kerf::cycles
