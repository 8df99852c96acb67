#pragma once

#include <cstdint>

#include "core/base/source_location.h"
#include "motion/path/path_geometry.h"
#include "motion/profile/jerk_profile.h"

// What the planner sends the servo cycle: fixed-size values in an SPSC ring, in program order.
// Written by the planner thread, read by the RT thread.
namespace kerf::motion {

// How an element's programmed velocity is formed in the servo cycle.
enum class FeedKind : uint8_t {
    Rapid,          // feed = rapid velocity (mm/s), times the rapid override
    PerMinute,      // feed in mm/s, times the feed override
    PerRevolution,  // feed in mm/rev, times the spindle speed and the feed override
    SpindleSynced,  // feed = |lead| mm/rev times the programmed spindle speed; overrides locked
};

// One piece of path. The path parameter s is global and increases along the program.
struct PathElement {
    PathGeometry geometry;
    double sStart = 0.0;
    double capVelocity = 0.0;  // machine limits (axes, curvature, tolerance), never scaled
    double feed = 0.0;         // see FeedKind
    FeedKind feedKind = FeedKind::PerMinute;
    Limits limits;  // tangential acceleration and jerk on this element
    // The next point at or after the end of this element that must be met with a = 0 and a
    // velocity no higher than min(bindVelocity, programmed velocity of the element after it).
    double bindS = 0.0;
    double bindVelocity = 0.0;
    double bindFeed = 0.0;
    FeedKind bindFeedKind = FeedKind::PerMinute;
    // Spindle-synchronised elements: spindle degrees per unit s (signed).
    double spindleDegPerUnit = 0.0;
    bool feedMove = false;  // counts for feed time (not rapid)
    bool probe = false;     // stop when the probe triggers
    bool blockEnd = false;  // the programmed block ends at the end of this element
    // Blocks a program joined (Fagor ESBLK .. DSBLK) share a group number and run as one block
    // in single block; 0: not joined.
    uint32_t joinedGroup = 0;
    uint32_t moveIndex = 0;  // programmed move it belongs to (a blend: the move after it)
    // First programmed move it stands for when it replaces several (a curve fitted to a
    // polyline, moveIndex being the last); 0: moveIndex alone.
    uint32_t firstMoveIndex = 0;
    SourceLocation source;

    double sEnd() const noexcept { return sStart + geometry.length; }
};

enum class ActionKind : uint8_t {
    Dwell,           // value = seconds
    ProgramStop,     // number = canon::StopKind (0 program, 1 optional, 2 end)
    ToolChange,      // value = tool length, number = tool axis index, aux = tool number
    Spindle,         // number = direction (0 stop, 1 cw, -1 ccw), value = rpm,
                     // aux = surface speed m/min (0: constant speed), value2 = max rpm
    SpindleOrient,   // value = angle (deg): stop the spindle at this angle
    SyncStart,       // value = start angle (deg): stop and orient the spindle, then lock it
    SyncEnd,         // release the spindle lock; back to the programmed speed
    SyncPoint,       // number = canon::SyncReason: report the position and wait for the task
    Coolant,         // number = bit 0 flood, bit 1 mist
    MachineFunction  // number = M function: reported, no stop beyond the exact stop before it
};

struct Action {
    ActionKind kind = ActionKind::Dwell;
    double value = 0.0;
    double value2 = 0.0;
    double aux = 0.0;
    int32_t number = 0;
    uint32_t joinedGroup = 0;  // as PathElement::joinedGroup
};

struct MotionItem {
    enum class Kind : uint8_t { Element, Action };
    Kind kind = Kind::Element;
    uint64_t sequence = 0;  // echoed in events and status
    PathElement element;
    Action action;
    SourceLocation source;
};

}  // namespace kerf::motion
