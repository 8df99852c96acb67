#pragma once

#include <cstdint>

namespace kerf::cycles {

// Unit of a cycle parameter, for dialogs and for inch conversion (lengths and feeds scale).
enum class Unit : uint8_t {
    None,
    Millimetre,     // length (inch in INCH programs)
    FeedPerMinute,  // mm/min (inch/min)
    Seconds,
    Degrees,
    Rpm,
    Percent,
    Factor,
    Count,
    Text,
};

// Keywords a feed parameter may hold instead of a number.
enum FeedKeyword : uint8_t {
    kNoKeyword = 0,
    kFeedAuto = 1,      // FAUTO: the TOOL CALL feed, taken when the definition is processed
    kFeedMax = 2,       // FMAX: rapid traverse
    kFeedPerRev = 4,    // FU<value>: feed per revolution
    kFeedPerTooth = 8,  // FZ<value>: feed per tooth (x CUT of the tool)
};

// One transfer parameter of a cycle: what the cycle dialog asks for and what the interpreter
// checks. Old-style cycles (7.1 X+10, 11.1 SCL 0.5) name a keyword instead of a Q number.
struct ParameterDescriptor {
    uint16_t q = 0;                     // Qnnn; 0 for old-style words
    const char* word = nullptr;         // old-style keyword, or nullptr
    const char* description = nullptr;  // English, marked with KERF_TR_NOOP
    Unit unit = Unit::None;
    double min = 0.0;
    double max = 0.0;
    double defaultValue = 0.0;
    uint8_t keywords = kNoKeyword;  // FeedKeyword bits allowed instead of a number
    bool predef = false;            // PREDEF (GLOBAL DEF value) allowed
    bool optional = false;          // added by a later software: may be missing, default used
    bool integer = false;           // whole numbers only
    bool toolName = false;          // a tool name in quotes (or a QS parameter) also allowed
};

}  // namespace kerf::cycles
