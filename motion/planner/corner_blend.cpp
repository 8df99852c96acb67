#include "motion/planner/corner_blend.h"

#include <algorithm>
#include <cmath>

#include "motion/planner/biarc.h"

namespace kerf::motion {

namespace {

using V3 = Vec3Array;

V3 scale(const V3& a, double f) {
    return {a[0] * f, a[1] * f, a[2] * f};
}
double dot(const V3& a, const V3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
double norm(const V3& a) {
    return std::sqrt(dot(a, a));
}
V3 unit(const V3& a) {
    return scale(a, 1.0 / norm(a));
}
V3 xyz(const AxisVector& p) {
    return {p[0], p[1], p[2]};
}

AxisVector withXyz(const AxisVector& base, const V3& p) {
    AxisVector out = base;
    out[0] = p[0];
    out[1] = p[1];
    out[2] = p[2];
    return out;
}

}  // namespace

double cornerAngle(const PathGeometry& before, const PathGeometry& after) {
    V3 ta = unit(xyz(pointAt(before, before.length).tangent));
    V3 tb = unit(xyz(pointAt(after, 0.0).tangent));
    return std::acos(std::clamp(dot(ta, tb), -1.0, 1.0));
}

double biarcDeviation(const CornerBlend& blend, const PathGeometry& before,
                      const PathGeometry& after) {
    double worst = 0.0;
    double sBefore = before.length - blend.trimBefore;
    for (int k = 0; k < blend.arcCount; ++k) {
        const PathGeometry& arc = blend.arcs[static_cast<size_t>(k)];
        for (int i = 1; i < 8; ++i) {
            V3 p = xyz(positionAt(arc, arc.length * i / 8.0));
            double d = std::min(distanceTo(before, p, sBefore, before.length),
                                distanceTo(after, p, 0.0, blend.trimAfter));
            worst = std::max(worst, d);
        }
    }
    return worst;
}

CornerBlend blendCornerFrom(const PathGeometry& before, const PathGeometry& after, double deviation,
                            double trimBefore, double trimAfter) {
    CornerBlend blend;
    if (cornerAngle(before, after) < 1e-9) return blend;
    PathPoint a = pointAt(before, before.length - trimBefore);
    PathPoint b = pointAt(after, trimAfter);
    blend.trimBefore = trimBefore;
    blend.trimAfter = trimAfter;
    blend.arcCount = makeBiarc(a.position, xyz(a.position), unit(xyz(a.tangent)), xyz(b.position),
                               unit(xyz(b.tangent)), blend.arcs);
    blend.deviation = biarcDeviation(blend, before, after);
    if (blend.deviation > deviation) blend.arcCount = 0;
    return blend;
}

CornerBlend blendCorner(const PathGeometry& before, const PathGeometry& after, double deviation,
                        double maxTrimBefore, double maxTrimAfter) {
    CornerBlend blend;
    double theta = cornerAngle(before, after);
    if (theta < 1e-9 || deviation <= 0.0) return blend;
    // Line to line: an arc of radius r = l / tan(theta/2) deviates by r (1 - cos(theta/2)).
    double trim = deviation * std::tan(theta / 2.0) / (1.0 - std::cos(theta / 2.0));
    trim = std::min({trim, maxTrimBefore, maxTrimAfter});
    bool lines = !before.curved() && !after.curved();
    for (int attempt = 0; attempt < 8 && trim > 1e-9; ++attempt) {
        double sBefore = before.length - trim;
        PathPoint a = pointAt(before, sBefore);
        PathPoint b = pointAt(after, trim);
        V3 pa = xyz(a.position);
        V3 pb = xyz(b.position);
        V3 ta = unit(xyz(a.tangent));
        V3 tb = unit(xyz(b.tangent));
        blend.trimBefore = trim;
        blend.trimAfter = trim;
        if (lines) {
            blend.arcs[0] = makeTangentArc(a.position, ta, withXyz(a.position, pb));
            blend.arcCount = 1;
            blend.deviation = trim * (1.0 - std::cos(theta / 2.0)) / std::tan(theta / 2.0);
            return blend;
        }
        blend.arcCount = makeBiarc(a.position, pa, ta, pb, tb, blend.arcs);
        double worst = biarcDeviation(blend, before, after);
        blend.deviation = worst;
        if (worst <= deviation) return blend;
        trim *= 0.9 * deviation / worst;
    }
    blend.arcCount = 0;
    return blend;
}

CornerBlend blendAcross(const PathGeometry& before, const PathGeometry& middle,
                        const PathGeometry& after, double deviation, double maxTrimBefore,
                        double trimAfter) {
    CornerBlend blend;
    PathPoint b = pointAt(after, trimAfter);
    // The longest trim that fits: the gentlest turn. Shorter ones down to the middle's length.
    for (double trim = maxTrimBefore; trim >= middle.length / 2.0; trim *= 0.7) {
        PathPoint a = pointAt(before, before.length - trim);
        blend.trimBefore = trim;
        blend.trimAfter = trimAfter;
        blend.arcCount = makeBiarc(a.position, xyz(a.position), unit(xyz(a.tangent)),
                                   xyz(b.position), unit(xyz(b.tangent)), blend.arcs);
        double worst = 0.0;
        for (int k = 0; k < blend.arcCount && worst <= deviation; ++k) {
            const PathGeometry& arc = blend.arcs[static_cast<size_t>(k)];
            for (int i = 1; i < 8; ++i) {
                V3 p = xyz(positionAt(arc, arc.length * i / 8.0));
                double d = std::min({distanceTo(before, p, before.length - trim, before.length),
                                     distanceTo(middle, p, 0.0, middle.length),
                                     distanceTo(after, p, 0.0, trimAfter)});
                worst = std::max(worst, d);
            }
        }
        blend.deviation = worst;
        if (worst <= deviation) return blend;
    }
    blend.arcCount = 0;
    return blend;
}

}  // namespace kerf::motion
