#pragma once

#include <cstdint>
#include <span>

namespace kerf::fagor {

// One parameter of a canned cycle G66-G89 (spec part 2 §2): its letter, the manual's format
// (digits before and after the point, signed or not; no decimals means a whole number), whether
// the block must program it and whether 0 is refused.
struct CycleParameter {
    char letter;
    uint8_t intDigits;
    uint8_t decDigits;
    bool sign;
    bool required;
    bool nonZero;
    uint32_t maxValue = 0;  // whole numbers: the largest value (0: all the digits allow)
};

struct CycleSyntax {
    int g;
    std::span<const CycleParameter> parameters;

    const CycleParameter* find(char letter) const {
        for (const CycleParameter& p : parameters) {
            if (p.letter == letter) return &p;
        }
        return nullptr;
    }
};

// The parameter table of canned cycle G<number>, or nullptr if G<number> is not a canned cycle.
const CycleSyntax* cycleSyntax(int number);

}  // namespace kerf::fagor
