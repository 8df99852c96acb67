#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/geometry/axes.h"

namespace kerf::interp {

// What the status tabs of the HMI show about a running program: a plain copy of the interpreter's
// state, taken between blocks. Lengths are in mm and angles in degrees whatever the program's unit;
// `inch` says in which unit the program is written (and the display shows it).
struct ProgramStatus {
    struct Cycle {
        int number = 0;
        std::string name;  // English, e.g. "POCKET MILLING"
        friend bool operator==(const Cycle&, const Cycle&) = default;
    };
    struct Tool {
        int number = -1;  // -1: no tool called
        std::string name;
        double lengthMm = 0.0;
        double radiusMm = 0.0;
        double deltaLengthMm = 0.0;  // DL: table and TOOL CALL together
        double deltaRadiusMm = 0.0;  // DR: table and TOOL CALL together
        Axis axis = Axis::Z;
        struct LatheOffset {  // Fagor tool offset D: X and Z as radius values
            int number = 0;
            double xMm = 0.0, zMm = 0.0;
            double wearXMm = 0.0, wearZMm = 0.0;  // I, K
            int location = 0;                     // F: location code of the tool tip
            friend bool operator==(const LatheOffset&, const LatheOffset&) = default;
        };
        std::optional<LatheOffset> lathe;
        friend bool operator==(const Tool&, const Tool&) = default;
    };
    struct Transformations {
        // Klartext: cycle 7 relative to the preset. Fagor: the active zero offset (with the PLC
        // offset) relative to machine zero, X as a radius; `datum` names it ("G54 G58", "G92").
        std::string datum;
        Pose datumShift{};         // mm, rotary axes in degrees
        AxisMask mirrored = 0;     // axes whose direction is reversed
        double rotationDeg = 0.0;  // about the tool axis
        std::array<double, kAxisCount> scale{1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0};
        // The tilted working plane (cycle 19, PLANE): its spatial angles and where the tool tip
        // is in its coordinates (the program's, shifts included). None while untilted.
        struct WorkingPlane {
            std::array<double, 3> spatialDeg{};  // SPA, SPB, SPC
            std::array<double, 3> positionMm{};  // X, Y, Z
            // The rotary axes' angles the plane was solved with (machine coordinates, degrees):
            // the axes in `rotaryAxes`, A B C in that order.
            AxisMask rotaryAxes = 0;
            std::array<double, 3> rotaryDeg{};
            // How the position display turns the machine's linear axes (the stream, relative to
            // the preset) into the program's coordinates in the tilted plane (the TNC's input
            // system, which its NOML and ACTL displays show): program = M * axes + origin, M row
            // by row. Differences (lag, distance to go) turn by M alone.
            std::array<double, 9> axesToProgram{1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
            std::array<double, 3> programAtAxesZeroMm{};
            // TCPM (M128, FUNCTION TCPM) turns the tables away from the solved angles: the map
            // above then takes the tool tip on the part, which the kinematics give from the
            // linear axes at the rotary axes' own angles (core/task/working_plane_position.h),
            // with the preset in machine coordinates (linear axes; rotary axes in degrees) and
            // the tool length in the spindle.
            bool tipFollowsTables = false;
            std::array<double, 3> presetInMachineMm{};
            std::array<double, 3> rotaryPresetDeg{};  // A, B, C
            double toolLengthMm = 0.0;
            friend bool operator==(const WorkingPlane&, const WorkingPlane&) = default;
        };
        std::optional<WorkingPlane> workingPlane;
        friend bool operator==(const Transformations&, const Transformations&) = default;
    };
    enum class ParameterScope : uint8_t {
        Global,    // Q; Fagor P100-P299 (and arithmetic P parameters)
        Local,     // QL; Fagor P0-P25 of a subroutine level
        Remanent,  // QR: kept across power off
        Text,      // QS strings
    };
    struct Parameter {
        std::string name;  // "Q5", "QL2", "QR10", "QS1", "P100"
        double value = 0.0;
        std::string text;  // QS only
        ParameterScope scope = ParameterScope::Global;
        int level = 0;  // Fagor local parameters: nesting level (0 = main program)
        friend bool operator==(const Parameter&, const Parameter&) = default;
    };
    // Spindle and feed as programmed (the machine's actual values are in the position display).
    struct Motion {
        double spindleRpm = 0.0;               // S of G97 / TOOL CALL
        std::optional<double> surfaceMPerMin;  // G96 active: the surface speed
        double spindleLimitRpm = 0.0;          // G92 S; 0: none
        double feedMm = 0.0;                   // F in mm (per minute or per revolution)
        bool feedPerRevolution = false;        // G95 / FU
        friend bool operator==(const Motion&, const Motion&) = default;
    };
    struct Probe {
        bool triggered = false;
        Pose position{};  // workpiece coordinates, mm
        friend bool operator==(const Probe&, const Probe&) = default;
    };

    // PGM
    std::string mainProgram;     // file name of the selected program
    std::string activeProgram;   // the called program (CALL PGM, Fagor subprogram file) or main
    std::string label;           // the LBL / subroutine being executed, empty outside one
    std::optional<Cycle> cycle;  // last defined cycle
    std::vector<int> activeM;    // modal M functions in effect, ascending (M3, M8, ...)
    uint32_t line = 0;           // line of the last executed block (1-based, 0 before start)
    int64_t blockNumber = -1;    // its block number (Klartext, FAGOR N); -1: it has none
    bool inch = false;           // program unit
    char parameterLetter = 'Q';  // Fagor: 'P'

    Motion motion;
    Tool tool;
    Transformations transformations;
    std::vector<Parameter> parameters;  // only the ones the program set, in name order
    std::optional<Probe> probe;         // last probe result

    friend bool operator==(const ProgramStatus&, const ProgramStatus&) = default;
};

}  // namespace kerf::interp
