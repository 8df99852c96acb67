#include "core/geometry/axes.h"

namespace kerf {

namespace {
constexpr char kLetters[kAxisCount] = {'X', 'Y', 'Z', 'A', 'B', 'C', 'U', 'V', 'W'};
}

char axisLetter(Axis axis) {
    return kLetters[axisIndex(axis)];
}

AxisMask axisMaskOf(std::string_view letters) {
    AxisMask mask = 0;
    for (char letter : letters) {
        if (auto axis = axisFromLetter(letter)) mask = static_cast<AxisMask>(mask | axisBit(*axis));
    }
    return mask;
}

std::optional<Axis> axisFromLetter(char letter) {
    switch (letter) {
        case 'X':
        case 'x':
            return Axis::X;
        case 'Y':
        case 'y':
            return Axis::Y;
        case 'Z':
        case 'z':
            return Axis::Z;
        case 'A':
        case 'a':
            return Axis::A;
        case 'B':
        case 'b':
            return Axis::B;
        case 'C':
        case 'c':
            return Axis::C;
        case 'U':
        case 'u':
            return Axis::U;
        case 'V':
        case 'v':
            return Axis::V;
        case 'W':
        case 'w':
            return Axis::W;
        default:
            return std::nullopt;
    }
}

}  // namespace kerf
