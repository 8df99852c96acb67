// Kept apart from the VTK and Eigen code: X11's headers define macros (Success, None ...) that
// collide with Eigen's names.
#include "graphics/scene/detail/x_display.h"

#include <X11/Xlib.h>

namespace kerf::graphics::detail {

bool canOpenXDisplay() {
    ::Display* display = XOpenDisplay(nullptr);
    if (display == nullptr) return false;
    XCloseDisplay(display);
    return true;
}

}  // namespace kerf::graphics::detail
