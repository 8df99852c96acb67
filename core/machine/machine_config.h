#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/machine/axis_config.h"

namespace kerf::machine {

enum class MachineKind : uint8_t { Mill, Lathe };

// CiA 402 mode of the spindle drive: cyclic synchronous velocity or profile velocity.
enum class SpindleDriveMode : uint8_t { Csv, Pv };

struct SpindleConfig {
    int minRpm = 0;
    int maxRpm = 6000;
    int driveNode = 0;                 // CANopen node-ID of the spindle drive; 0: none
    double driveCountsPerDeg = 100.0;  // drive position units per degree
    SpindleDriveMode driveMode = SpindleDriveMode::Csv;

    friend bool operator==(const SpindleConfig&, const SpindleConfig&) = default;
};

// The CANopen drive bus (drivers/): used when the drives are CiA 402 nodes; the node of each
// drive is in its axis (axes.<L>.drive_node) and in the spindle (spindle.drive_node).
struct DrivesConfig {
    std::string interface = "can0";  // SocketCAN interface
    int bitrate = 1000000;           // bit/s
    double cyclePeriodMs = 1.0;      // SYNC period, a whole multiple of the servo period
    int heartbeatPeriodMs = 10;      // every drive's heartbeat (0x1017)
    int heartbeatTimeoutMs = 30;     // master's consumer time per drive (0x1016)
    int pdoLossCycles = 3;           // cycles without a drive's TPDO before it counts as lost
    int masterNode = 127;            // node-ID of the master's heartbeat
    std::string vendorId;            // expected 0x1018 sub 1 ("0x..."); empty: not checked
    std::string productCode;         // expected 0x1018 sub 2; empty: not checked

    friend bool operator==(const DrivesConfig&, const DrivesConfig&) = default;
};

// The bar a lathe turns when the program defines no blank (graphics' stock simulation): a cylinder
// about Z from faceZ down to faceZ - length, in workpiece coordinates. Diameter 0: no bar.
struct BarConfig {
    double diameterMm = 0.0;
    double lengthMm = 100.0;
    double faceZMm = 0.0;
    double boreDiameterMm = 0.0;  // a tube's inner diameter; 0: solid

    friend bool operator==(const BarConfig&, const BarConfig&) = default;
};

// A workpiece the simulated touch probe can touch (kerf run --motion): a box in machine
// coordinates of the tool tip (lathe X a radius); the probe touches while the tip is inside it.
// Sides left at their default are unbounded, so one bound makes a plane.
struct ProbeWorkpieceConfig {
    bool enabled = false;
    double xMinMm = -100000.0;
    double xMaxMm = 100000.0;
    double yMinMm = -100000.0;
    double yMaxMm = 100000.0;
    double zMinMm = -100000.0;
    double zMaxMm = 100000.0;

    friend bool operator==(const ProbeWorkpieceConfig&, const ProbeWorkpieceConfig&) = default;
};

// How the real blank lies compared with its programmed position (kerf run's simulated workpiece,
// the touch probe finds it): shifted in machine axes, then rotated about the tool axis through
// the blank's programmed origin (the workpiece datum). In the file: [simulation.setup] with
// shift = [x, y, z] and rotation = degrees.
struct SetupErrorConfig {
    double shiftXMm = 0.0;
    double shiftYMm = 0.0;
    double shiftZMm = 0.0;
    double rotationDeg = 0.0;

    friend bool operator==(const SetupErrorConfig&, const SetupErrorConfig&) = default;
};

// The blank the simulation clamps when a milling program defines none (a setup program that only
// probes): a box in workpiece coordinates of the machine file's preset (axes.<L>.preset), so it
// stays where it is when probing moves the preset. In the file: [simulation.blank] with
// min = [x, y, z] and max = [x, y, z]; the default is 100 x 60 x 40 with its top at Z 0 and its
// corner at the origin.
struct SimulationBlankConfig {
    double minXMm = 0.0;
    double minYMm = 0.0;
    double minZMm = -40.0;
    double maxXMm = 100.0;
    double maxYMm = 60.0;
    double maxZMm = 0.0;

    friend bool operator==(const SimulationBlankConfig&, const SimulationBlankConfig&) = default;
};

// A calibration sphere for cycle 460, clamped with the blank: its centre in the blank's
// programmed frame (workpiece coordinates of the start preset), so the setup error moves it
// too. In the file: [simulation.calibration_sphere] with centre = [x, y, z] and radius; radius
// 0: none.
struct CalibrationSphereConfig {
    double centreXMm = 0.0;
    double centreYMm = 0.0;
    double centreZMm = 0.0;
    double radiusMm = 0.0;

