#pragma once

#include <functional>
#include <string>

#include "core/canon/commands.h"

namespace kerf::canon {

// Formatting of one canonical command as a trace line (without the newline). The text is stable:
// lengths with 4 decimals, feeds and speeds with 3, never "-0"; only the machine's axes are
// printed.
//
//   12:1 N11 LINE X10.0000 Y0.0000 Z-2.0000 F200.000
//   7:1 N6 TOOL T5 "MILL" L=50.0000 R=5.0000 R2=0.0000 AXIS Z
//   SUB.H:3:1 N3 ARC X20.0000 Y10.0000 Z0.0000 CENTER X10.0000 Y10.0000 PLANE XY SWEEP 90.0000
//   F200.000
struct TraceFormat {
    AxisMask axes = kXyzMask;
    // Display name of a source file; file 0 (the main program) is not named.
    std::function<std::string(uint32_t fileId)> fileName;
};

void appendCommand(std::string& out, const Command& command, const TraceFormat& format);

}  // namespace kerf::canon
