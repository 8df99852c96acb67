#include "graphics/stock/mesh.h"

#include <Eigen/Geometry>

namespace kerf::graphics {

uint32_t Mesh::addVertex(const Vec3& p, const Vec3& n) {
    const auto index = static_cast<uint32_t>(vertexCount());
    points.push_back(static_cast<float>(p.x()));
    points.push_back(static_cast<float>(p.y()));
    points.push_back(static_cast<float>(p.z()));
    normals.push_back(static_cast<float>(n.x()));
    normals.push_back(static_cast<float>(n.y()));
    normals.push_back(static_cast<float>(n.z()));
    bounds.add(p);
    return index;
}

void Mesh::addTriangle(uint32_t a, uint32_t b, uint32_t c) {
    triangles.push_back(a);
    triangles.push_back(b);
    triangles.push_back(c);
}

void Mesh::addQuad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    addTriangle(a, b, c);
    addTriangle(a, c, d);
}

double Mesh::signedVolume() const {
    double volume = 0.0;
    for (size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const float* a = &points[3 * size_t{triangles[t]}];
        const float* b = &points[3 * size_t{triangles[t + 1]}];
        const float* c = &points[3 * size_t{triangles[t + 2]}];
        const Vec3 va(a[0], a[1], a[2]);
        const Vec3 vb(b[0], b[1], b[2]);
        const Vec3 vc(c[0], c[1], c[2]);
        volume += va.dot(vb.cross(vc));
    }
    return volume / 6.0;
}

}  // namespace kerf::graphics
