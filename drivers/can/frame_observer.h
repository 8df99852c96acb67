#pragma once

#include <chrono>

#include "drivers/can/can_frame.h"

// Sees every frame a bus carries, at the time its transmission ended: trace writers and tests.
namespace kerf::drivers::can {

class FrameObserver {
public:
    virtual ~FrameObserver() = default;
    virtual void onFrame(std::chrono::nanoseconds time, const CanFrame& frame) noexcept = 0;
};

}  // namespace kerf::drivers::can
