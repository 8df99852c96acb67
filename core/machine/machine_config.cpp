#include "core/machine/machine_config.h"

#include <algorithm>
#include <utility>

namespace kerf::machine {

const AxisConfig* MachineConfig::axis(char letter) const {
    auto it = std::find_if(axes.begin(), axes.end(),
                           [letter](const AxisConfig& a) { return a.letter == letter; });
    return it == axes.end() ? nullptr : &*it;
}

AxisConfig* MachineConfig::axis(char letter) {
    return const_cast<AxisConfig*>(std::as_const(*this).axis(letter));
}

const ToolErrorConfig* MachineConfig::toolError(int tool) const {
    auto it = std::find_if(toolErrors.begin(), toolErrors.end(),
                           [tool](const ToolErrorConfig& e) { return e.tool == tool; });
    return it == toolErrors.end() ? nullptr : &*it;
}

std::string MachineConfig::enabledAxisLetters() const {
    std::string letters;
    for (const AxisConfig& a : axes) {
        if (a.enabled) letters += a.letter;
    }
    return letters;
}

void sortAxes(MachineConfig& config) {
    std::stable_sort(config.axes.begin(), config.axes.end(),
                     [](const AxisConfig& a, const AxisConfig& b) {
                         return axisLetterRank(a.letter) < axisLetterRank(b.letter);
                     });
}

}  // namespace kerf::machine
