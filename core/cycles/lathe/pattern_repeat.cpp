// G66 (spec part 2 §2): every pass is the profile moved out to the material side by what is left
// to remove (I - k C, the last roughing pass at the finishing allowance), cut at the profile's far
// end along the main axis; rapid approach from the call point, rapid return first along the axis
// that clears the part. Pass model and choices: docs/fagor.md.
#include "core/cycles/lathe/pattern_repeat.h"

#include <cmath>

#include "core/base/translate.h"
#include "core/geometry/arc_math.h"
#include "core/geometry/open_chain_offset.h"

namespace kerf::cycles::lathe {

namespace {

constexpr double kTolerance = 1e-9;

double sign(double v) {
    return v < 0.0 ? -1.0 : 1.0;
}

LatheError geometryError(char letter, const char* message) {
    return {letter, "cycle-geometry", message, {}};
}

bool buildChain(const Vec2& start, const std::vector<ProfileElement>& elements,
                const PatternRepeat& cycle, std::vector<PlanarSegment>& chain, LatheError& error) {
    Vec2 from = start;
    for (const ProfileElement& e : elements) {
        if ((e.end - from).norm() > kTolerance) {
            if (!e.centre) {
                chain.push_back(PlanarSegment::line(from, e.end));
            } else {
                const Vec2& c = *e.centre;
                const double r = (from - c).norm();
                if (r < kTolerance || std::fabs((e.end - c).norm() - r) > cycle.radiusTolerance) {
                    error = geometryError('S', KERF_TR_NOOP("the start and the end of an arc are "
                                                            "not on one circle about its centre"));
                    return false;
                }
                chain.push_back(PlanarSegment{PlanarSegment::Kind::Arc, from, e.end, c,
                                              arcSweep(from, e.end, c, e.ccw)});
            }
        }
        from = e.end;
    }
    if (chain.empty()) {
        error = geometryError('S', KERF_TR_NOOP("the profile has no length"));
        return false;
    }
    return true;
}

// The raw-stock profile as a dense polyline, to tell whether a pass meets its material: a point
// is inside when the outline lies beyond it (towards the call point) along the measuring axis.
class RawOutline {
public:
    RawOutline(const std::vector<PlanarSegment>& raw, int main, double outward)
        : m_main(main), m_outward(outward) {
        for (const PlanarSegment& s : raw)
            sample(s, m_points);
    }

    // Whether any point of the pass lies in the raw stock (always, without one).
    bool cuts(const std::vector<PlanarSegment>& pass) const {
        if (m_points.empty()) return true;
        std::vector<Vec2> points;
        for (const PlanarSegment& s : pass)
            sample(s, points);
        for (const Vec2& p : points) {
            if (inside(p)) return true;
        }
        return false;
    }

private:
    static void sample(const PlanarSegment& s, std::vector<Vec2>& out) {
        const int n = s.kind == PlanarSegment::Kind::Arc ? 64 : 1;
        for (int k = 0; k <= n; ++k) {
            const double t = static_cast<double>(k) / n;
            if (s.kind == PlanarSegment::Kind::Line) {
                out.push_back(s.start + t * (s.end - s.start));
            } else {
                const double a = t * s.sweep;
                const Vec2 r = s.start - s.center;
                out.push_back(s.center + Vec2(std::cos(a) * r.x() - std::sin(a) * r.y(),
                                              std::sin(a) * r.x() + std::cos(a) * r.y()));
            }
        }
    }

    bool inside(const Vec2& p) const {
        const int measure = 1 - m_main;
        for (size_t i = 1; i < m_points.size(); ++i) {
            const Vec2& a = m_points[i - 1];
            const Vec2& b = m_points[i];
            const double lo = std::min(a[m_main], b[m_main]);
            const double hi = std::max(a[m_main], b[m_main]);
            if (p[m_main] < lo || p[m_main] > hi || hi - lo < kTolerance) continue;
            const double t = (p[m_main] - a[m_main]) / (b[m_main] - a[m_main]);
            const double edge = a[measure] + t * (b[measure] - a[measure]);
            if (m_outward * (edge - p[measure]) > 1e-6) return true;
        }
        return false;
    }

