#include "core/machine/axis_config.h"

namespace kerf::machine {

std::string_view axisLetters() {
    return "XYZABCUVW";
}

bool isAxisLetter(char letter) {
    return axisLetters().find(letter) != std::string_view::npos;
}

int axisLetterRank(char letter) {
    size_t index = axisLetters().find(letter);
    return index == std::string_view::npos ? static_cast<int>(axisLetters().size())
                                           : static_cast<int>(index);
}

AxisType defaultAxisType(char letter) {
    return (letter == 'A' || letter == 'B' || letter == 'C') ? AxisType::Rotary : AxisType::Linear;
}

AxisConfig defaultAxis(char letter) {
    AxisConfig axis;
    axis.letter = letter;
    axis.type = defaultAxisType(letter);
    return axis;
}

}  // namespace kerf::machine
