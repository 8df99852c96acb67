#include "app/runner/workpiece_origin.h"

#include "app/runner/motion_output.h"

namespace kerf::app {

Pose workpieceOrigin(const machine::MachineConfig& machine,
                     const std::optional<std::string>& workOffsetOption) {
    Pose origin;
    for (const machine::AxisConfig& axis : machine.axes) {
        if (auto a = axisFromLetter(axis.letter)) origin[*a] = axis.presetPosition;
    }
    if (!workOffsetOption) return origin;
    const std::optional<Pose> given = parseWorkOffset(*workOffsetOption);
    if (!given) return origin;
    // The items are "<letter><value>" separated by commas: the letters say which axes it names.
    const std::string& text = *workOffsetOption;
    for (size_t at = 0; at < text.size(); at = text.find(',', at) + 1) {
        if (auto a = axisFromLetter(text[at])) origin[*a] = (*given)[*a];
        if (text.find(',', at) == std::string::npos) break;
    }
    return origin;
}

}  // namespace kerf::app
