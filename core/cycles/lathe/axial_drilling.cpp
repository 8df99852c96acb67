#include "core/cycles/lathe/axial_drilling.h"

#include <algorithm>
#include <cmath>

#include "core/base/translate.h"

namespace kerf::cycles::lathe {

namespace {
constexpr double kSmallestPeck = 1e-3;  // mm: pecks that shrink below this never end
}

bool expandAxialHole(const AxialHole& h, LathePath& path, LatheError& error) {
    const double sense = h.depth > 0.0 ? 1.0 : -1.0;  // +1: drilling towards -Z
    const double total = std::fabs(h.depth);
    // Rigid tapping runs on the spindle axis (X0); the other operations at the programmed X.
    const bool rigid = h.peck == 0.0 && h.tappingType != 0;
    const double x = rigid ? 0.0 : h.start.y();
    const Vec2 approach(h.start.x() + sense * h.safety, x);
    auto at = [&](double depth) { return Vec2(h.start.x() - sense * depth, x); };
    if (h.peck == 0.0) {
        if (h.tappingType < 0 || h.tappingType > 2) {
            error = {
                'R', "cycle-parameter", KERF_TR_NOOP("{1} must be 0, 1 or 2 for tapping"), {"R"}};
            return false;
        }
        if (rigid && !(h.tappingLeadMm > 0.0)) {
            error = {0,
                     "cycle-parameter",
                     KERF_TR_NOOP("rigid tapping needs a feed and a spindle speed"),
                     {}};
            return false;
        }
        if (h.tappingType == 1) path.command(LatheStep::Kind::Orient, 0.0);
        path.rapid(approach);
        const double length = total + h.safety;
        if (rigid) {
            path.thread(at(total), h.tappingLeadMm, 0.0);
            path.dwell(h.dwellSeconds);
            // Back in the same thread: the spindle has turned length / lead revolutions.
            const double angle = std::fmod(360.0 * length / h.tappingLeadMm, 360.0);
            path.thread(approach, h.tappingLeadMm, angle);
            path.command(LatheStep::Kind::SpindleStop);
            return true;
        }
        path.feed(at(total));
        if (h.dwellSeconds > 0.0) {
            path.command(LatheStep::Kind::SpindleStop);
            path.dwell(h.dwellSeconds);
        }
        path.command(LatheStep::Kind::SpindleReverse);
        path.feed(approach);
        path.command(LatheStep::Kind::SpindleRestore);
        return true;
    }
    path.rapid(approach);
    double peck = h.peck;
    double depth = std::min(peck, total);
    path.feed(at(depth));
    while (depth < total - 1e-9) {
        if (path.full()) {
            error = tooManySteps('B');
            return false;
        }
        if (h.retract > 0.0) {
            path.rapid(at(depth - h.retract));
        } else {
            path.rapid(approach);
        }
        const double back = depth - h.reapproach;
        path.rapid(back > -h.safety ? at(back) : approach);
        peck = std::max(h.minimumPeck, peck * h.factor);
        if (peck < kSmallestPeck) {
            error = {'L',
                     "cycle-parameter",
                     KERF_TR_NOOP("the pecks shrink below 0.001 mm before the depth I: program L"),
                     {}};
            return false;
        }
        depth = std::min(depth + peck, total);
        path.feed(at(depth));
    }
    path.dwell(h.dwellSeconds);
    path.rapid(approach);
    return true;
}

}  // namespace kerf::cycles::lathe
