#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "graphics/stock/cutter.h"
#include "graphics/stock/mesh.h"

namespace kerf::graphics {

// Mill stock as a height field (Z-map) over a regular XY grid: each cell keeps the height of the
// material's top at its centre; material fills the cell from the blank's bottom up to there.
// Tool axis Z. Cells outside a cylindrical blank hold no material.
class HeightFieldStock {
public:
    // A box blank; the cell size is raised when the grid would exceed `maxCells`.
    HeightFieldStock(const Vec3& min, const Vec3& max, double cellMm, size_t maxCells);
    // A cylindrical blank standing on its axis (Z), optionally hollow.
    static HeightFieldStock cylinder(double centreX, double centreY, double radiusMm,
                                     double innerRadiusMm, double zMin, double zMax, double cellMm,
                                     size_t maxCells);

    // Removes what the cutter's tip moving in a straight line from a to b sweeps through.
    // Returns true when material was removed.
    bool cut(const Vec3& a, const Vec3& b, const MillCutter& cutter);

    double cellMm() const { return m_cell; }
    int cellsX() const { return m_nx; }
    int cellsY() const { return m_ny; }
    double topAt(int i, int j) const { return double{m_top[index(i, j)]}; }
    bool hasMaterial(int i, int j) const { return double{m_top[index(i, j)]} > m_bottom; }
    Vec3 minCorner() const { return {m_x0, m_y0, m_bottom}; }
    Vec3 maxCorner() const { return {m_x0 + m_nx * m_cell, m_y0 + m_ny * m_cell, m_topZ}; }

    double initialVolumeMm3() const { return m_initialVolume; }
    double volumeMm3() const;
    double removedVolumeMm3() const { return m_initialVolume - volumeMm3(); }

    // Shaded solid: the top surface sampled on at most `maxSide` vertices per side (each sample
    // the lowest height of the cells it covers, so narrow cuts stay visible), walls and bottom.
    Mesh mesh(int maxSide = 512) const;

private:
    HeightFieldStock() = default;
    void allocate(double x0, double y0, double x1, double y1, double cellMm, size_t maxCells);
    size_t index(int i, int j) const {
        return static_cast<size_t>(j) * static_cast<size_t>(m_nx) + static_cast<size_t>(i);
    }

    double m_x0 = 0.0;
    double m_y0 = 0.0;
    double m_cell = 1.0;
    int m_nx = 0;
    int m_ny = 0;
    double m_bottom = 0.0;
    double m_topZ = 0.0;
    double m_initialVolume = 0.0;
    std::vector<float> m_top;
};

}  // namespace kerf::graphics
