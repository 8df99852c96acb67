#include "app/runner/workpiece_origin.h"

#include "app/runner/motion_output.h"

namespace kerf::app {

Pose workpieceOrigin(const machine::MachineConfig& machine,
                     const std::optional<std::string>& workOffsetOption,
                     const tables::PresetData* presetRow) {
    Pose origin;
    for (const machine::AxisConfig& axis : machine.axes) {
        const auto a = axisFromLetter(axis.letter);
        if (!a) continue;
        origin[*a] = axis.presetPosition;
        if (presetRow == nullptr) continue;
        if (const auto value = presetRow->axis(axis.letter)) origin[*a] = *value;
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
