#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "graphics/stock/cutter.h"
#include "graphics/stock/height_field_stock.h"
#include "graphics/stock/mesh.h"

namespace kerf::graphics {

// Mill stock as voxels: one bit per cube of the grid, set while the cube's centre is material.
// Unlike the height field it holds a tool of any direction (tilted working plane, simultaneous
// 5-axis moves) and undercuts. Why voxels and not tri-dexels or a distance field: docs/graphics.md.
class VoxelStock {
public:
    // A box blank; the cell size is raised when the grid would exceed `maxVoxels`.
    VoxelStock(const Vec3& min, const Vec3& max, double cellMm, size_t maxVoxels);
    // The material of a height field (tool axis Z so far), at the height field's cell size or
    // coarser when the box it spans would exceed `maxVoxels`.
    static VoxelStock fromHeightField(const HeightFieldStock& field, size_t maxVoxels);
    // A cylinder lying along the workpiece's X (`along` 0) or Y (1), or standing along Z (2), its
    // axis through the origin, from `lowMm` to `highMm` along it, bored to `innerRadiusMm`: the
    // blank of a part clamped on a rotary table, which the height field cannot hold.
    static VoxelStock cylinder(int along, double radiusMm, double innerRadiusMm, double lowMm,
                               double highMm, double cellMm, size_t maxVoxels);

    // Removes what the cutter sweeps while its tip moves in a straight line from a to b, its
    // axis (unit, from the tip up the tool) along `axis` all the way. The tool is taken as long as
    // cuttingLengthMm(cutter). Returns true when material was removed.
    bool cut(const Vec3& a, const Vec3& b, const Vec3& axis, const MillCutter& cutter);
    static double cuttingLengthMm(const MillCutter& cutter);

    double cellMm() const { return m_cell; }
    int cellsX() const { return m_nx; }
    int cellsY() const { return m_ny; }
    int cellsZ() const { return m_nz; }
    Vec3 minCorner() const { return m_origin; }
    Vec3 maxCorner() const { return m_origin + m_cell * Vec3(m_nx, m_ny, m_nz); }
    // The voxel holding `p` is material (false outside the grid).
    bool solidAt(const Vec3& p) const;
    size_t solidVoxels() const;
    double volumeMm3() const;

    // Shaded solid: the boundary faces of a grid of at most `maxSide` cubes a side, a cube solid
    // when at least half of the voxels it covers are.
    Mesh mesh(int maxSide = 200) const;

private:
    VoxelStock() = default;
    void allocate(const Vec3& min, const Vec3& max, double cellMm, size_t maxVoxels);
    size_t row(int j, int k) const {
        return (static_cast<size_t>(k) * static_cast<size_t>(m_ny) + static_cast<size_t>(j)) *
               m_wordsPerRow;
    }
    bool bit(int i, int j, int k) const {
        return (m_bits[row(j, k) + static_cast<size_t>(i >> 6)] >> (i & 63)) & 1u;
    }
    // Solid voxels of row (j, k) in [i0, i1).
    int countRow(int j, int k, int i0, int i1) const;

    Vec3 m_origin{0.0, 0.0, 0.0};
    double m_cell = 1.0;
    int m_nx = 0;
    int m_ny = 0;
    int m_nz = 0;
    size_t m_wordsPerRow = 0;
    std::vector<uint64_t> m_bits;
};

}  // namespace kerf::graphics
