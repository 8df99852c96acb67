// Cycle 276 3-D CONTOUR TRAIN (spec §6): as cycle 25, but the contour subprogram may move in the
// tool axis and the tool follows it: beside the path in the plane, at the path's height there.
// Q1 = 0: one pass on the programmed heights; otherwise infeeds of Q10 down to them, the first
// |Q1| - Q10 above [interp].
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
    kClearanceHeight,
    kPlungingDepth,
    kPlungeFeed,
    kMillingFeed,
    kClimbOrUpCut,
    {.q = 18,
     .description = KERF_TR_NOOP("Coarse roughing tool number (0: none)"),
     .min = 0.0,
     .max = 99999.0,
     .defaultValue = 0.0},
    {.q = 446,
     .description = KERF_TR_NOOP("Accepted residual material"),
     .unit = Unit::Millimetre,
     .min = 0.001,
     .max = 9.999,
     .defaultValue = 0.01},
    {.q = 447,
     .description = KERF_TR_NOOP("Maximum connection distance"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = 999.999,
     .defaultValue = 10.0},
    {.q = 448,
     .description = KERF_TR_NOOP("Path extension"),
     .unit = Unit::Millimetre,
     .min = 0.0,
     .max = 99.999,
     .defaultValue = 2.0},
};

std::optional<CycleError> expand(const CycleValues& v, const CycleContext& ctx, CyclePath& path) {
    const ContourTrain& train = ctx.train;
    if (train.labelCount == 0) {
        return contourError(276, KERF_TR_NOOP("cycle {1} needs cycle 14 CONTOUR before it"));
    }
    if (train.labelCount > 1) {
        return contourError(276, KERF_TR_NOOP("cycle {1}: cycle 14 must list exactly one "
                                              "contour subprogram"));
    }
    if (auto e = checkDepthSign(276, 1, v.number(1), ctx)) return e;
    const double up = v.number(1) > 0.0 ? -1.0 : 1.0;
    const double clearance = v.number(7);
    if ((path.w() - clearance) * up < -1e-9) {
        return contourError(276, KERF_TR_NOOP("cycle {1}: the tool is below the clearance height "
                                              "Q7 at the call"));
    }
    int side = 0;
    if (auto e = trainToolSide(276, ctx, side)) return e;
    const double distance = ctx.tool.radius + v.number(3);
    if (side != 0 && distance < 0.0) return pocket::toolTooLarge(276);
    const Chain centre = trainCentrePath(train, side, distance);
    if (centre.empty()) return pocket::toolTooLarge(276);
    // Q18: only where the coarse tool left material (found in the plane), each piece from above.
    std::vector<Chain> pieces{centre};
    if (v.number(18) > 0.0) {
        ToolInfo coarse;
        if (auto e = coarseTool(276, v, ctx, coarse)) return e;
        const Chain coarsePath = trainCentrePath(train, side, coarse.radius + v.number(3));
        pieces = restPieces(centre, ctx.tool.radius, coarsePath, coarse.radius,
                            {v.number(446), v.number(447), v.number(448)});
        if (pieces.empty()) return std::nullopt;
    }
    // Each pass lies `shift` above the programmed heights, the last on them.
    std::vector<double> shifts{0.0};
    const double depth = std::fabs(v.number(1));
    if (depth > 0.0) {
        std::vector<double> depths;
        if (auto e = infeedDepths(276, 0.0, depth, v.number(10), depths)) return e;
        shifts.clear();
        for (double d : depths)
            shifts.push_back(up * (depth - d));
    }

    bool climb = v.integer(15) >= 0;
    if (ctx.mirroredMain != ctx.mirroredSecondary) climb = !climb;
    const bool climbForward = side >= 0;
    const bool alternate = v.integer(15) == 0;
    const bool fromAbove = !alternate || pieces.size() > 1 || v.number(18) > 0.0;
    const TrainApproach approach = readTrainApproach(ctx.trainData);
    const Feed plunge = v.feed(11);
    const Feed mill = v.feed(12);
    bool first = true;
    for (size_t k = 0; k < shifts.size(); ++k) {
        const bool reverse = alternate && k % 2 == 1;
        const bool ahead = (climbForward == climb) != reverse;
        const int freeSide = side == 0 ? 1 : ahead ? side : -side;
        for (size_t i = 0; i < pieces.size(); ++i) {
            const Chain chain = ahead ? pieces[i] : reversedChain(pieces[pieces.size() - 1 - i]);
            const double startW = heightNear(train, chain.front().start, !ahead) + shifts[k];
            if (first || fromAbove) {
                path.rapidW(clearance);
                path.rapidUv(approachStart(approach, chain, freeSide));
                path.moveW(startW, plunge);  // no set-up clearance in 276: from Q7 at Q11
                approachPath(path, approach, chain, freeSide, mill);
            } else {
                path.moveW(startW, plunge);  // alternating: the infeed where the pass ended
            }
            first = false;
            followChain3d(path, chain, train, shifts[k], mill);
            if (fromAbove || k + 1 == shifts.size()) {
                departPath(path, approach, chain, freeSide, mill);
            }
        }
    }
    finishSlCycle(path, ctx, clearance, up, Feed::rapid());
    return std::nullopt;
}

}  // namespace

const CycleDescriptor kCycle276{.number = 276,
                                .name = KERF_TR_NOOP("3-D CONTOUR TRAIN"),
                                .group = CycleGroup::Contours,
                                .parameters = kParameters,
                                .expand = expand};

}  // namespace kerf::cycles
