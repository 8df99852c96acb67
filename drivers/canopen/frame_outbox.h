#pragma once

#include "drivers/can/can_frame.h"
#include "drivers/can/fixed_queue.h"

// Frames a protocol layer wants sent; the cycle drains it into the CAN channel.
namespace kerf::drivers::canopen {

using FrameOutbox = can::FixedQueue<can::CanFrame, 256>;

}  // namespace kerf::drivers::canopen
