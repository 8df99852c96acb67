#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "core/geometry/plane.h"
#include "core/workpiece/tool_sweep.h"

namespace kerf::workpiece {

// The material the program's tools have removed so far: the union of the volumes the cutters
// swept, in the coordinates of the tool-tip positions (workpiece coordinates, tool axis z).
// Sweeps are filed in a grid of cells in the plane, so a query looks only at the sweeps whose
// bounding box covers its cell: thousands of moves stay fast.
class RemovedMaterial {
public:
    // Helical arcs and arcs in the planes ZX and YZ become chords whose distance from the arc is
    // at most this (mm): the swept volume is that much smaller than the true one at most.
    static constexpr double kChordTolerance = 0.0005;

    void addLine(const Cutter& cutter, const Vec3& from, const Vec3& to);
    // An arc from `from` to `to` about `centre` in `plane`, by the signed `sweepRad` about the
    // plane's normal; the normal coordinate moves linearly (a helix). Exact in XY at one height.
    void addArc(const Cutter& cutter, const Vec3& from, const Vec3& to, const Vec3& centre,
                Plane plane, double sweepRad);

    // [choice] At most this many sweeps are kept (about 30 MB): a test run of a million
    // blocks must not hold them all. Later moves remove nothing; overflowed() says so.
    static constexpr size_t kMaxSweeps = 100000;
    bool overflowed() const { return m_overflowed; }

    bool empty() const { return m_sweeps.empty(); }
    size_t size() const { return m_sweeps.size(); }

    // How deep `p` lies in the removed volume: the largest depth within one sweep (a lower bound
    // of the depth in their union), negative or -infinity outside every sweep.
    double depth(const Vec3& p) const;
    // True when a disc of `radius` square to z, its centre moving from `a` to `b`, stays in one
    // sweep along a line all the way, so in the removed volume (0: the segment itself). Both
    // centres lie in that sweep made by a cutter `radius` thinner, which the disc dilates back
    // to the real one, and a line sweep is convex. A rapid retracing a feed move (a retract out
    // of a drilled hole) is proven free in one look.
    bool containsMovingDisc(const Vec3& a, const Vec3& b, double radius) const;

private:
    static constexpr double kCell = 5.0;               // mm
    static constexpr size_t kMaxCellsPerSweep = 4096;  // larger sweeps are looked at always

    void add(const Sweep& sweep);
    static int64_t cellOf(double coordinate);
    static uint64_t key(int64_t ix, int64_t iy);

    std::vector<Sweep> m_sweeps;
    std::unordered_map<uint64_t, std::vector<uint32_t>> m_cells;
    std::vector<uint32_t> m_large;
    bool m_overflowed = false;
};

}  // namespace kerf::workpiece
