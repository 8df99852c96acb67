#pragma once

#include <functional>
#include <memory>
#include <string>

#include "core/machine/machine_config.h"
#include "core/task/machining_clock.h"
#include "core/task/motion_port.h"
#include "core/task/move_check.h"

namespace kerf::ui {

struct HmiOptions {
    std::string machine = "mill";  // built-in name or TOML file
    std::string screenshot;        // if set: save a picture of the window there and exit
    int width = 1280;
    int height = 800;
    std::string ncRoot;   // empty: <user data folder>/nc_prog
    std::string program;  // opened at start
    std::string
        mode;  // screen at start: manual, handwheel, mdi, single, full, programming, testrun
    std::string language;             // en, pt, pl; empty: the system's
    std::string layout;               // program, graphics, status, positions; empty: the mode's
    bool programmingStation = false;  // no machine: Programming and Test run only
    // Connects the machine (app/ decides: simulated or real drives); not called on a
    // programming station. Empty: no program run or manual operation.
    std::function<std::unique_ptr<task::MotionPort>(const machine::MachineConfig&)> connectMachine;
    // Times the test run (app/ wires motion's simulated clock); also on a programming station.
    task::MachiningClockFactory machiningClock;
    // The machine's check of a program's moves (soft limits, planner rules) for a workpiece
    // origin in machine coordinates: the test run checks with it (also on a programming
    // station). Empty: the test run does not check the work area.
    std::function<std::unique_ptr<task::MoveCheck>(const machine::MachineConfig&,
                                                   const Pose& originInMachine)>
        checkMoves;
};

// Starts the operator panel and runs the Qt event loop; returns the process exit code.
int runHmi(int argc, char** argv, const HmiOptions& options);

}  // namespace kerf::ui
