#include "core/machine/builtin_machines.h"

#include "core/machine/detail/builtin_presets.h"

namespace kerf::machine {

const std::vector<std::string_view>& builtinMachineNames() {
    static const std::vector<std::string_view> names{"mill",   "mill4",   "mill5",
                                                     "mill5h", "mill5hh", "lathe"};
    return names;
}

std::string_view builtinMachineToml(std::string_view name) {
    if (name == "mill") return detail::millPresetToml();
    if (name == "mill4") return detail::mill4PresetToml();
    if (name == "mill5") return detail::mill5PresetToml();
    if (name == "mill5h") return detail::mill5hPresetToml();
    if (name == "mill5hh") return detail::mill5hhPresetToml();
    if (name == "lathe") return detail::lathePresetToml();
    return {};
}

}  // namespace kerf::machine
