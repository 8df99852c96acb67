// Cycle 25 CONTOUR TRAIN (spec §6): the first contour of cycle 14 followed as a path, open or
// closed, beside it by the tool radius plus Q3 on the side of its RL/RR (or cycle 270's Q391),
// at the plunging depths, in climb or up-cut or alternating.
#include <cmath>

#include "core/cycles/contour/contour_train.h"
#include "core/cycles/contour/sl_end_position.h"
#include "core/cycles/contour/sl_machining.h"
#include "core/cycles/contour/sl_parameters.h"
#include "core/cycles/contour/train_rest.h"
#include "core/cycles/detail/cycle_list.h"
#include "core/cycles/drilling/hole_levels.h"
#include "core/cycles/pocket/milling_setup.h"

namespace kerf::cycles {

namespace {

using namespace contour;

constexpr ParameterDescriptor kParameters[] = {
    kContourDepth,
    kSideAllowance,
    kSurfaceCoordinate,
    kClearanceHeight,
    kPlungingDepth,
    kPlungeFeed,
    kMillingFeed,
    kClimbOrUpCut,
    common::addedLater({.q = 18,
                        .description = KERF_TR_NOOP("Coarse roughing tool number (0: none)"),
                        .min = 0.0,
                        .max = 99999.0,
                        .defaultValue = 0.0}),
    common::addedLater({.q = 446,
                        .description = KERF_TR_NOOP("Accepted residual material"),
                        .unit = Unit::Millimetre,
                        .min = 0.001,
                        .max = 9.999,
                        .defaultValue = 0.01}),
    common::addedLater({.q = 447,
                        .description = KERF_TR_NOOP("Maximum connection distance"),
                        .unit = Unit::Millimetre,
                        .min = 0.0,
                        .max = 999.999,
                        .defaultValue = 10.0}),
    common::addedLater({.q = 448,
                        .description = KERF_TR_NOOP("Path extension"),
                        .unit = Unit::Millimetre,
                        .min = 0.0,
                        .max = 99.999,
                        .defaultValue = 2.0}),
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    if (ctx.train.labelCount == 0) {
        return contourError(25, KERF_TR_NOOP("cycle {1} needs cycle 14 CONTOUR before it"));
    }
    if (auto e = checkDepthSign(25, 1, v.number(1), ctx)) return e;
    int side = 0;
    if (auto e = trainToolSide(25, ctx, side)) return e;
    const double distance = ctx.tool.radius + v.number(3);
    if (side != 0 && distance < 0.0) return pocket::toolTooLarge(25);
    const Chain centre = trainCentrePath(ctx.train, side, distance);
    if (centre.empty()) return pocket::toolTooLarge(25);
    // Q18: only where the coarse tool left material, each piece entered from above.
    std::vector<Chain> pieces{centre};
    if (v.number(18) > 0.0) {
        ToolInfo coarse;
        if (auto e = coarseTool(25, v, ctx, coarse)) return e;
        const Chain coarsePath = trainCentrePath(ctx.train, side, coarse.radius + v.number(3));
        pieces = restPieces(centre, ctx.tool.radius, coarsePath, coarse.radius,
                            {v.number(446), v.number(447), v.number(448)});
        if (pieces.empty()) return std::nullopt;
    }
    const double depth = std::fabs(v.number(1));
    const double up = v.number(1) > 0.0 ? -1.0 : 1.0;
    const double surface = v.number(5);
    const double clearance = v.number(7);
    auto at = [&](double below) { return surface - up * below; };
    std::vector<double> depths;
    if (auto e = infeedDepths(25, 0.0, depth, v.number(10), depths)) return e;
    if (depths.empty()) return std::nullopt;

    // Climb (with M3) keeps the tool left of its travel; a mirror image reverses the paths.
    bool climb = v.integer(15) >= 0;
    if (ctx.mirroredMain != ctx.mirroredSecondary) climb = !climb;
    const bool climbForward = side >= 0;
    // With rest pieces every piece is entered from above, also when alternating.
    const bool alternate = v.integer(15) == 0;
    const bool fromAbove = !alternate || pieces.size() > 1 || v.number(18) > 0.0;
    const TrainApproach approach = readTrainApproach(ctx.trainData);
    const Feed plunge = v.feed(11);
    const Feed mill = v.feed(12);

    double previous = 0.0;
    bool first = true;
    for (size_t k = 0; k < depths.size(); ++k) {
        const bool reverse = alternate && k % 2 == 1;
        const bool ahead = (climbForward == climb) != reverse;
        // The free side: where the tool is relative to its travel (left for a path on the line).
        const int freeSide = side == 0 ? 1 : ahead ? side : -side;
        for (size_t i = 0; i < pieces.size(); ++i) {
            const Chain chain = ahead ? pieces[i] : reversedChain(pieces[pieces.size() - 1 - i]);
            if (first || fromAbove) {
                // Over the start at the clearance height (staying higher when coming from above).
                if (!first || (path.w() - clearance) * up < 0.0) path.rapidW(clearance);
                path.rapidUv(approachStart(approach, chain, freeSide));
                // Onto the path, cut down to the previous depth; beside it only to the surface.
                path.rapidW(at(approach.kind == TrainApproach::Kind::Straight ? previous : 0.0));
                path.moveW(at(depths[k]), plunge);
                approachPath(path, approach, chain, freeSide, mill);
            } else {
                path.moveW(at(depths[k]), plunge);  // alternating: the infeed where it ended
            }
            first = false;
            followChain(path, chain, mill);
            if (fromAbove || k + 1 == depths.size())
                departPath(path, approach, chain, freeSide, mill);
        }
        previous = depths[k];
    }
    finishSlCycle(path, ctx, clearance, up, Feed::rapid());
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle25{.number = 25,
                               .name = KERF_TR_NOOP("CONTOUR TRAIN"),
                               .group = CycleGroup::Contours,
                               .parameters = kParameters,
                               .expand = expand};

}  // namespace kerf::cycles
