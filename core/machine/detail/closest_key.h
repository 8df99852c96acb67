#pragma once

#include <string_view>
#include <vector>

namespace kerf::machine::detail {

// The candidate closest to a mistyped key, when it is only a typo or two away; empty otherwise.
std::string_view closestKey(std::string_view typed,
                            const std::vector<std::string_view>& candidates);

}  // namespace kerf::machine::detail
