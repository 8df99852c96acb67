#pragma once

#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "core/base/source_location.h"
#include "core/geometry/axes.h"
#include "core/geometry/plane.h"

// The canonical command stream: what every dialect front end produces and every consumer (motion,
// graphics, reports, golden traces) reads. Positions are in the workpiece coordinate system of the
// active preset, in mm (linear) and degrees (rotary), for the tool tip; lathe X is a radius here.
namespace kerf::canon {

struct RapidMove {
    Pose target;
};

// Feed is mm/min, or mm/rev when the feed mode is per revolution.
struct LinearMove {
    Pose target;
    double feed = 0.0;
};

// Circular or helical move: the centre's in-plane coordinates define the circle, the signed sweep
// (radians, positive = counter-clockwise about the plane normal) its extent; the target's normal
// coordinate (and other axes) move linearly along it.
struct ArcMove {
    Pose target;
    Vec3 center;
    Plane plane = Plane::XY;
    double sweepRad = 0.0;
    double feed = 0.0;
};

// Move locked to the spindle angle (threading, rigid tapping): the axes advance `leadMmPerRev`
// along the path per spindle revolution, from the spindle angle `startAngleDeg`.
struct SpindleSyncedMove {
    Pose target;
    double leadMmPerRev = 0.0;
    double startAngleDeg = 0.0;
    // Variable pitch (Fagor G34): the lead grows by this much per spindle revolution.
    double leadChangeMmPerRev = 0.0;
};

struct Dwell {
    double seconds = 0.0;
};

enum class SpindleDirection : uint8_t { Stopped, Clockwise, CounterClockwise };

// Spindle on/off and speed. With a surface speed (lathe G96) the speed follows the X radius,
// limited to maxRpm; speedRpm is then the speed at the current position.
struct SpindleControl {
    SpindleDirection direction = SpindleDirection::Stopped;
    double speedRpm = 0.0;
    double surfaceSpeedMPerMin = 0.0;  // 0: constant speed
    double maxRpm = 0.0;               // 0: machine limit
};

struct SpindleOrient {
    double angleDeg = 0.0;
};

struct CoolantControl {
    bool flood = false;
    bool mist = false;
};

// Effective tool geometry, table values plus the deltas of the call.
struct ToolGeometry {
    double lengthMm = 0.0;
    double radiusMm = 0.0;
    double radius2Mm = 0.0;
    // Lathe offsets (Fagor D): the vector from the holder reference to the theoretical tip along
    // X (radius) and Z, wear included, and the tip location code 0-9 (-1: not a lathe offset).
    double tipXMm = 0.0;
    double tipZMm = 0.0;
    int offsetNumber = 0;
    int locationCode = -1;
    // The cutting edge's width of a grooving or parting tool, or a drill's diameter (Fagor NOSEW
    // of the tool table); 0: none given.
    double cuttingWidthMm = 0.0;
    // The nose angle of an insert or the point angle of a drill (Fagor NOSEA); 0: none given.
    double noseAngleDeg = 0.0;
    friend bool operator==(const ToolGeometry&, const ToolGeometry&) = default;
};

struct ToolChange {
    int number = 0;
    std::string name;
    ToolGeometry geometry;
    Axis toolAxis = Axis::Z;
};

// New deltas (DL, DR, DR2) or tool axis for the tool already in the spindle.
struct ToolUpdate {
    ToolGeometry geometry;
    Axis toolAxis = Axis::Z;
};

enum class FeedMode : uint8_t { PerMinute, PerRevolution };

struct SetFeedMode {
    FeedMode mode = FeedMode::PerMinute;
};

// What a simulated machine's probe input touches during one probe move, when the interpreter
// knows the part (a TNC probing cycle's simulated workpiece, docs/probing.md): true when the
// probe, the tool tip at `tip` (the stream's coordinates, X Y Z), touches. Called in the servo
// cycle: it must neither allocate nor lock.
class ProbeSurface {
public:
    virtual ~ProbeSurface() = default;
    virtual bool touches(const Vec3& tip) const = 0;
};

// Feed move that ends when the probe touches (or, with untilRelease, stops touching: Fagor G76);
// the machine decides where it ends, so a SyncPoint follows before the program reads positions.
// `surface`: what a simulated machine's probe touches on this move; null: the machine file's
// [simulation.probe] box. A real machine ignores it.
struct ProbeMove {
    Pose target;
    double feed = 0.0;
    bool untilRelease = false;
    std::shared_ptr<const ProbeSurface> surface = nullptr;
};

// Operator: a FAGOR customisation program waits for a key (WKEY) or an input (IB).
enum class SyncReason : uint8_t { ReadPosition, ProbeResult, Inputs, Operator };

// The interpreter needs live machine data: motion must drain before it continues.
struct SyncPoint {
    SyncReason reason = SyncReason::ReadPosition;
};

enum class MessageKind : uint8_t { Info, Print, Error };

struct Message {
    MessageKind kind = MessageKind::Info;
    std::string text;
};

enum class StopKind : uint8_t { Program, Optional, End };

struct ProgramStop {
    StopKind kind = StopKind::Program;
    int mCode = -1;  // -1: no M function (TNC STOP, END PGM); else 0, 1, 2, 30 ...
};

// A miscellaneous function the interpreter does not act on itself; the machine integrator may.
struct MachineFunction {
    int number = 0;
};

// The blank for graphics and material removal (TNC BLK FORM).
struct StockBox {
    Vec3 min;
    Vec3 max;
};
struct StockCylinder {
    Axis axis = Axis::Z;
    double radiusMm = 0.0;
    double innerRadiusMm = 0.0;
    double lengthMm = 0.0;
    double distanceMm = 0.0;  // length beyond the datum on the positive side (TNC DIST)
};
// A lathe blank turned about Z from an outline (the FAGOR raw-stock profile of G66/G68/G69):
// its points in (X radius, Z), first to last, and the side its material lies on (a unit vector
// along X or Z). The graphics closes the outline towards that side: to the axis, the bar's
// outside or the bar's end.
struct StockRevolved {
    std::vector<Vec3> outline;
    Vec3 materialSide{0.0, 0.0, 0.0};
};
struct StockDefinition {
    std::variant<StockBox, StockCylinder, StockRevolved> shape;
};

// How the X axis is shown (lathe G151/G152): positions stay radii in the stream.
struct DiameterMode {
    bool xInDiameter = false;
};

// Where the axes retract when a thread (Fagor G33) is stopped: incremental distances per axis
// (lathe X as a radius); no axes = no retraction.
struct ThreadRetraction {
    Pose distance;
    AxisMask axes = 0;
};

// Operator controls a program switches off for a while (Fagor ESBLK, DSTOP, DFHOLD): blocks run
// as one in single-block mode, the stop key and the feed hold input are ignored.
struct ControlLocks {
    bool joinBlocks = false;
    bool stopDisabled = false;
    bool feedHoldDisabled = false;
};

// Contour tolerance for corner blending (TNC cycle 32, Fagor G51); 0 restores the machine default.
struct PathTolerance {
    double toleranceMm = 0.0;
};

using CommandBody =
    std::variant<RapidMove, LinearMove, ArcMove, SpindleSyncedMove, Dwell, SpindleControl,
                 SpindleOrient, CoolantControl, ToolChange, ToolUpdate, SetFeedMode, ProbeMove,
                 SyncPoint, Message, ProgramStop, MachineFunction, StockDefinition, DiameterMode,
                 PathTolerance, ThreadRetraction, ControlLocks>;

struct Command {
    SourceLocation location;
    CommandBody body;
};

// Consumer of the canonical stream.
class Sink {
public:
    virtual ~Sink() = default;
    virtual void consume(const Command& command) = 0;
};

}  // namespace kerf::canon
