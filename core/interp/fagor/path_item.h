#pragma once

#include <cstdint>

#include "core/base/source_location.h"
#include "core/geometry/contour_element.h"
#include "core/interp/path/path_move.h"

namespace kerf::fagor {

// Probe moves are feed moves that end where the probe touches (G75) or stops touching (G76).
enum class MoveKind : uint8_t { Rapid, Feed, Thread, ProbeTouch, ProbeRelease };

// G33/G34: lead per spindle revolution, start angle, lead change per revolution.
struct ThreadData {
    double lead = 0.0;
    double startAngle = 0.0;
    double leadChange = 0.0;
};

// What happens at the end of a move on the programmed contour (G36, G38, G39) or at its start
// (G37). Sizes are lengths in mm.
struct ContourRequest {
    enum class Corner : uint8_t { None, Round, Chamfer, TangentExit };
    Corner corner = Corner::None;
    double cornerSize = 0.0;
    double entryRadius = 0.0;  // G37: 0 = none
};

// A programmed move as it enters the path pipeline, in stream coordinates (tool tip, mm, X radius).
struct Move {
    ContourElement geometry;
    MoveKind kind = MoveKind::Feed;
    double feed = 0.0;
    ThreadData thread;
    interp::CompSide side = interp::CompSide::None;
    int collisionWindow = 0;  // G41 N / G42 N: blocks analysed for loops (0: off)
    ContourRequest request;
    SourceLocation location;
};

}  // namespace kerf::fagor
