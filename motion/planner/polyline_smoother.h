#pragma once

#include <array>
#include <cstddef>
#include <deque>
#include <vector>

#include "motion/path/path_geometry.h"

// Smoothing of CAM polylines within the path tolerance (TNC cycle 32 T, Fagor G51 E): a run of
// short lines that describes a smooth curve is followed as biarcs between knots placed on its
// vertices every few millimetres. The tangent at a knot comes from chords of the polyline over
// +-h around it, so the rounding of the vertices (delta = 5e-5 mm at 4 decimals) averages out:
// the curvature is that of a curve through knots millimetres apart (error about delta / L^2),
// not the 2 delta / l^2 of neighbouring vertices l apart. A span whose biarc leaves the polyline
// by more than the allowed deviation is split; a single segment that still does not fit stays
// a line (its corners are blended as usual). Planner thread.
namespace kerf::motion {

struct SmoothPiece {
    bool fitted = false;  // false: segment `lastSegment` as a line
    std::array<PathGeometry, 2> arcs{};
    // Of a line after a fitted piece that ended off the vertex: where the line starts.
    bool startsOffVertex = false;
    AxisVector lineStart{};
    size_t firstSegment = 0;  // segments covered (segment k runs from vertex k - 1 to vertex k)
    size_t lastSegment = 0;
    size_t jointSegment = 0;         // segment whose span holds the joint of the two arcs
    bool tangentToPrevious = false;  // starts with the end tangent of the piece before
    double deviation = 0.0;          // largest distance of the polyline from the biarc
};

class PolylineSmoother {
public:
    // Longest span between two knots, and the half-width of the chords that give a knot's
    // tangent (the chords reach 2h beyond the knot).
    static constexpr double kSpanMm = 2.0;
    static constexpr double kChordMm = 0.5;
    // A single segment that does not fit within the allowed deviation may deviate this much
    // more (the planner gives the servo filter what the fit leaves of the tolerance).
    static constexpr double kLooseFitFactor = 1.3;

    // A new run starting at `first` (vertex 0).
    void start(const AxisVector& first);
    // The end of the next segment of the run.
    void add(const AxisVector& vertex);
    size_t segments() const { return m_base + m_points.size() - 1; }
    // Length of the run not yet taken.
    double pendingLength() const;

    // Appends the pieces that no later vertex can change, in order (all of them when `final`).
    void take(double deviation, bool final, std::vector<SmoothPiece>& out);

private:
    struct Vertex {
        AxisVector position{};
        double s = 0.0;  // arc length along the polyline from vertex 0
    };
    const Vertex& vertex(size_t index) const { return m_points[index - m_base]; }
    // Last vertex at or before arc length s.
    size_t vertexBefore(double s) const;
    Vec3Array pointAtLength(double s) const;
    // Unit tangent of the curve at a vertex, from chords of the polyline kept around it.
    Vec3Array tangentAt(size_t index) const;
    // Where a knot at an inner vertex goes: moved towards the curve's centre by half the sagitta
    // of the segments there, so that the curve passes between the vertices and the segments'
    // midpoints instead of through the vertices (a 0.5 mm polyline of R5 has a sagitta of
    // 0.0063 mm, more than half the 0.01 mm tolerance; half of it fits).
    Vec3Array knotAt(size_t index) const;
    // Largest distance of the vertices and segment midpoints of [a, b] from the biarc (stops
    // counting once it exceeds `allowed`).
    double deviationOf(const std::array<PathGeometry, 2>& arcs, size_t a, size_t b,
                       double allowed) const;

    std::deque<Vertex> m_points;
    size_t m_base = 0;  // vertex number of m_points.front()
    size_t m_knot = 0;  // vertex where the next piece starts
    Vec3Array m_knotTangent{};
    Vec3Array m_knotPoint{};      // where the next piece starts when m_tangentKnown
    bool m_tangentKnown = false;  // m_knotTangent is the end tangent of the last fitted piece
    double m_span = kSpanMm;      // longest span tried next
};

}  // namespace kerf::motion
