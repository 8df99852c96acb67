// kerf-gui: the operator panel and `kerf run --png`, with Qt and VTK linked. `kerf` starts it
// with its own arguments when they need them (app/main.cpp); it accepts every `kerf` command.
#include <iostream>

#include "app/command_line.h"
#include "app/runner/png_picture.h"

#ifdef KERF_WITH_UI
#include "motion/runtime/machine_realtime_options.h"
#include "motion/runtime/realtime_motion_port.h"
#include "motion/runtime/work_area_check.h"
#include "motion/sim/simulated_clock.h"
#include "ui/shell/hmi_main.h"
#endif

int main(int argc, char** argv) {
    kerf::app::CommandLine commandLine;
    if (auto exitCode = commandLine.parse(argc, argv)) return *exitCode;
    if (commandLine.headless()) return commandLine.runHeadless(&kerf::app::makePngPicture);
#ifdef KERF_WITH_UI
    kerf::ui::HmiOptions hmi;
    if (auto exitCode = commandLine.hmiOptions(hmi)) return *exitCode;
    // The HMI runs programs on the simulated drives in real time, from the machine file's
    // workpiece origin, with its simulated probe box.
    hmi.connectMachine = [](const kerf::machine::MachineConfig& config) {
        return std::unique_ptr<kerf::task::MotionPort>(
            std::make_unique<kerf::motion::RealtimeMotionPort>(
                config, kerf::motion::machineRealtimeOptions(config)));
    };
    hmi.machiningClock = kerf::motion::makeSimulatedClock;
    // The test run checks the work area with the check of Program run's planner.
    hmi.checkMoves = &kerf::motion::makeWorkAreaCheck;
    return kerf::ui::runHmi(argc, argv, hmi);
#else
    std::cerr << "kerf: built without the HMI; use 'kerf check' or 'kerf run'\n";
    return 2;
#endif
}
