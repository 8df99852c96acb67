#include "motion/planner/biarc.h"

#include <cmath>

namespace kerf::motion {

namespace {

using V3 = Vec3Array;

V3 sub(const V3& a, const V3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
V3 add(const V3& a, const V3& b) {
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}
V3 scale(const V3& a, double f) {
    return {a[0] * f, a[1] * f, a[2] * f};
}
double dot(const V3& a, const V3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

AxisVector withXyz(const AxisVector& base, const V3& p) {
    AxisVector out = base;
    out[0] = p[0];
    out[1] = p[1];
    out[2] = p[2];
    return out;
}

}  // namespace

int makeBiarc(const AxisVector& base, const V3& p0, const V3& t0, const V3& p1, const V3& t1,
              std::array<PathGeometry, 2>& arcs) {
    V3 v = sub(p1, p0);
    V3 t = add(t0, t1);
    double c = dot(t0, t1);
    double vt = dot(v, t);
    double vv = dot(v, v);
    double root = vt + std::sqrt(vt * vt + 2.0 * (1.0 - c) * vv);
    if (!(root > 0.0) || vv <= 0.0) return 0;
    double d = vv / root;
    V3 q0 = add(p0, scale(t0, d));
    V3 q1 = sub(p1, scale(t1, d));
    V3 joint = scale(add(q0, q1), 0.5);
    V3 leg = sub(q1, q0);
    double legLength = std::sqrt(dot(leg, leg));
    if (!(legLength > 0.0)) return 0;
    arcs[0] = makeTangentArc(withXyz(base, p0), t0, withXyz(base, joint));
    arcs[1] = makeTangentArc(withXyz(base, joint), scale(leg, 1.0 / legLength), withXyz(base, p1));
    return 2;
}

}  // namespace kerf::motion
