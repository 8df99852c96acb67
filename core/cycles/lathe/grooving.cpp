#include "core/cycles/lathe/grooving.h"

#include <cmath>

#include "core/base/translate.h"

namespace kerf::cycles::lathe {

namespace {

constexpr double kTolerance = 1e-9;

// The cycle works in a (plunge, step) frame: G88 plunges along X, G89 along Z.
Vec2 frame(const Vec2& zx, bool alongZ) {
    return alongZ ? zx : Vec2(zx.y(), zx.x());
}

}  // namespace

bool expandGroove(const Groove& g, const Vec2& callZx, LathePath& path, LatheError& error) {
    const bool z = g.alongZ;
    const Vec2 call = frame(callZx, z);
    const Vec2 s = frame(g.start, z);
    const Vec2 e = frame(g.end, z);
    const char depthLetter = z ? 'R' : 'Q';
    if (std::fabs(e.x() - s.x()) < kTolerance) {
        error = {depthLetter, "cycle-geometry", KERF_TR_NOOP("the groove has no depth"), {}};
        return false;
    }
    const double width = std::fabs(e.y() - s.y());
    if (width < g.toolWidth - kTolerance) {
        error = {z ? 'Q' : 'R',
                 "cycle-geometry",
                 KERF_TR_NOOP("the groove is narrower than the tool's cutting width NOSEW"),
                 {}};
        return false;
    }
    const double step = g.maxStep > 0.0 ? g.maxStep : g.toolWidth;
    if (step <= 0.0 && width - g.toolWidth > kTolerance) {
        error = {'C',
                 "cycle-parameter",
                 KERF_TR_NOOP("C is not programmed and the tool has no cutting width NOSEW"),
                 {}};
        return false;
    }
    const double side = s.x() > e.x() ? 1.0 : -1.0;  // away from the groove bottom
    if (side * (call.x() - s.x()) < g.safety - kTolerance) {
        error = {z ? 'Z' : 'X',
                 "cycle-position",
                 KERF_TR_NOOP("the tool position is not correct for the cycle ({1})"),
                 {std::string(1, 'D')}};
        return false;
    }
    const double travel = width - g.toolWidth;
    const double count = travel > kTolerance ? std::ceil(travel / step - 1e-9) : 0.0;
    if (count * 4 > LathePath::kStepLimit) {
        error = tooManySteps('C');
        return false;
    }
    const int n = static_cast<int>(count);
    const double pitch = n > 0 ? travel / n : 0.0;
    const double direction = e.y() >= s.y() ? 1.0 : -1.0;
    const double clear = s.x() + side * g.safety;
    for (int k = 0; k <= n; ++k) {
        const double at = s.y() + direction * k * pitch;
        path.rapid(frame({clear, at}, z));
        path.feed(frame({e.x(), at}, z));
        path.dwell(g.dwellSeconds);
        path.rapid(frame({clear, at}, z));
    }
    path.rapid(callZx);
    return true;
}

}  // namespace kerf::cycles::lathe
