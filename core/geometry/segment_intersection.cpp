#include "core/geometry/segment_intersection.h"

#include <algorithm>
#include <cmath>

#include "core/geometry/arc_math.h"

namespace kerf {

std::vector<Vec2> carrierIntersections(const PlanarSegment& a, const PlanarSegment& b) {
    using Kind = PlanarSegment::Kind;
    std::vector<Vec2> out;
    if (a.kind == Kind::Line && b.kind == Kind::Line) {
        const Vec2 da = a.end - a.start;
        const Vec2 db = b.end - b.start;
        const double det = cross2(da, db);
        if (std::fabs(det) < 1e-14) return out;
        const double t = cross2(b.start - a.start, db) / det;
        out.push_back(a.start + t * da);
        return out;
    }
    if (a.kind == Kind::Arc && b.kind == Kind::Line) return carrierIntersections(b, a);
    if (a.kind == Kind::Line) {
        const Vec2 d = (a.end - a.start).normalized();
        const Vec2 f = a.start - b.center;
        const double along = -f.dot(d);
        const double r = b.radius();
        const double h2 = r * r - (f.squaredNorm() - along * along);
        if (h2 < -1e-12) return out;
        const double h = std::sqrt(std::max(0.0, h2));
        out.push_back(a.start + (along - h) * d);
        out.push_back(a.start + (along + h) * d);
        return out;
    }
    const Vec2 dc = b.center - a.center;
    const double dist = dc.norm();
    const double ra = a.radius();
    const double rb = b.radius();
    if (dist < 1e-12) return out;
    const double x = (dist * dist + ra * ra - rb * rb) / (2.0 * dist);
    const double h2 = ra * ra - x * x;
    if (h2 < -1e-12) return out;
    const double h = std::sqrt(std::max(0.0, h2));
    const Vec2 u = dc / dist;
    const Vec2 n(-u.y(), u.x());
    out.push_back(a.center + x * u + h * n);
    out.push_back(a.center + x * u - h * n);
    return out;
}

}  // namespace kerf
