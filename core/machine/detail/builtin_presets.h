#pragma once

#include <string_view>

namespace kerf::machine::detail {

// Texts of core/machine/presets/*.toml; defined in a file generated from builtin_presets.cpp.in.
std::string_view millPresetToml();
std::string_view mill4PresetToml();
std::string_view mill5PresetToml();
std::string_view mill5hPresetToml();
std::string_view mill5hhPresetToml();
std::string_view lathePresetToml();

}  // namespace kerf::machine::detail
