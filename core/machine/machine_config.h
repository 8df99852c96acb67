#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/machine/axis_config.h"

namespace kerf::machine {

enum class MachineKind : uint8_t { Mill, Lathe };

struct SpindleConfig {
    int minRpm = 0;
    int maxRpm = 6000;

    friend bool operator==(const SpindleConfig&, const SpindleConfig&) = default;
};

// The machine configuration. Every field except `axes[i].letter` is a parameter of the schema in
// core/machine/machine_schema.h, which loads, checks and writes it; the default member values are
// the schema defaults. New sections (drives, ...) become new member structs plus schema entries.
struct MachineConfig {
    std::string name = "unnamed machine";
    MachineKind kind = MachineKind::Mill;
    std::vector<AxisConfig> axes;  // in display order X Y Z A B C U V W, each letter once
    char toolAxis = 'Z';
    double rapidVelocityMmPerS = 250.0;
    double maxFeedMmPerS = 100.0;
    SpindleConfig spindle;
    double servoPeriodMs = 1.0;
    double pathToleranceMm = 0.01;  // default corner-blending tolerance

    // The axis with this letter (enabled or not), or nullptr.
    const AxisConfig* axis(char letter) const;
    AxisConfig* axis(char letter);

    // Letters of the enabled axes in display order, e.g. "XZ" for the built-in lathe.
    std::string enabledAxisLetters() const;

    friend bool operator==(const MachineConfig&, const MachineConfig&) = default;
};

// Puts the axes into display order (X Y Z A B C U V W).
void sortAxes(MachineConfig& config);

}  // namespace kerf::machine
