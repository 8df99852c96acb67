#include "graphics/stock/cutter.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geometry/arc_math.h"

namespace kerf::graphics {

const char* cutterKindName(CutterKind kind) {
    switch (kind) {
        case CutterKind::Flat:
            return "flat";
        case CutterKind::Ball:
            return "ball";
        case CutterKind::BullNose:
            return "bull-nose";
        case CutterKind::Drill:
            return "drill";
    }
    return "?";
}

MillCutter MillCutter::fromGeometry(double radiusMm, double radius2Mm, double pointAngleDeg) {
    MillCutter cutter;
    cutter.radiusMm = std::isfinite(radiusMm) ? std::max(0.0, radiusMm) : 0.0;
    const double r2 = std::isfinite(radius2Mm) ? std::clamp(radius2Mm, 0.0, cutter.radiusMm) : 0.0;
    if (std::isfinite(pointAngleDeg) && pointAngleDeg > 0.0 && pointAngleDeg < 180.0) {
        cutter.kind = CutterKind::Drill;
        cutter.pointAngleDeg = pointAngleDeg;
    } else if (r2 > 0.0 && r2 >= cutter.radiusMm - 1e-9) {
        cutter.kind = CutterKind::Ball;
        cutter.cornerRadiusMm = cutter.radiusMm;
    } else if (r2 > 0.0) {
        cutter.kind = CutterKind::BullNose;
        cutter.cornerRadiusMm = r2;
    }
    return cutter;
}

MillCutter MillCutter::touchProbeStylus(double ballRadiusMm) {
    MillCutter stylus = fromGeometry(ballRadiusMm, ballRadiusMm);
    stylus.touchProbe = true;
    return stylus;
}

double MillCutter::heightAt(double rho) const {
    if (rho > radiusMm) return std::numeric_limits<double>::infinity();
    switch (kind) {
        case CutterKind::Flat:
            return 0.0;
        case CutterKind::Ball:
        case CutterKind::BullNose: {
            const double r2 = cornerRadiusMm;
            const double flat = radiusMm - r2;
            if (rho <= flat) return 0.0;
            const double d = rho - flat;
            return r2 - std::sqrt(std::max(0.0, r2 * r2 - d * d));
        }
        case CutterKind::Drill:
            return rho / std::tan(degToRad(pointAngleDeg) * 0.5);
    }
    return 0.0;
}

double MillCutter::profileHeight() const {
    return heightAt(radiusMm);
}

double MillCutter::volumeBelow(double h) const {
    if (!(h > 0.0) || !cuts()) return 0.0;
    const double r = radiusMm;
    switch (kind) {
        case CutterKind::Flat:
            return kPi * r * r * h;
        case CutterKind::Drill: {
            const double cone = profileHeight();
            if (h <= cone) {
                const double rh = r * h / cone;
                return kPi * rh * rh * h / 3.0;
            }
            return kPi * r * r * cone / 3.0 + kPi * r * r * (h - cone);
        }
        case CutterKind::Ball:
        case CutterKind::BullNose: {
            // Integrate the disc areas of the profile: radius(z) for 0 <= z <= h.
            const double r2 = cornerRadiusMm;
            const double flat = r - r2;
            const double top = std::min(h, r2);
            // radius(z) = flat + sqrt(r2^2 - (r2 - z)^2) for z in [0, r2]
            // pi * integral (flat + s)^2 dz with s = sqrt(r2^2 - (r2 - z)^2)
            auto primitive = [&](double z) {
                const double u = z - r2;                               // from -r2 to 0
                const double s2int = r2 * r2 * z - (u * u * u) / 3.0;  // integral of s^2
                const double sint = 0.5 * (u * std::sqrt(std::max(0.0, r2 * r2 - u * u)) +
                                           r2 * r2 * std::asin(std::clamp(u / r2, -1.0, 1.0)));
                return flat * flat * z + 2.0 * flat * sint + s2int;
            };
            double volume = kPi * (primitive(top) - primitive(0.0));
            if (h > r2) volume += kPi * r * r * (h - r2);
            return volume;
        }
    }
    return 0.0;
}

std::pair<double, double> LatheInsert::tipDirection(int code) {
    switch (code) {
        case 1:
            return {1.0, -1.0};
        case 2:
            return {0.0, -1.0};
        case 3:
            return {-1.0, -1.0};
        case 4:
            return {-1.0, 0.0};
        case 5:
            return {-1.0, 1.0};
        case 6:
            return {0.0, 1.0};
        case 7:
            return {1.0, 1.0};
        case 8:
            return {1.0, 0.0};
        default:
            return {0.0, 0.0};
    }
}

std::pair<double, double> LatheInsert::noseCentreOffset() const {
    auto [ux, uz] = tipDirection(locationCode);
    const double r = std::isfinite(noseRadiusMm) ? std::max(0.0, noseRadiusMm) : 0.0;
    return {-r * ux, -r * uz};
}

LatheInsert LatheInsert::fromGeometry(const canon::ToolGeometry& geometry) {
    LatheInsert insert;
    insert.noseRadiusMm = std::max(0.0, geometry.radiusMm);
    if (geometry.locationCode >= 0) insert.locationCode = geometry.locationCode;
    if (geometry.locationCode >= 0 && geometry.cuttingWidthMm > 0.0 &&
        std::isfinite(geometry.cuttingWidthMm)) {
        const bool centre = geometry.locationCode == 0 || geometry.locationCode == 9;
        insert.kind = centre ? LatheToolKind::Drill : LatheToolKind::Grooving;
        insert.widthMm = geometry.cuttingWidthMm;
    }
    const double point = geometry.noseAngleDeg;
    if (insert.kind == LatheToolKind::Drill && point > 0.0 && point < 180.0) {
        insert.pointAngleDeg = point;
    }
    return insert;
}

bool LatheInsert::groovesAlongZ() const {
    return kind == LatheToolKind::Grooving && tipDirection(locationCode).first == 0.0;
}

std::vector<std::pair<double, double>> LatheInsert::outline(int arcPoints, double bodyMm) const {
    if (kind != LatheToolKind::Turning) {
        // Counter-clockwise in (X, Z): a drill on its axis, the tip of its point at the
        // programmed point and its body along +Z (it enters the part's face from the turret
        // side); a blade's rectangle across its width, its body behind the edge, the programmed
        // point at the corner or middle the code names.
        const double w = std::isfinite(widthMm) ? std::max(0.0, widthMm) : 0.0;
        const double body = bodyMm > 0.0 ? bodyMm : 4.0 * w;
        if (kind == LatheToolKind::Drill) {
            const bool pointed =
                std::isfinite(pointAngleDeg) && pointAngleDeg > 0.0 && pointAngleDeg < 180.0;
            const double half = 0.5 * w;
            const double cone =
                pointed ? std::min(half / std::tan(degToRad(pointAngleDeg) * 0.5), body) : 0.0;
            return {{0.0, 0.0}, {half, cone}, {half, body}, {-half, body}, {-half, cone}};
        }
        const auto [ux, uz] = tipDirection(locationCode);
        double x0 = -0.5 * w;
        double x1 = 0.5 * w;
        double z0 = 0.0;
        double z1 = body;
        if (kind == LatheToolKind::Grooving && ux != 0.0) {
            // Plunges along X: the edge faces u_X, the width runs away from the tip's Z side.
            x0 = ux < 0.0 ? 0.0 : -body;
            x1 = ux < 0.0 ? body : 0.0;
            z0 = uz < 0.0 ? 0.0 : (uz > 0.0 ? -w : -0.5 * w);
            z1 = z0 + w;
        } else if (kind == LatheToolKind::Grooving) {
            // Plunges along Z (face grooving): the width runs outwards from the programmed point,
            // as G89 places the tool against the groove's inner wall.
            x0 = 0.0;
            x1 = w;
            z0 = uz < 0.0 ? 0.0 : -body;
            z1 = uz < 0.0 ? body : 0.0;
        }
        return {{x0, z0}, {x1, z0}, {x1, z1}, {x0, z1}};
    }
    const double r = std::isfinite(noseRadiusMm) ? std::max(0.0, noseRadiusMm) : 0.0;
    const auto [cx, cz] = noseCentreOffset();
    std::vector<std::pair<double, double>> points;
    const int n = std::max(arcPoints, 8);
    const bool body = includedAngleDeg > 0.0 && includedAngleDeg < 180.0 && edgeLengthMm > 0.0 &&
                      std::isfinite(edgeLengthMm);
    if (!body) {
        for (int i = 0; i < n; ++i) {
            const double a = kTwoPi * i / n;
            points.emplace_back(cx + r * std::cos(a), cz + r * std::sin(a));
        }
        return points;
    }
    // Direction (X, Z) in which the tip points; centre codes point along -X, -Z like code 3.
    auto [dx, dz] = tipDirection(locationCode);
    if (dx == 0.0 && dz == 0.0) {
        dx = -1.0;
        dz = -1.0;
    }
    const double norm = std::hypot(dx, dz);
    dx /= norm;
    dz /= norm;
    // Sharp corner V of the rhombus ahead of the nose centre; edges e1, e2 run back from it at
    // +-half the included angle; the nose arc is tangent to both.
    const double half = degToRad(includedAngleDeg) * 0.5;
    const double vx = cx + dx * r / std::sin(half);
    const double vz = cz + dz * r / std::sin(half);
    const double back = std::atan2(-dz, -dx);  // angle of the backward direction in (X, Z)
    const double e1 = back + half;
    const double e2 = back - half;
    // Nose arc from the tangent point on edge 1 round the front to the one on edge 2 (the outward
    // normals of the edges), spanning 180 degrees less the included angle.
    const double arcFrom = e1 + kPi * 0.5;
    const double sweep = kPi - 2.0 * half;
    for (int i = 0; i <= n; ++i) {
        const double a = arcFrom + sweep * i / n;
        points.emplace_back(cx + r * std::cos(a), cz + r * std::sin(a));
    }
    const double l = edgeLengthMm;
    points.emplace_back(vx + l * std::cos(e2), vz + l * std::sin(e2));
    points.emplace_back(vx + l * (std::cos(e1) + std::cos(e2)),
                        vz + l * (std::sin(e1) + std::sin(e2)));
    points.emplace_back(vx + l * std::cos(e1), vz + l * std::sin(e1));
    return points;
}

}  // namespace kerf::graphics
