#pragma once

#include <cstdint>
#include <vector>

#include "graphics/toolpath/toolpath_data.h"

namespace kerf::graphics {

// A triangle mesh as flat arrays (VTK-free), built by the stock models and tool glyphs and
// turned into a shaded solid by the scene.
struct Mesh {
    std::vector<float> points;        // xyz per vertex
    std::vector<float> normals;       // xyz per vertex (unit), may be empty
    std::vector<uint32_t> triangles;  // 3 vertex indices per triangle
    Bounds3 bounds;
    // A stock lying along X (0) or Y (1) about the origin (a part on a rotary table) is shaded
    // by the distance from that axis, as a lathe's is from Z; -1: by height.
    int shadeAboutAxis = -1;

    size_t vertexCount() const { return points.size() / 3; }
    size_t triangleCount() const { return triangles.size() / 3; }
    uint32_t addVertex(const Vec3& p, const Vec3& n);
    void addTriangle(uint32_t a, uint32_t b, uint32_t c);
    void addQuad(uint32_t a, uint32_t b, uint32_t c, uint32_t d);
    // Volume enclosed (divergence theorem); meaningful for closed meshes.
    double signedVolume() const;
};

}  // namespace kerf::graphics
