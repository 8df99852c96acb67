#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "core/base/diagnostic.h"
#include "core/machine/machine_config.h"

namespace kerf::machine {

struct TextPosition {
    uint32_t line = 0;  // 1-based; 0 = unknown
    uint32_t column = 0;
};

// Where a file wrote each key: full key -> position of its value, "axes.X" -> its table.
using KeyPositions = std::map<std::string, TextPosition, std::less<>>;

// Checks every parameter's range and the rules that relate parameters: soft limits min < max,
// home inside the limits, only optional axes disabled, diameter mode only on linear lathe axes,
// tool axis an enabled linear axis, spindle min <= max, at least one axis, valid unique letters;
// with drive nodes: unique node-IDs other than the master's, a drive cycle that is a whole
// number of servo periods, heartbeat timeout above its period, a CiA 301 bit rate, identities
// that are numbers.
// Each diagnostic is placed at the first key involved that `positions` knows, in `file`.
DiagnosticList validateMachine(const MachineConfig& config, std::string_view file = {},
                               const KeyPositions& positions = {});

// A drive identity (drives.vendor_id, drives.product_code): "0x..." hexadecimal or decimal, 32
// bits.
std::optional<uint32_t> parseDriveIdentity(std::string_view text);

}  // namespace kerf::machine
