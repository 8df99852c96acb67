#include "core/machine/builtin_machines.h"

#include "core/machine/detail/builtin_presets.h"

namespace kerf::machine {

const std::vector<std::string_view>& builtinMachineNames() {
    static const std::vector<std::string_view> names{"mill", "lathe"};
    return names;
}

std::string_view builtinMachineToml(std::string_view name) {
    if (name == "mill") return detail::millPresetToml();
    if (name == "lathe") return detail::lathePresetToml();
    return {};
}

}  // namespace kerf::machine
