#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <vector>

#include "core/geometry/axes.h"
#include "core/geometry/plane.h"
#include "core/interp/fagor/m_functions.h"
#include "core/interp/fagor/user_screen.h"
#include "core/machine/machine_config.h"

namespace kerf::fagor {

// The machine parameters of the FAGOR 8035 T that change how programs are interpreted, with the
// defaults Kerf uses (docs/fagor.md, "Machine parameters"), and the files of the run.
struct FagorSettings {
    const machine::MachineConfig* machine = nullptr;  // required
    std::filesystem::path ncRoot;  // EXEC, OPEN, CALL into other programs stay inside it
    std::vector<std::filesystem::path> runOutputs;  // files the run writes: never read
    std::filesystem::path toolOffsetFile;           // empty: no table (every offset is zero)
    std::filesystem::path zeroOffsetFile;           // empty: no table
    std::filesystem::path toolFile;                 // empty: tool n uses offset n
    bool writeFiles =
        true;  // false (a dry run): OPEN/WRITE and the tables are admitted, not written
    uint8_t blockSkip = 0;  // PLC marks BLKSKIP1-3 (bit 0: '/' and '/1')
    // The machine's workpiece origin (machine file presets, kerf run --work-offset), machine
    // coordinates: the zero offset in effect when the table selects none (like G92).
    Pose presetInMachine{};
    // Where the tool stands when the program starts, machine coordinates (the panel knows it;
    // kerf run starts at the program's origin): the first move is drawn from there.
    std::optional<Pose> startInMachine;
    // The spindle speed S the program starts with: an MDI block keeps the S the machine was left
    // with (0: none programmed yet).
    double startSpindleRpm = 0.0;
    // The user channel (spec part 2 §6.8): with a screen the program runs as the user
    // customisation program of its mode, drawing on it and reading the operator's keys and input.
    UserScreen* userScreen = nullptr;
    // What IB0-IB25 hold for an ordinary program (the user screen's last inputs).
    std::array<double, UserScreen::kInputs> inputValues{};

    // General machine parameters.
    bool imoveLinear = false;                   // IMOVE: G01 (true) or G00 at reset
    Plane iplane = Plane::ZX;                   // IPLANE: G18 on a lathe
    bool inches = false;                        // INCHES
    bool incremental = false;                   // ISYSTEM: G91 at reset
    bool feedPerRevolution = false;             // IFEED: G95 at reset
    bool roundCorner = false;                   // ICORNER: G05 (true) or G07 at reset
    std::optional<bool> diameter;               // DFORMAT of X: G151; default: the machine's X axis
    int compMode = 0;                           // COMPMODE 0, 1, 2: joins of compensated paths
    bool compensationInAllPlanes = false;       // PLACOMP
    bool polarOriginFollowsArcs = false;        // PORGMOVE
    int m19Type = 1;                            // M19TYPE: 1 allows Q in G33/G34
    double circleToleranceMm = 0.01;            // CIRINERR
    std::array<double, 4> maxGearRpm{};         // MAXGEAR1-4; 0: the machine's maximum
    bool autoGear = false;                      // AUTOGEAR: a gear needs no M41-M44 for G96
    bool toolChangeByM06 = false;               // TOFFM06: T preselects, M06 changes
    int homingSubroutine = 0;                   // REFPSUB for G74 alone (0: none)
    std::array<int, 4> interruptSubroutines{};  // INT1SUB-INT4SUB
    std::vector<MFunctionEntry> mFunctions = defaultMFunctionTable();
    int operatingMode = 10;  // OPMODE: automatic execution
    bool probeError = true;  // PROBERR (P119): G75/G76 ending without a probe event is an error

    int maxCallNesting = 15;
};

}  // namespace kerf::fagor
