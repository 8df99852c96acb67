#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "graphics/stock/cutter.h"
#include "graphics/stock/mesh.h"

namespace kerf::graphics {

// A bar on the lathe: revolved about Z, between zMin and zMax (mm), optionally bored.
struct LatheBar {
    double radiusMm = 25.0;
    double innerRadiusMm = 0.0;
    double zMin = -100.0;
    double zMax = 0.0;
};

// Lathe stock as a 2D profile: an occupancy grid over the half plane (radius, Z), swept by the
// insert and revolved for display. The removed volume sums the rings of the removed cells
// (2 pi r dr dz each), exact for the grid.
class LatheStock {
public:
    LatheStock(const LatheBar& bar, double cellMm, size_t maxCells);

    // A blank turned from an outline in (radius, Z) (the FAGOR raw-stock profile), closed towards
    // `side` (a unit (radius, Z) vector): to the bore of `bar` (the axis without one), to the
    // outside of `bar` and the outline, or to the end of `bar` and the outline along Z. The grid
    // covers the closed outline; a cell is material when its centre lies inside it.
    static LatheStock revolved(const std::vector<std::pair<double, double>>& outline,
                               std::pair<double, double> side, const LatheBar* bar, double cellMm,
                               size_t maxCells);

    // Removes what the insert sweeps moving its programmed point from a to b, given as
    // (X radius, Z). The part turns, so a tool beyond the axis (X < 0) cuts at |X| too. The
    // holder side is solid: outside the swept insert for external tools, inside it for boring
    // tools (tip codes 1, 7, 8).
    bool cut(double ax, double az, double bx, double bz, const LatheInsert& insert);

    double cellMm() const { return m_cell; }
    int cellsR() const { return m_nr; }
    int cellsZ() const { return m_nz; }
    bool material(int ir, int iz) const { return m_cells[index(ir, iz)] != 0; }
    const LatheBar& bar() const { return m_bar; }

    double initialVolumeMm3() const { return m_initialVolume; }
    double volumeMm3() const;
    double removedVolumeMm3() const { return m_initialVolume - volumeMm3(); }

    // Revolved solid over `sweepDeg` (180: the half section seen from +Y, the cut faces in the
    // plane Y = 0; 360: the whole part), profile sampled on at most `maxSide` cells per side.
    Mesh mesh(double sweepDeg = 180.0, int angularSteps = 48, int maxSide = 400) const;

private:
    // Clears the cells whose centres lie outside the closed polygon of (radius, Z) points.
    void keepInside(const std::vector<std::pair<double, double>>& polygon);
    size_t index(int ir, int iz) const {
        return static_cast<size_t>(iz) * static_cast<size_t>(m_nr) + static_cast<size_t>(ir);
    }
    LatheBar m_bar;
    double m_cell = 0.1;
    double m_z0 = 0.0;
    int m_nr = 0;
    int m_nz = 0;
    double m_initialVolume = 0.0;
    std::vector<uint8_t> m_cells;
};

}  // namespace kerf::graphics
