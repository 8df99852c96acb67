#pragma once

#include <memory>
#include <string>

#include "core/base/expected.h"

namespace kerf::graphics {

// An X display for VTK, which on Debian renders only through X even off screen. With DISPLAY set
// nothing is started. Otherwise Xvfb is started on a free display number (Xvfb picks it and
// reports it through -displayfd), DISPLAY is set for this process, and the server is stopped and
// DISPLAY restored when the object goes away. Call from the main thread before rendering.
class VirtualDisplay {
public:
    // The display to use, or a diagnostic when none is set and Xvfb is missing or fails.
    static Expected<std::shared_ptr<VirtualDisplay>> ensure();
    ~VirtualDisplay();
    VirtualDisplay(const VirtualDisplay&) = delete;
    VirtualDisplay& operator=(const VirtualDisplay&) = delete;

    const std::string& display() const { return m_display; }
    bool started() const { return m_pid > 0; }

private:
    VirtualDisplay() = default;
    std::string m_display;
    int m_pid = -1;
};

// Where Xvfb is (searched in PATH), or empty.
std::string findXvfb();

}  // namespace kerf::graphics
