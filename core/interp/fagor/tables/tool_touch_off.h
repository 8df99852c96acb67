#pragma once

#include "core/geometry/axes.h"
#include "core/interp/fagor/tables/tool_offset_table.h"

namespace kerf::fagor {

// Tool calibration by touching the part (a lathe's manual mode): the operator touches a face or
// a diameter of known position with the tool and enters that position. Millimetres, X as a
// radius, part coordinates.
struct TouchOff {
    int offset = 1;         // the offset D to calibrate, 1-255
    Axis axis = Axis::X;    // X or Z
    double shownMm = 0.0;   // where the display puts the tip now
    double knownMm = 0.0;   // where the tip really touches: the known radius or face Z
    double activeMm = 0.0;  // length plus wear, on `axis`, of the offset the tip is shown with
};

// Sets the length of offset D on the axis so that the tip of the tool, whose holder reference
// stands at shown - active, is at the known position: length = known - (shown - active) - wear
// (the wear is kept). False, with the table unchanged, for D0, D out of range, an axis other
// than X or Z, or a non-finite value.
bool touchOff(ToolOffsetTable& table, const TouchOff& touch);

}  // namespace kerf::fagor
