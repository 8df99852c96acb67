#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "drivers/can/frame_observer.h"

// Keeps every frame a virtual bus delivered, with its time.
namespace kerf::drivers::test {

struct FrameRecorder final : can::FrameObserver {
    struct Entry {
        std::chrono::nanoseconds time;
        can::CanFrame frame;
    };
    std::vector<Entry> frames;

    void onFrame(std::chrono::nanoseconds time, const can::CanFrame& frame) noexcept override {
        frames.push_back({time, frame});
    }
    // Time of the last frame with this identifier at or before `before`; -1 ns when none.
    std::chrono::nanoseconds last(
        uint32_t id, std::chrono::nanoseconds before = std::chrono::nanoseconds::max()) const {
        std::chrono::nanoseconds found{-1};
        for (const Entry& e : frames) {
            if (e.frame.id == id && e.time <= before) found = e.time;
        }
        return found;
    }
    // Controlwords of the RPDO1 frames of `node`, in order.
    std::vector<uint16_t> controlwords(uint8_t node) const {
        std::vector<uint16_t> words;
        for (const Entry& e : frames) {
            if (e.frame.id == 0x200u + node) {
                words.push_back(static_cast<uint16_t>(e.frame.data[0] | e.frame.data[1] << 8));
            }
        }
        return words;
    }
};

}  // namespace kerf::drivers::test
