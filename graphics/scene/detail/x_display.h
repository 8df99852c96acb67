#pragma once

namespace kerf::graphics::detail {

// True when the X display named by DISPLAY can be opened.
bool canOpenXDisplay();

}  // namespace kerf::graphics::detail
