#include "core/geometry/axes.h"

namespace kerf {

namespace {
constexpr char kLetters[kAxisCount] = {'X', 'Y', 'Z', 'A', 'B', 'C', 'U', 'V', 'W'};
}

char axisLetter(Axis axis) { return kLetters[axisIndex(axis)]; }

std::optional<Axis> axisFromLetter(char letter) {
    if (letter >= 'a' && letter <= 'z') letter = static_cast<char>(letter - 'a' + 'A');
    for (int i = 0; i < kAxisCount; ++i) {
        if (kLetters[i] == letter) return static_cast<Axis>(i);
    }
    return std::nullopt;
}

}  // namespace kerf
