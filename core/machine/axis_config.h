#pragma once

#include <cstdint>
#include <string_view>

namespace kerf::machine {

enum class AxisType : uint8_t { Linear, Rotary };

// One programmed axis. Positions and their derivatives are in axis units: millimetres for linear
// axes, degrees for rotary axes (so `maxVelocityPerS` is mm/s or deg/s).
//
// Default member values are the schema defaults (core/machine/machine_schema.h reads them from a
// default-constructed AxisConfig), so they are written here and nowhere else.
struct AxisConfig {
    char letter = 'X';
    AxisType type = AxisType::Linear;
    double minLimit = -100.0;  // soft limit, machine coordinates
    double maxLimit = 100.0;
    double maxVelocityPerS = 100.0;
    double maxAccelerationPerS2 = 1000.0;
    double maxJerkPerS3 = 10000.0;
    double homePosition = 0.0;
    // Place of the axis in the reference run: groups with lower numbers are homed first (on a mill
    // the tool axis comes first so that the tool leaves the part before X and Y move).
    int homeSequence = 1;
    // Machine coordinate of the workpiece origin (the default preset); kerf run --work-offset
    // overrides it.
    double presetPosition = 0.0;
    bool optional = false;  // may be switched off in the file (a removable rotary table)
    bool enabled = true;
    bool diameterMode = false;
    // Rotary: turns without end (a C table); no soft limits, positions shown modulo 360 with M94
    // and reached the short way with M126.
    bool endless = false;  // lathe X: programmed and displayed as a diameter
    // The axis's drive on the CANopen bus (drivers/).
    int driveNode = 0;                    // node-ID; 0: none
    double driveCountsPerUnit = 10000.0;  // drive position units per mm or degree
    double followingErrorWindow = 1.0;    // mm or deg, the drive's 0x6065

    friend bool operator==(const AxisConfig&, const AxisConfig&) = default;
};

// The axis letters of ISO 841 / DIN 66025 in display order: X Y Z A B C U V W.
std::string_view axisLetters();

bool isAxisLetter(char letter);

// Position of the letter in axisLetters(), used to keep axis lists in display order.
int axisLetterRank(char letter);

// A, B and C turn about X, Y and Z; every other letter moves along a line.
AxisType defaultAxisType(char letter);

// Schema defaults for a new axis with this letter (rotary for A, B and C).
AxisConfig defaultAxis(char letter);

}  // namespace kerf::machine
