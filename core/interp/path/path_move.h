#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/base/source_location.h"
#include "core/geometry/contour_element.h"

namespace kerf::interp {

// Side of the contour the tool runs on: TNC RL/RR, Fagor G41/G42.
enum class CompSide : int8_t { None = 0, Left = 1, Right = -1 };

// A programmed move as it enters the path pipeline: the contour element in workpiece coordinates
// (before tool-radius compensation), how fast, and on which side the tool runs.
struct PathMove {
    ContourElement geometry;
    bool rapid = false;
    double feed = 0.0;  // mm/min or mm/rev (modal feed, also kept for rapid moves)
    CompSide side = CompSide::None;
    SourceLocation location;
};

// A geometric problem found while building the path, tied to the block that caused it.
struct PathError {
    SourceLocation location;
    std::string code;
    std::string messageTemplate;
    std::vector<std::string> args;
};

enum class ApproachKind : uint8_t { Tangent, Normal, Circle, LineCircle };  // LT LN CT LCT

// TNC APPR/DEP and Fagor G37/G38 parameters, resolved to workpiece coordinates.
struct ApproachSpec {
    ApproachKind kind = ApproachKind::Tangent;
    Pose contourPoint;          // APPR: first contour point P_A (with its tool-axis value)
    bool moveToolAxis = false;  // APPR with a tool-axis coordinate
    Pose endPoint;              // DEP LCT: end point P_N (tool centre, no compensation)
    double length = 0.0;        // LEN
    double angleDeg = 0.0;      // CCA
    double radius = 0.0;        // R (signed for CT)
    CompSide side = CompSide::None;
    bool rapidToHelper = false;
    double feed = 0.0;
    SourceLocation location;
};

}  // namespace kerf::interp
