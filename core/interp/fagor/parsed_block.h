#pragma once

#include <cstdint>
#include <string_view>

#include "core/interp/fagor/iso_block.h"

namespace kerf::fagor {

// One block after reading: header (skip marks, label), body and end (repetition count).
struct ParsedBlock {
    enum class Kind : uint8_t {
        Nothing,    // label only
        Comment,    // the block starts with ';'
        Header,     // "%comment,attributes," transfer header (first line)
        Iso,        // ISO words in `iso`
        HighLevel,  // "( ... )": the text inside the parentheses
    };
    Kind kind = Kind::Nothing;
    uint8_t skipMarks = 0;    // bit 0: '/' or '/1', bit 1: '/2', bit 2: '/3'
    int64_t label = -1;       // N before the body
    int32_t repetition = -1;  // N after the body (0-9999)
    uint16_t repetitionOffset = 0;
    bool endOfFile = false;   // an end-of-file character ended the text in this block
    uint16_t outOfOrder = 0;  // offset of a word written out of the G X F S T D M order (0: none)
    IsoBlock iso;
    std::string_view highLevel;  // without the parentheses
    size_t highLevelOffset = 0;  // where `highLevel` starts in the block text
};

}  // namespace kerf::fagor
