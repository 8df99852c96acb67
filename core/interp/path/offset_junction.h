#pragma once

#include <optional>

#include "core/geometry/contour_element.h"

namespace kerf::interp {

// Where the tool-centre paths of two compensated contour elements meet.
struct OffsetJunction {
    ContourElement before;                     // tool path of the earlier element, end resolved
    std::optional<ContourElement> transition;  // arc around a contour corner between them
    ContourElement after;                      // tool path of the later element, start resolved
};

// Why two adjacent elements cannot be joined: the offset swallows one of them (or leaves nothing
// of an arc). `swallowedLater` names the later element, otherwise the earlier one.
struct JunctionFailure {
    bool swallowedLater = true;
    const char* messageTemplate = "";
};

struct JunctionOutcome {
    std::optional<OffsetJunction> junction;
    JunctionFailure failure;
};

// The TNC/Fagor corner rules for adjacent elements a -> b: an outside corner gets an arc around
// the corner point, an inside corner ends both offsets at their intersection. `beforeTool` is the
// tool path of a with its start already fixed. `activation`: a is the block that switches
// compensation on, which ends perpendicular to the start of b.
JunctionOutcome joinAdjacent(const ContourElement& beforeTool, const ContourElement& a,
                             const ContourElement& b, double offset, bool activation);

// M120: the elements between a and b are left out. The offsets of a and b meet at the
// intersection of their carriers (straight on when they lie on one line), or else by an arc around
// the end of a or the start of b, the tool touching that contour point. Empty when none of these
// joins a forward part of a to a part of b.
std::optional<OffsetJunction> bridgeOffsets(const ContourElement& beforeTool,
                                            const ContourElement& a, const ContourElement& b,
                                            double offset);

}  // namespace kerf::interp
