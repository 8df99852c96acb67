#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "graphics/toolpath/toolpath_data.h"

namespace kerf::graphics {

// Polylines of one kind each, as flat arrays ready for a vertex buffer: points (xyz floats), the
// kind of every point (constant along a polyline) and the start of every polyline
// (offsets.size() == polylines + 1; offsets.back() == points).
struct PolylineSet {
    std::vector<float> xyz;
    std::vector<uint8_t> kind;
    std::vector<int32_t> offsets{0};
    Bounds3 bounds;

    size_t pointCount() const { return xyz.size() / 3; }
    size_t polylineCount() const { return offsets.size() - 1; }
    size_t segmentCount() const { return pointCount() - polylineCount(); }
};

// A run of consecutive path points with the same geometry at several levels of detail. Level 0
// is the exact path; level k >= 1 deviates from it by at most ToolpathGeometry::tolerances[k]
// and drops segments that coincide at that tolerance with one already drawn in this or an
// earlier chunk (paths that run over themselves, such as repeated passes, draw each place once).
struct ToolpathChunk {
    std::vector<PolylineSet> levels;
    Bounds3 bounds;
    uint32_t firstPoint = 0;  // range of ToolpathData points covered, [firstPoint, lastPoint]
    uint32_t lastPoint = 0;
};

struct LodOptions {
    size_t pointsPerChunk = 1u << 16;
    int coarseLevels = 8;                   // levels beyond the exact one
    double finestRelative = 1.0 / 32768.0;  // nominal tolerance of level 1, part of the diagonal
    double levelFactor = 2.0;  // each level's nominal tolerance is this many times the last
    int simplifyWindow = 64;   // bounds the simplification's worst case to O(n * 4 * window)
    unsigned threads = 0;      // 0: one per core
};

// The toolpath split into chunks (each culled and detailed on its own) with levels of detail.
struct ToolpathGeometry {
    std::vector<ToolpathChunk> chunks;
    std::vector<double> tolerances;  // per level: bound of the deviation in mm; [0] == 0
    Bounds3 bounds;
    // Segments drawn at a level (chunks without it count their coarsest level).
    size_t segmentCount(size_t level) const;
    size_t pointCount(size_t level) const;
};

ToolpathGeometry buildToolpathGeometry(const ToolpathData& data, const LodOptions& options = {});

// The coarsest level whose tolerance is at most `maxErrorPx` pixels of `mmPerPixel`.
int chooseLevel(const std::vector<double>& tolerances, double mmPerPixel, double maxErrorPx);

// Douglas-Peucker simplification of points [begin, end) of a flat xyz array, in windows of about
// `window` points (at most four times that) ending at points chosen by their coordinates and
// `salt` (use a different salt per level, so a coarser level does not keep the same breaks);
// appends the indices kept (always the first and the last).
void simplifyPolyline(const float* xyz, size_t begin, size_t end, double tolerance, int window,
                      std::vector<uint32_t>& kept, uint64_t salt = 0);

}  // namespace kerf::graphics
