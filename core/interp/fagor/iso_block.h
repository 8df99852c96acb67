#pragma once

#include <array>
#include <cstdint>

#include "core/geometry/axes.h"

namespace kerf::fagor {

// A numeric word of an ISO block after parameter substitution.
struct WordValue {
    bool present = false;
    bool hasValue = false;   // "X" alone has none (it means X0, or an axis selector)
    bool parameter = false;  // the value came from a parameter (XP3)
    double value = 0.0;
    uint16_t offset = 0;  // byte offset of the letter in the block text
};

struct MWord {
    WordValue number;
    WordValue s;  // M19 S<angle>
};

// The parameters of a canned cycle block (G66-G89), by letter.
struct CycleWords {
    int16_t g = -1;  // the cycle, -1: none
    uint16_t offset = 0;
    std::array<WordValue, 26> letters{};

    const WordValue& operator[](char letter) const {
        return letters[static_cast<size_t>(letter - 'A')];
    }
    WordValue& operator[](char letter) { return letters[static_cast<size_t>(letter - 'A')]; }
    bool has(char letter) const { return (*this)[letter].present; }
    double value(char letter, double fallback) const {
        const WordValue& w = (*this)[letter];
        return w.present ? w.value : fallback;
    }
};

// An ISO block with its words sorted out. Coordinates are as programmed (units and diameter not
// applied yet): their meaning depends on the block's G functions (G92 presets, G72 factors, G20
// limits ...), which the interpreter knows.
struct IsoBlock {
    static constexpr int kMaxG = 12;
    static constexpr int kMaxM = 7;

    std::array<WordValue, kMaxG> g{};
    uint8_t gCount = 0;
    std::array<WordValue, kAxisCount> axes{};  // by Axis
    AxisMask axisMask = 0;
    std::array<Axis, kAxisCount> axisOrder{};  // the order written (G16, G74, REPOS order)
    uint8_t axisCount = 0;
    WordValue i1, i2, j, k;   // centre, intermediate point, G93 origin, G34 pitch change
    WordValue r;              // arc radius or polar radius
    WordValue q;              // polar angle, angle + coordinate, thread start angle
    WordValue l;              // thread pitch
    WordValue cornerR;        // R after G36, G37, G38, G39
    WordValue gK;             // K after G04, G20, G21, G22
    WordValue gN;             // N after G41, G42, G159
    WordValue a51, e51, b51;  // G51 A E B
    WordValue f, s, t, d;
    std::array<MWord, kMaxM> m{};
    uint8_t mCount = 0;
    CycleWords cycle;  // the words after a canned cycle's G are its parameters

    bool hasG(int number) const {
        for (uint8_t i = 0; i < gCount; ++i) {
            if (g[i].value == number) return true;
        }
        return false;
    }
    bool has(Axis axis) const { return (axisMask & axisBit(axis)) != 0; }
    // Anything besides the G functions and their own arguments.
    bool hasOtherWords() const {
        return axisMask != 0 || i1.present || j.present || k.present || r.present || q.present ||
               l.present || f.present || s.present || t.present || d.present || mCount != 0 ||
               cycle.g >= 0;
    }
    void clear() {
        gCount = 0;
        axisMask = 0;
        axisCount = 0;
        i1 = i2 = j = k = r = q = l = cornerR = gK = gN = a51 = e51 = b51 = f = s = t = d =
            WordValue{};
        mCount = 0;
        if (cycle.g >= 0) cycle = CycleWords{};
    }
};

}  // namespace kerf::fagor
