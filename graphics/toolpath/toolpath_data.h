#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/base/source_location.h"
#include "core/canon/commands.h"
#include "core/machine/workpiece_frame.h"

namespace kerf::graphics {

// Colour classes of the toolpath.
enum class MoveKind : uint8_t { Rapid, Feed, Arc, Synced, Probe };
inline constexpr int kMoveKindCount = 5;
const char* moveKindName(MoveKind kind);

// Axis-aligned box in mm; empty until a point is added.
struct Bounds3 {
    Vec3 min{0.0, 0.0, 0.0};
    Vec3 max{0.0, 0.0, 0.0};
    bool empty = true;
    void add(const Vec3& p);
    void add(const Bounds3& other);
    Vec3 centre() const { return (min + max) * 0.5; }
    double diagonal() const { return empty ? 0.0 : (max - min).norm(); }
};

// A tool taking effect at a point of the path (from the canonical ToolChange).
struct ToolEvent {
    uint32_t move = 0;  // index of the first move made with this tool
    canon::ToolChange tool;
};

// The toolpath as compact arrays, appended while the canonical stream is consumed: one continuous
// polyline of tool-tip points (workpiece coordinates, mm, float; lathe X is a radius) and one
// record per move. Move m owns the points [firstPoint[m], firstPoint[m + 1]) and the segments
// reaching them, so segment s (from point s - 1 to point s, s >= 1) belongs to the last move
// whose firstPoint <= s. No object per segment.
struct ToolpathData {
    std::vector<float> xyz;  // 3 floats per point; point 0 is the start position
    // A machine with rotary tables: per point the tool's direction on the workpiece (unit, from
    // the tip up the tool), 3 floats; empty on other machines (the tool stands along Z).
    std::vector<float> toolAxis;
    std::vector<uint32_t> firstPoint;       // per move
    std::vector<MoveKind> kinds;            // per move
    std::vector<SourceLocation> locations;  // per move
    std::vector<ToolEvent> tools;
    std::optional<canon::StockDefinition> stock;  // the first BLK FORM of the program
    bool xInDiameter = false;                     // lathe display mode at the end of the stream
    bool truncated = false;   // the point cap was reached; later moves are missing
    size_t skippedMoves = 0;  // moves with coordinates that are not finite
    Bounds3 bounds;           // of every point
    Bounds3 feedBounds;       // of the points of feed moves (arcs, synced, probe)

    size_t pointCount() const { return xyz.size() / 3; }
    size_t moveCount() const { return firstPoint.size(); }
    size_t segmentCount() const { return pointCount() > 0 ? pointCount() - 1 : 0; }
    Vec3 point(size_t i) const { return {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}; }
    Vec3 toolAxisAt(size_t i) const {
        if (3 * i + 2 >= toolAxis.size()) return Vec3::UnitZ();
        return {toolAxis[3 * i], toolAxis[3 * i + 1], toolAxis[3 * i + 2]};
    }
    // The move owning segment s (1 <= s < pointCount()); nullopt if none does.
    std::optional<uint32_t> moveOfSegment(size_t segment) const;
    // Points of move m: [begin, end).
    std::pair<size_t, size_t> pointsOfMove(size_t move) const;
    // Approximate heap use in bytes.
    size_t memoryBytes() const;
};

struct ToolpathOptions {
    double arcChordToleranceMm = 0.002;  // world tolerance of the stored arc points
    int maxPointsPerArc = 4096;
    size_t maxPoints = 50'000'000;  // cap for endless programs (HMI stays responsive)
    // A machine with rotary tables: the path is drawn on the workpiece the tables turn, a move
    // whose tables turn in points at most `maxTableStepDeg` of turn apart.
    std::optional<machine::WorkpieceFrame> workpieceFrame;
    double maxTableStepDeg = 1.0;
};

// canon::Sink that collects the toolpath while the stream is consumed by everyone else.
class ToolpathCollector final : public canon::Sink {
public:
    explicit ToolpathCollector(ToolpathOptions options = {});

    // Position before the first command; the first point of the path.
    void setStart(const Pose& start);
    void consume(const canon::Command& command) override;

    const ToolpathData& data() const { return m_data; }
    // Hands the collected data over and starts again from the current position.
    ToolpathData take();
    const Pose& position() const { return m_position; }

private:
    void beginMove(const SourceLocation& location, MoveKind kind);
    void addPoint(const Vec3& p, bool feed);
    void addPoint(const machine::ToolOnPart& p, bool feed);
    machine::ToolOnPart onPart(const Pose& stream) const;
    void addLine(const canon::Command& command, const Pose& target, MoveKind kind);

    ToolpathOptions m_options;
    ToolpathData m_data;
    Pose m_position{};
    std::vector<Vec3> m_scratch;
    std::vector<machine::ToolOnPart> m_samples;
};

}  // namespace kerf::graphics