    friend bool operator==(const CalibrationSphereConfig&,
                           const CalibrationSphereConfig&) = default;
};

// The tool touch probe (TT) of the simulated machine: a round stylus (disc) or a square one
// (cube, sides along X and Y) whose measuring surface (the top face) is centred on `centre`, in
// machine coordinates; its sides reach down without end. Kerf has no other TT description, so
// these are also the nominal values the TT cycles start from (the TNC's centerPos); cycle 30/480
// calibrates them. In the file: [simulation.tool_probe].
enum class ToolProbeShape : uint8_t { Disc, Cube };

struct ToolProbeConfig {
    bool enabled = false;
    double centreXMm = 0.0;
    double centreYMm = 0.0;
    double centreZMm = 0.0;
    double diameterMm = 40.0;  // a cube's side
    ToolProbeShape shape = ToolProbeShape::Disc;
    double offsetToolAxisMm = 2.0;             // radius measurement: end face below the top
    double safetyDistanceMm = 5.0;             // clearance above the stylus and before each touch
    double maxPeripheralSpeedMPerMin = 100.0;  // rotating tool: cutting-edge speed
    double measureToleranceMm = 0.005;         // rotating tool: probing feed = tolerance * rpm
    double probingFeedMmPerMin = 50.0;         // stationary spindle

    friend bool operator==(const ToolProbeConfig&, const ToolProbeConfig&) = default;
};

// How a real tool differs from its tool-table entry (L + DL, R + DR as the table held them when the
// run started): the error the TT cycles find. In the file: [[simulation.tool_error]] with tool,
// length and radius.
struct ToolErrorConfig {
    int tool = 0;
    double lengthMm = 0.0;
    double radiusMm = 0.0;
    // A touch probe's stylus: its ball centre's offset from the spindle axis (X, Y) with the
    // spindle oriented at 0 degrees; it turns with the spindle (what CAL_OF1/CAL_OF2 calibrate).
    std::array<double, 2> centreOffsetMm{0.0, 0.0};

    friend bool operator==(const ToolErrorConfig&, const ToolErrorConfig&) = default;
};

// How the rotary axes are built (core/machine/table_kinematics.h computes with it). A table
// carries the workpiece, a head the spindle. "table" is one rotary table (the primary axis);
// "table-table" a secondary table mounted on the primary (tilting) one (a trunnion B or A with a C
// table on it); "head-table" a swivel head (primary, tilting) and a rotary table (secondary);
// "head-head" a head turning about the secondary axis that carries the tilting primary axis (a
// fork head: C carrying A or B). The primary axis is always the tilting one, the master axis of
// SEQ+/SEQ-. The tables' axes meet at the pivot (machine coordinates, all rotary axes at 0); the
// head's axes meet at the head pivot, given from the spindle nose (gauge line) with the head at 0.
enum class KinematicsType : uint8_t { None, Table, TableTable, HeadTable, HeadHead };

struct KinematicsConfig {
    KinematicsType type = KinematicsType::None;
    char primary = 'B';    // the tilting axis
    char secondary = 'C';  // the axis that turns the primary one or the workpiece about Z
    double pivotXMm = 0.0;
    double pivotYMm = 0.0;
    double pivotZMm = 0.0;
    double headPivotXMm = 0.0;
    double headPivotYMm = 0.0;
    double headPivotZMm = 0.0;

    friend bool operator==(const KinematicsConfig&, const KinematicsConfig&) = default;
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
    // The HMI runs programs and MDI only after a reference run (as a real control does).
    bool referenceRequired = true;
    // Code number the HMI asks before machine parameters may be edited (the TNC's user
    // parameters open with 123); viewing needs none.
    int parameterCode = 123;
    // The TNC's posAfterContPocket: the SL cycles end back at the position before the cycle
    // (PosBeforeMachining); false: at the clearance height, the tool axis only.
    bool slReturnToStart = false;
    DrivesConfig drives;
    KinematicsConfig kinematics;
    BarConfig bar;                              // lathe only
    ProbeWorkpieceConfig probeWorkpiece;        // simulation only
    SetupErrorConfig setupError;                // simulation only
    SimulationBlankConfig simulationBlank;      // simulation only
    CalibrationSphereConfig calibrationSphere;  // simulation only
    ToolProbeConfig toolProbe;                  // simulation only
    std::vector<ToolErrorConfig> toolErrors;    // simulation only; each tool at most once

    // The axis with this letter (enabled or not), or nullptr.
    const AxisConfig* axis(char letter) const;
    AxisConfig* axis(char letter);
    // The simulated error of a tool, or nullptr when it has none.
    const ToolErrorConfig* toolError(int tool) const;

    // Letters of the enabled axes in display order, e.g. "XZ" for the built-in lathe.
    std::string enabledAxisLetters() const;

    friend bool operator==(const MachineConfig&, const MachineConfig&) = default;
};

// Puts the axes into display order (X Y Z A B C U V W).
void sortAxes(MachineConfig& config);

}  // namespace kerf::machine
