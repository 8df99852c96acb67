#pragma once

#include <QString>
#include <vector>

#include "core/cycles/cycle_descriptor.h"

namespace kerf::ui {

// How an old-style sub-block writes a word: "X+60", "SCL 0.75", "T0.05", "DEPTH = -20",
// "HSC-MODE:1", or the bare text of cycle 8 ("X Y").
enum class WordStyle { Signed, Spaced, Joined, Equals, Colon, Bare };

// One input row of the cycle dialog. New-style cycles have one per Q parameter; old-style
// cycles one per word, axis words spread over the axes ("X" of cycle 7 gives X, Y and Z).
struct CycleField {
    const cycles::ParameterDescriptor* parameter = nullptr;
    QString label;     // "Q200", "X", "ROT", "CCY"
    QString word;      // old-style keyword written in the block; empty for Q parameters
    int subBlock = 0;  // old-style: sub-block n of "CYCL DEF c.n" (fields of one n share it)
    WordStyle style = WordStyle::Signed;
    bool optional = false;  // old-style words that may stay empty
};

std::vector<CycleField> cycleFields(const cycles::CycleDescriptor& cycle);

}  // namespace kerf::ui
