#include "core/cycles/lathe/threading.h"

#include <cmath>
#include <vector>

#include "core/base/translate.h"
#include "core/geometry/arc_math.h"

namespace kerf::cycles::lathe {

namespace {

constexpr double kTolerance = 1e-9;

// The cycle works in a (cut, depth) frame: G86 cuts along Z, G87 along X.
Vec2 frame(const Vec2& p, bool face) {
    return face ? Vec2(p.y(), p.x()) : p;
}

struct Pass {
    double depth;
    double shift;  // along the cut direction, from the infeed angle
};

}  // namespace

bool expandThread(const Thread& t, const Vec2& callZx, LathePath& path, LatheError& error) {
    (void)callZx;
    const bool f = t.face;
    const Vec2 s = frame(t.start, f);
    const Vec2 e = frame(t.end, f);
    const double length = e.x() - s.x();
    if (std::fabs(length) < kTolerance) {
        error = {f ? 'Q' : 'R',
                 "cycle-geometry",
                 KERF_TR_NOOP("the thread has no length along its axis"),
                 {}};
        return false;
    }
    const double dir = length > 0.0 ? 1.0 : -1.0;
    const double side = t.depth > 0.0 ? 1.0 : -1.0;  // the depth goes towards -side
    const double slope = (e.y() - s.y()) / length;   // depth-axis change per cut-axis mm
    const double lineLength = std::hypot(length, e.y() - s.y());
    // Pitch along the cut axis; every move's lead is scaled to its own length.
    const double axial = t.pitch < 0.0 ? -t.pitch : t.pitch * std::fabs(length) / lineLength;
    const double change = t.pitchChange;
    if (change < 0.0 && axial * axial + 2.0 * change * std::fabs(length) < 0.0) {
        error = {'M',
                 "cycle-parameter",
                 KERF_TR_NOOP("the variable pitch reaches zero before the end point"),
                 {}};
        return false;
    }
    // Revolutions from the thread start to a point `advance` mm further along the cut axis.
    auto revolutions = [&](double advance) {
        if (std::fabs(change) < 1e-12) return advance / axial;
        return (-axial + std::sqrt(axial * axial + 2.0 * change * advance)) / change;
    };
    double startAngle = t.spindleAngleDeg;
    if (t.measuredAt) {
        // Repass: W is the spindle angle where the thread passes K.
        startAngle -= 360.0 * revolutions(dir * (*t.measuredAt - s.x()));
    }
    const double total = std::fabs(t.depth);
    const double rough = total - std::fabs(t.finishing);
    if (std::fabs(t.exit) >= std::fabs(length)) {
        error = {'J',
                 "cycle-geometry",
                 KERF_TR_NOOP("{1} leaves no thread to cut between the start and the end"),
                 {"J"}};
        return false;
    }
    const double tangent = std::fabs(t.infeedAngleDeg) < 90.0
                               ? std::tan(degToRad(std::fabs(t.infeedAngleDeg)))
                               : HUGE_VAL;
    if (total * tangent >= std::fabs(length) - std::fabs(t.exit)) {
        error = {'A',
                 "cycle-geometry",
                 KERF_TR_NOOP("{1} leaves no thread to cut between the start and the end"),
                 {"A"}};
        return false;
    }
    const bool zigzag = t.infeedAngleDeg < 0.0;
    std::vector<Pass> passes;
    double previous = 0.0;
    for (int k = 1; previous < rough - kTolerance; ++k) {
        if (passes.size() * 4 * static_cast<size_t>(t.starts) > LathePath::kStepLimit) {
            error = tooManySteps('B');
            return false;
        }
        double p = t.infeed > 0.0 ? std::max(t.infeed * std::sqrt(static_cast<double>(k)),
                                             previous + t.minimumIncrement)
                                  : k * std::fabs(t.infeed);
        if (p >= rough) p = rough;
        const double sense = zigzag && k % 2 == 0 ? -1.0 : 1.0;
        passes.push_back({p, sense * p * tangent});
        previous = p;
    }
    if (t.finishing > 0.0 || passes.empty()) {
        const double sense = zigzag && passes.size() % 2 == 1 ? -1.0 : 1.0;
        passes.push_back({total, t.finishing > 0.0 ? sense * total * tangent : 0.0});
    } else if (t.finishing < 0.0) {
        passes.push_back({total, 0.0});  // radial infeed
    } else {
        passes.push_back(passes.back());  // spring pass at the last depth
    }
    const double safety = std::fabs(t.safety);
    auto line = [&](double u) { return s.y() + slope * (u - s.x()); };
    const Vec2 approach(s.x(), s.y() + side * safety);
    const Vec2 safe(e.x(), e.y() + side * safety);
    auto out = [&](const Vec2& p) { return frame(p, f); };
    auto threadTo = [&](const Vec2& from, const Vec2& to, double angle0) {
        const double advance = dir * (from.x() - s.x());
        const double n = revolutions(advance);
        const double scale = (to - from).norm() / std::fabs(to.x() - from.x());
        const double lead = (axial + change * n) * scale;
        const double angle = std::fmod(std::fmod(angle0 + 360.0 * n, 360.0) + 360.0, 360.0);
        path.thread(out(to), lead, angle, change * scale);
    };
    const int starts = std::max(1, t.starts);
    const double exitAt = e.x() - dir * std::fabs(t.exit);
    path.rapid(out(approach));
    for (const Pass& pass : passes) {
        for (int j = 0; j < starts; ++j) {
            const double angle0 = startAngle + 360.0 * j / starts;
            const double u0 = s.x() + dir * pass.shift;
            const Vec2 first(u0, line(u0) - side * pass.depth);
            path.rapid(out(first));
            if (t.exit == 0.0) {
                threadTo(first, Vec2(e.x(), e.y() - side * pass.depth), angle0);
                path.rapid(out(safe));
            } else {
                const Vec2 j1(exitAt, line(exitAt) - side * pass.depth);
                threadTo(first, j1, angle0);
                if (t.exit > 0.0) {
                    threadTo(j1, safe, angle0);
                } else {
                    threadTo(j1, e, angle0);
                    path.rapid(out(safe));
                }
            }
            path.rapid(out(approach));
        }
    }
    if (path.full()) {
        error = tooManySteps('B');
        return false;
    }
    return true;
}

}  // namespace kerf::cycles::lathe
