// How the session tests wait: the HMI services its session from a timer; a test does it by hand
// until a condition holds or a real-time limit passes.
#pragma once

#include <chrono>
#include <functional>
#include <thread>

#include "ui/session/machine_session.h"

namespace kerf::ui::test {

// Services `session` every 2 ms until `done` holds (true) or `limit` has passed (false).
inline bool serviceUntil(MachineSession& session, const std::function<bool()>& done,
                         std::chrono::milliseconds limit) {
    const auto deadline = std::chrono::steady_clock::now() + limit;
    while (std::chrono::steady_clock::now() < deadline) {
        session.service();
        if (done()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    return false;
}

}  // namespace kerf::ui::test
