#include "core/cycles/lathe/straight_turning.h"

#include <cmath>

#include "core/base/translate.h"

namespace kerf::cycles::lathe {

namespace {

constexpr double kTolerance = 1e-9;

// The cycle works in a (cut, step) frame: G81 cuts along Z and steps in X, G82 the other way.
Vec2 swapped(const Vec2& p, bool swap) {
    return swap ? Vec2(p.y(), p.x()) : p;
}

double sign(double v) {
    return v < 0.0 ? -1.0 : 1.0;
}

LatheError positionError(char letter) {
    return {letter,
            "cycle-position",
            KERF_TR_NOOP("the tool position is not correct for the cycle ({1})"),
            {std::string(1, letter)}};
}

}  // namespace

bool expandStraightSection(const StraightSection& section, const Vec2& callZx, LathePath& path,
                           LatheError& error) {
    const bool f = section.facing;
    const Vec2 call = swapped(callZx, f);
    const Vec2 a = swapped(section.a, f);
    const Vec2 b = swapped(section.b, f);
    // Allowances along the cut and the step directions of this frame.
    const double allowCut = f ? section.allowanceX : section.allowanceZ;
    const double allowStep = f ? section.allowanceZ : section.allowanceX;
    const double cutDirection = b.x() - a.x();
    if (std::fabs(cutDirection) < kTolerance) {
        // G81 needs a length along Z, G82 along X: the passes run from A's side towards B.
        error = {f ? 'Q' : 'R',
                 "cycle-geometry",
                 KERF_TR_NOOP("the section has no length along the passes"),
                 {}};
        return false;
    }
    const double sideCut = -sign(cutDirection);      // the call point lies before A
    const double sideStep = sign(call.y() - a.y());  // the material lies between call and A
    // Clearance (spec: along X from the call point to B at least L, along Z to A at least M),
    // and B no deeper than A: the section may not turn back under material already passed.
    if (sideStep * (call.y() - b.y()) < allowStep - kTolerance ||
        std::fabs(call.y() - a.y()) < kTolerance) {
        error = positionError(f ? 'Z' : 'X');
        return false;
    }
    if (sideCut * (call.x() - a.x()) < allowCut - kTolerance) {
        error = positionError(f ? 'X' : 'Z');
        return false;
    }
    if (sideStep * (b.y() - a.y()) < -kTolerance) {
        error = {f ? 'R' : 'Q',
                 "cycle-geometry",
                 KERF_TR_NOOP("the section runs back under the material: B must not be deeper "
                              "than A"),
                 {}};
        return false;
    }
    const Vec2 shift(sideCut * allowCut, sideStep * allowStep);
    const Vec2 a1 = a + shift;  // the section plus the allowances
    const Vec2 b1 = b + shift;
    // Where a pass at step level v meets the section plus allowances (beyond B: B's wall).
    auto passEnd = [&](double v) {
        if (sideStep * (v - b1.y()) >= -kTolerance || std::fabs(b1.y() - a1.y()) < kTolerance) {
            return Vec2(b1.x(), v);
        }
        const double t = (v - a1.y()) / (b1.y() - a1.y());
        return Vec2(a1.x() + t * (b1.x() - a1.x()), v);
    };
    auto out = [&](const Vec2& p) { return swapped(p, f); };
    const double depth = sideStep * (call.y() - a1.y());
    const int passes =
        depth > kTolerance ? static_cast<int>(std::ceil(depth / section.maxStep - 1e-9)) : 0;
    if (static_cast<size_t>(passes) * 4 > LathePath::kStepLimit) {
        error = tooManySteps('C');
        return false;
    }
    const double step = passes > 0 ? depth / passes : 0.0;
    double previous = call.y();
    for (int k = 1; k <= passes; ++k) {
        const double level = k == passes ? a1.y() : call.y() - sideStep * k * step;
        path.rapid(out({call.x(), level}));  // 1-2
        const Vec2 end = passEnd(level);
        path.feed(out(end));     // 2-3
        if (!section.retract) {  // 3-4 along the section
            const bool viaB = sideStep * (b1.y() - level) > kTolerance &&
                              sideStep * (previous - b1.y()) > kTolerance;
            if (viaB) path.feed(out(b1));
            path.feed(out(passEnd(previous)));
        } else if (*section.retract > 0.0) {  // 3-4 at 45 degrees
            const double d = *section.retract;
            path.rapid(out(end + Vec2(sideCut * d, sideStep * d)));
        }
        path.rapid(out({call.x(), swapped(path.position(), f).y()}));  // 4-5
        previous = level;
    }
    // Final roughing pass and finishing pass: along the section (plus allowances), up B's wall.
    auto along = [&](const Vec2& from, const Vec2& to, double feed) {
        path.rapid(out({call.x(), from.y()}));
        path.feed(out(from), feed);
        path.feed(out(to), feed);
        path.feed(out({to.x(), call.y()}), feed);
        path.rapid(callZx);
    };
    if (section.finalRoughingFeed > 0.0) along(a1, b1, section.finalRoughingFeed);
    if (section.finishingFeed > 0.0) along(a, b, section.finishingFeed);
    path.rapid(callZx);
    if (path.full()) {
        error = tooManySteps('C');
        return false;
    }
    return true;
}

}  // namespace kerf::cycles::lathe
