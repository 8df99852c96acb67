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

// Where the blade's near edge lies from the programmed point along the step axis (its far edge is
// the width beyond): the code's tip direction along that axis says which edge the point is
// (tip towards - : the near edge, towards + : the far edge, across: the middle). Codes without a
// direction answer nothing (NaN). G89 steps along X: the face codes 2 and 6, which have no X
// direction, name the inner edge (the blade's width runs outwards, as the stock model draws it).
double bladeNearEdge(int code, bool alongZ, double width) {
    static constexpr int kTipZ[10] = {0, -1, -1, -1, 0, 1, 1, 1, 0, 0};
    static constexpr int kTipX[10] = {0, 1, 0, -1, -1, -1, 0, 1, 1, 0};
    if (code < 1 || code > 8) return std::nan("");
    const int tip = alongZ ? kTipX[code] : kTipZ[code];
    if (alongZ && tip == 0) return 0.0;
    return tip < 0 ? 0.0 : tip > 0 ? -width : -0.5 * width;
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
    const double direction = e.y() >= s.y() ? 1.0 : -1.0;
    // The first plunge puts the blade flush with the wall at the start, the last one flush with
    // the wall at the end.
    double near = bladeNearEdge(g.locationCode, z, g.toolWidth);
    if (std::isnan(near)) near = direction > 0.0 ? 0.0 : -g.toolWidth;
    const double first = direction > 0.0 ? s.y() - near : s.y() - near - g.toolWidth;
    const double last = direction > 0.0 ? e.y() - near - g.toolWidth : e.y() - near;
    const double clear = s.x() + side * g.safety;
    for (int k = 0; k <= n; ++k) {
        const double at = n > 0 ? first + (last - first) * k / n : first;
        path.rapid(frame({clear, at}, z));
        path.feed(frame({e.x(), at}, z));
        path.dwell(g.dwellSeconds);
        path.rapid(frame({clear, at}, z));
    }
    path.rapid(callZx);
    return true;
}

}  // namespace kerf::cycles::lathe
