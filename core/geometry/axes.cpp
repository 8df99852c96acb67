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

}  // namespace kerf
