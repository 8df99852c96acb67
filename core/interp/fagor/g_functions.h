#pragma once

#include <cstdint>

namespace kerf::fagor {

// Sets of G functions of which a block may contain only one (spec part 1 §5.1).
enum class GGroup : uint8_t {
    None,
    Motion,        // G00 G01 G02 G03 G33 G34 (G75 G76 are one-shot: see g_rules.cpp)
    ArcForm,       // G08 G09
    Plane,         // G16 G17 G18 G19
    Units,         // G70 G71
    Distance,      // G90 G91
    XFormat,       // G151 G152
    FeedMode,      // G32 G94 G95
    SpindleMode,   // G96 G97
    Corner,        // G05 G07 G50 G51
    Mirror,        // G10 against G11-G14 (G11, G12 and G13 combine)
    Compensation,  // G40 G41 G42
    ZeroOffset,    // G53 G54-G59 G92 G159
    CornerShape,   // G36 G38 G39: what happens at the end of the block
    WorkZone,      // G20 G21 G22
};

enum GFlag : uint16_t {
    kModal = 1u << 0,
    kAlone = 1u << 1,         // nothing else in the block but its own arguments
    kNoOtherG = 1u << 2,      // no other G function (G74)
    kNotSupported = 1u << 4,  // G46 inclined axis: not in this release
    kCombinable = 1u << 5,    // may repeat its group in one block (G11 G12 G13)
};

// One G function of the FAGOR 8035 T (spec part 1 §4, part 2 appendix A).
struct GFunction {
    uint16_t number;
    GGroup group;
    uint16_t flags;
    const char* meaning;
};

// The descriptor of G<number>, or nullptr for a number the control does not have.
const GFunction* gFunction(int number);

}  // namespace kerf::fagor