    int m_main;
    double m_outward;
    std::vector<Vec2> m_points;
};

double distanceTo(const std::vector<PlanarSegment>& chain, const Vec2& p) {
    double nearest = HUGE_VAL;
    for (const PlanarSegment& s : chain)
        nearest = std::min(nearest, s.distanceTo(p));
    return nearest;
}

}  // namespace

bool expandPatternRepeat(const PatternRepeat& cycle, const Vec2& call, LathePath& path,
                         LatheError& error) {
    std::vector<PlanarSegment> profile;
    if (!buildChain(cycle.start, cycle.elements, cycle, profile, error)) return false;
    std::vector<PlanarSegment> raw;
    if (!cycle.raw.elements.empty() &&
        !buildChain(cycle.raw.start, cycle.raw.elements, cycle, raw, error)) {
        return false;
    }
    // Axis 0 is Z, 1 is X. The stock is measured along `measure`; the passes run along `main`.
    const int measure = cycle.stockAlongZ ? 0 : 1;
    const int main = 1 - measure;
    const Vec2 start = profile.front().start;
    const Vec2 end = profile.back().end;
    const Vec2 outward(sign(call.x() - start.x()), sign(call.y() - start.y()));
    // The material lies on the call point's side of the profile: left or right of its travel.
    const Vec2 chord = end - start;
    Vec2 towardsCall(0.0, 0.0);
    towardsCall[measure] = outward[measure];
    double side = cross2(chord, towardsCall);
    if (std::fabs(side) < kTolerance) side = cross2(chord, call - start);
    const double left = sign(side);
    const char positionLetter = measure == 1 ? 'X' : 'Z';
    if (distanceTo(profile, call) <= cycle.stock + kTolerance ||
        left * cross2(chord, call - start) <= 0.0) {
        error = {positionLetter,
                 "cycle-position",
                 KERF_TR_NOOP("the tool position is not correct for the cycle ({1})"),
                 {std::string(1, positionLetter)}};
        return false;
    }
    // Passes end where the profile ends along the main axis.
    const double limit = end[main];
    const double direction = sign(end[main] - start[main]);
    const double allowance =
        measure == 1 ? cycle.allowanceX : cycle.allowanceZ.value_or(cycle.allowanceX);
    auto passAt = [&](double d, std::vector<PlanarSegment>& pass) {
        if (!cycle.allowanceZ) {
            const auto offset = offsetOpenChain(profile, left * d);
            if (!offset) return false;
            pass = *offset;
        } else {
            // Different allowances in X and Z: every element moves by the allowance of each
            // direction it faces, and the elements facing the call point along the measuring
            // axis by the rest of the stock too (the profile swept by that box): so a wall that
            // faces away (a groove's far side, an undercut) keeps its allowance instead of being
            // crossed by a copy moved bodily.
            Box2 box;
            box.min = Vec2(-*cycle.allowanceZ, -cycle.allowanceX);
            box.max = Vec2(*cycle.allowanceZ, cycle.allowanceX);
            if (outward[measure] > 0.0) {
                box.max[measure] += d - allowance;
            } else {
                box.min[measure] -= d - allowance;
            }
            const auto offset = offsetOpenChainByBox(profile, box, left);
            if (!offset) return false;
            pass = *offset;
        }
        pass = chainUpTo(pass, main, limit, direction);
        return true;
    };
    auto run = [&](const std::vector<PlanarSegment>& pass, double feed) {
        if (pass.empty()) return;
        path.rapid(pass.front().start);  // 1-2
        for (const PlanarSegment& s : pass) {
            if (s.kind == PlanarSegment::Kind::Arc) {
                path.arc(s.end, s.center, s.sweep > 0.0, feed);
            } else {
                path.feed(s.end, feed);  // 2-3
            }
        }
        Vec2 clear = path.position();  // 3-4: away from the material first
        clear[measure] = call[measure];
        path.rapid(clear);
        path.rapid(call);  // 4-1
    };
    std::vector<double> depths;
    if (cycle.stock > allowance + kTolerance) {
        const double count = std::ceil((cycle.stock - allowance) / cycle.step - 1e-9);
        if (count * (2.0 * static_cast<double>(profile.size()) + 3.0) > LathePath::kStepLimit) {
            error = tooManySteps('C');
            return false;
        }
        for (int k = 1; k < static_cast<int>(count); ++k)
            depths.push_back(cycle.stock - k * cycle.step);
        depths.push_back(allowance);
    }
    const RawOutline outline(raw, main, outward[measure]);
    std::vector<PlanarSegment> pass;
    for (const double d : depths) {
        if (!passAt(d, pass)) {
            error = geometryError('I', KERF_TR_NOOP("the profile cannot be copied at the "
                                                    "distance of a pass: it is too narrow"));
            return false;
        }
        if (outline.cuts(pass)) run(pass, 0.0);
    }
    if (cycle.finishingFeed > 0.0)
        run(chainUpTo(profile, main, limit, direction), cycle.finishingFeed);
    path.rapid(call);
    if (path.full()) {
        error = tooManySteps('C');
        return false;
    }
    return true;
}

}  // namespace kerf::cycles::lathe
