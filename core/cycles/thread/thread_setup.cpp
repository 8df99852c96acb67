#include "core/cycles/thread/thread_setup.h"

#include <cmath>
#include <string>

#include "core/base/fixed_format.h"
#include "core/base/translate.h"
#include "core/cycles/tapping/tapping_checks.h"

namespace kerf::cycles {

std::optional<CycleError> threadHelix(int cycle, const CycleValues& v, const CycleContext& ctx,
                                      bool outside, double dw, const Feed& approach,
                                      ThreadHelix& helix) {
    const double pitch = v.number(239);
    if (auto e = checkPitchNotZero(cycle, 239, pitch)) return e;
    const double nominal = v.number(335) / 2.0;
    const double radius = outside ? nominal + ctx.tool.radius : nominal - ctx.tool.radius;
    if (radius <= 0.0) {
        return CycleError{"cycle-tool",
                          KERF_TR_NOOP("cycle {1}: the tool diameter {2} is too large for the "
                                       "nominal diameter {3}"),
                          {std::to_string(cycle), formatFixed(2.0 * ctx.tool.radius, 4),
                           formatFixed(v.number(335), 4)}};
    }
    helix.centre = Vec2(ctx.start.x(), ctx.start.y());
    helix.radius = radius;
    helix.pitch = std::fabs(pitch);
    helix.dw = dw;
    helix.ccw = threadCcw(pitch, dw);
    helix.outside = outside;
    helix.prePosition = v.feed(253);
    helix.approach = approach;
    helix.mill = centreFeed(v.feed(207), nominal, radius);
    return std::nullopt;
}

double firstNonZero(std::initializer_list<double> depths) {
    for (double d : depths) {
        if (d != 0.0) return d;
    }
    return 0.0;
}

std::optional<CycleError> millThread(int cycle, CyclePath& path, const ThreadHelix& helix,
                                     const HoleLevels& levels, double depth, int perStep,
                                     bool towardsSurface) {
    const auto passes = threadPasses(depth, helix.pitch, perStep, towardsSurface);
    if (passes.empty()) return tooManyMoves(cycle);
    for (const ThreadPass& pass : passes) {
        millThreadPass(path, helix, levels.at(pass.depthStart), pass.turns);
        if (path.limitReached()) return tooManyMoves(cycle);
    }
    return std::nullopt;
}

}  // namespace kerf::cycles
