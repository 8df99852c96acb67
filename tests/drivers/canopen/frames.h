#pragma once

#include <string>
#include <vector>

#include "drivers/can/candump_log.h"
#include "drivers/canopen/frame_outbox.h"

// Frames written the candump way ("602#2B17100064000000") so tests state bytes as CiA 301 gives
// them.
namespace kerf::drivers::test {

inline can::CanFrame frame(const std::string& text) {
    can::CandumpRecord r;
    if (!can::parseCandumpLine("(0000000000.000000) can0 " + text, r)) return {};
    return r.frame;
}

inline std::string text(const can::CanFrame& f) {
    char line[can::kCandumpLineMax + 1];
    size_t n = can::formatCandumpLine(line, {}, "can0", f);
    return std::string(line, n).substr(25);  // after "(0000000000.000000) can0 "
}

// Takes every frame out of an outbox, as text.
inline std::vector<std::string> drain(canopen::FrameOutbox& out) {
    std::vector<std::string> frames;
    while (!out.empty()) {
        frames.push_back(text(out.front()));
        out.pop();
    }
    return frames;
}

}  // namespace kerf::drivers::test
