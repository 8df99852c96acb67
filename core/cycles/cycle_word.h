#pragma once

#include <optional>
#include <string>
#include <vector>

namespace kerf::cycles {

// A word of an old-style cycle sub-block ("X+60", "IROT+45", "SCL 0.75", "#5", "HSC-MODE:1",
// "DWELL 1.5", a bare "X" of cycle 8), with its value evaluated. Keys are upper case.
struct CycleWord {
    std::string key;
    bool incremental = false;  // written with a leading I (IX, IROT)
    std::optional<double> value;
};

using CycleWords = std::vector<CycleWord>;

}  // namespace kerf::cycles
