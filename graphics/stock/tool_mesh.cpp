#include "graphics/stock/tool_mesh.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/geometry/arc_math.h"

namespace kerf::graphics {

Mesh millToolMesh(const MillCutter& cutter, Axis axis, int segments) {
    Mesh mesh;
    if (!(cutter.radiusMm > 0.0) || !std::isfinite(cutter.radiusMm)) return mesh;
    const double r = cutter.radiusMm;
    const double length = cutter.lengthMm > 0.0 ? cutter.lengthMm : std::max(10.0, 4.0 * r);
    // Profile (rho, height) from the tip up the side to the top.
    std::vector<std::pair<double, double>> profile;
    const int n = 12;
    for (int i = 0; i <= n; ++i) {
        const double rho = r * i / n;
        const double h = cutter.heightAt(rho);
        profile.emplace_back(rho, std::isfinite(h) ? h : 0.0);
    }
    profile.emplace_back(r, std::max(length, profile.back().second));
    profile.emplace_back(0.0, std::max(length, profile.back().second));
    auto place = [&](double x, double y, double z) {
        switch (axis) {
            case Axis::X:
                return Vec3(z, x, y);
            case Axis::Y:
                return Vec3(y, z, x);
            default:
                return Vec3(x, y, z);
        }
    };
    const int s = std::max(8, segments);
    // One band per profile segment with its own normals, so edges stay crisp.
    for (size_t p = 0; p + 1 < profile.size(); ++p) {
        const auto [rho0, h0] = profile[p];
        const auto [rho1, h1] = profile[p + 1];
        const double dr = rho1 - rho0;
        const double dh = h1 - h0;
        const double len = std::hypot(dr, dh);
        if (len < 1e-12) continue;
        const double nr = dh / len;   // radial part of the outward normal
        const double na = -dr / len;  // axial part
        std::vector<uint32_t> lower;
        std::vector<uint32_t> upper;
        for (int k = 0; k < s; ++k) {
            const double a = kTwoPi * k / s;
            const double c = std::cos(a);
            const double sn = std::sin(a);
            const Vec3 normal = place(nr * c, nr * sn, na);
            lower.push_back(mesh.addVertex(place(rho0 * c, rho0 * sn, h0), normal));
            upper.push_back(mesh.addVertex(place(rho1 * c, rho1 * sn, h1), normal));
        }
        for (int k = 0; k < s; ++k) {
            const auto k0 = static_cast<size_t>(k);
            const auto k1 = static_cast<size_t>((k + 1) % s);
            mesh.addQuad(lower[k0], lower[k1], upper[k1], upper[k0]);
        }
    }
    return mesh;
}

Mesh latheInsertMesh(const LatheInsert& insert, double thickness) {
    Mesh mesh;
    const auto outline = insert.outline(24);
    if (outline.size() < 3) return mesh;
    const double half = std::max(0.01, thickness) * 0.5;
    double cx = 0.0;
    double cz = 0.0;
    for (const auto& [x, z] : outline) {
        cx += x;
        cz += z;
    }
    cx /= static_cast<double>(outline.size());
    cz /= static_cast<double>(outline.size());
    for (double side : {-1.0, 1.0}) {
        const Vec3 normal(0, side, 0);
        const uint32_t centre = mesh.addVertex(Vec3(cx, side * half, cz), normal);
        std::vector<uint32_t> ring;
        for (const auto& [x, z] : outline)
            ring.push_back(mesh.addVertex(Vec3(x, side * half, z), normal));
        // Winding must agree with the normal: VTK flips the normals of back-facing triangles.
        for (size_t i = 0; i < ring.size(); ++i) {
            const uint32_t next = ring[(i + 1) % ring.size()];
            if (side > 0.0) {
                mesh.addTriangle(centre, next, ring[i]);
            } else {
                mesh.addTriangle(centre, ring[i], next);
            }
        }
    }
    for (size_t i = 0; i < outline.size(); ++i) {
        const auto [x0, z0] = outline[i];
        const auto [x1, z1] = outline[(i + 1) % outline.size()];
        const Vec3 normal = Vec3(z1 - z0, 0.0, -(x1 - x0)).normalized();
        const uint32_t a = mesh.addVertex(Vec3(x0, -half, z0), normal);
        const uint32_t b = mesh.addVertex(Vec3(x1, -half, z1), normal);
        const uint32_t c = mesh.addVertex(Vec3(x1, half, z1), normal);
        const uint32_t d = mesh.addVertex(Vec3(x0, half, z0), normal);
        mesh.addQuad(a, b, c, d);
    }
    return mesh;
}

}  // namespace kerf::graphics
