#pragma once

#include <span>

#include "core/cycles/cycle_descriptor.h"

// Machining cycles of older TNCs that shop programs still contain although the TNC 320 manuals
// no longer list them: 1 PECKING, 2 TAPPING, 3 SLOT MILLING, 4 POCKET MILLING, 5 CIRCULAR POCKET
// and 17 RIGID TAPPING. They are written as old-style sub-blocks ("CYCL DEF 1.2 DEPTH -20") and run
// from where the tool stands, at set-up clearance above the surface; each does the work of the
// modern cycle it became (docs/cycles.md, "Cycles of older TNCs"). Not offered in the cycle menus:
// only for running old programs.
namespace kerf::cycles {

// What a word of a sub-block is: its value (the first word that is neither F nor DR, whatever
// its keyword, which depends on the control's language: ABST, SET UP, DIST ...), the feed F
// or the direction DR+ / DR-; Axis stores 1 when the value's keyword is the working plane's
// secondary axis (cycle 3's "3.4 Y+80": a slot along Y), else 0.
enum class LegacyWordKind : uint8_t { Value, Feed, Direction, Axis };

// Where a word of sub-block `subBlock` goes: the value with this id (the 1-based index of its
// parameter in the descriptor).
struct LegacyWordSlot {
    int subBlock = 0;
    LegacyWordKind kind = LegacyWordKind::Value;
    uint16_t id = 0;
};

struct LegacyCycle {
    const CycleDescriptor* descriptor = nullptr;
    std::span<const LegacyWordSlot> slots;
    int subBlocks = 0;  // the last sub-block number
};

// The legacy machining cycle `number`, or nullptr.
const LegacyCycle* findLegacyCycle(int number);

}  // namespace kerf::cycles
