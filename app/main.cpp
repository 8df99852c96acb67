#include <cstdio>
#include <iostream>

#include <CLI/CLI.hpp>

#include "app/runner/drive_output.h"
#include "app/runner/headless_run.h"
#include "app/runner/motion_output.h"
#include "app/runner/picture_output.h"

#ifdef KERF_WITH_UI
#include "motion/runtime/machine_realtime_options.h"
#include "motion/runtime/realtime_motion_port.h"
#include "motion/runtime/work_area_check.h"
#include "motion/sim/simulated_clock.h"
#include "ui/shell/hmi_main.h"
#endif

namespace {

void addProgramOptions(CLI::App& command, kerf::app::RunOptions& options) {
    command.add_option("program", options.program, "NC program")->required();
    command.add_option("--machine", options.machine,
                       "mill, mill4, mill5, mill5h, mill5hh, lathe or a machine TOML file");
    command.add_option("--dialect", options.dialect,
                       "klartext, tnciso or fagor (default: from the file)");
    command.add_option("--tool-table", options.toolTable, "TNC tool table (.T)");
    command.add_option("--nc-root", options.ncRoot,
                       "folder the program may read and write (default: its folder)");
    command.add_flag("--block-skip", options.blockSkip, "skip blocks marked with /");
    command
        .add_option("--user-screen", options.userScreen,
                    "FAGOR: run the program as the user customisation program of this mode "
                    "(execution, edit, manual, diagnosis)")
        ->check(CLI::IsMember({"execution", "edit", "manual", "diagnosis"}));
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Kerf: CNC control for HEIDENHAIN TNC 320 and FAGOR 8035 T programs"};
    app.require_subcommand(0, 1);
    kerf::app::RunOptions checkOptions;
    CLI::App* check = app.add_subcommand("check", "check a program and print its diagnostics");
    addProgramOptions(*check, checkOptions);

    kerf::app::RunOptions runOptions;
    CLI::App* run = app.add_subcommand("run", "interpret a program without a window");
    addProgramOptions(*run, runOptions);
    run->add_option("--report", runOptions.reportFile, "write a JSON report");
    run->add_option("--trace", runOptions.traceFile, "write the canonical trace ('-' for stdout)");
    run->add_option("--state-dir", runOptions.stateDir, "folder for remanent QR parameters");
    run->add_option("--max-blocks", runOptions.maxBlocks, "stop after this many blocks");
    run->add_option("--png", runOptions.png, "write a picture of the toolpath (and stock) as PNG");
    run->add_option("--view", runOptions.view, "view of the picture: 3d, top, front, side, section")
        ->check(CLI::IsMember({"3d", "top", "front", "side", "section"}));
    run->add_option("--size", runOptions.size, "picture size WxH (default 1280x800)");
    run->add_flag("--stock", runOptions.stock, "simulate material removal (picture and report)");
    run->add_option("--drives", runOptions.drives,
                    "run through the drive chain: can-sim (CANopen master, simulated drives)");
    run->add_option("--can-trace", runOptions.canTrace, "write every CAN frame as a candump log");
    run->add_option("--max-drive-time", runOptions.maxDriveTimeS,
                    "with --drives: end the run after this many simulated seconds (default 3600)")
        ->check(CLI::PositiveNumber);
    run->add_flag("--motion", runOptions.motion,
                  "execute through planner and servo cycle in simulated time (report: motion)");
    run->add_option("--samples", runOptions.samples,
                    "with --motion: write every servo cycle's setpoints as CSV");
    run->add_option("--emergency-stop-at", runOptions.emergencyStopAtS,
                    "with --motion: press the simulated emergency-stop button at this simulated "
                    "time (s since the program started)")
        ->check(CLI::NonNegativeNumber);
    run->add_option("--work-offset", runOptions.workOffset,
                    "machine coordinates of the workpiece origin on the axes named, e.g. "
                    "Z-300 (default: the machine file's presets)");
    run->add_option(
           "--operator-input", runOptions.operatorInput,
           "the operator's inputs: IBn=value for the IB variables any FAGOR program "
           "reads (e.g. IB3=40,IB1=6.25); with --user-screen also its answers in order, "
           "e.g. F1,2.5,-3 (a key F1-F7, $FC00 or one character for WKEY, a number for IB)")
        ->allow_extra_args(false);
    run->add_option("--inject-fault", runOptions.injectFaults,
                    "NODE:KIND@SECONDS, e.g. 2:heartbeat@1.5 (repeatable; see docs/drives.md)");

#ifdef KERF_WITH_UI
    kerf::ui::HmiOptions hmi;
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
    app.add_option(
        "--machine", hmi.machine,
        "machine for the HMI: mill, mill4, mill5, mill5h, mill5hh, lathe or a TOML file");
    app.add_option("--screenshot", hmi.screenshot,
                   "save a picture of the HMI to this PNG and exit");
    std::string size;
    app.add_option("--size", size, "window size WxH for --screenshot (default 1280x800)");
    app.add_option("--nc-root", hmi.ncRoot,
                   "folder of programs and tables (default: user data folder)");
    app.add_option("--program", hmi.program, "program to open at start");
    app.add_option("--mode", hmi.mode,
                   "mode on screen: manual, handwheel, mdi, single, full, programming, testrun");
    app.add_option("--language", hmi.language, "HMI language: en, de, es, pl, pt");
    app.add_option("--layout", hmi.layout,
                   "workspace at start: program, graphics, status (program + status), positions");
    app.add_flag("--programming-station", hmi.programmingStation,
                 "no machine: edit, simulate and test-run programs only");
#endif

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }
    if (*check) return kerf::app::checkProgramCommand(checkOptions, std::cerr);
    if (*run) {
        if (runOptions.size && !kerf::app::parsePictureSize(*runOptions.size)) {
            std::cerr << "kerf: --size must be WIDTHxHEIGHT (16..8192 each)\n";
            return 2;
        }
        if (runOptions.workOffset && !kerf::app::parseWorkOffset(*runOptions.workOffset)) {
            std::cerr << "kerf: --work-offset must be axis letters with values, e.g. X10,Z-300\n";
            return 2;
        }
        if (runOptions.emergencyStopAtS && !runOptions.motion && !runOptions.samples) {
            std::cerr << "kerf: --emergency-stop-at needs --motion\n";
            return 2;
        }
        if (auto error = kerf::app::checkDriveOptions(runOptions)) {
            std::cerr << "kerf: " << *error << '\n';
            return 2;
        }
        return kerf::app::runProgramCommand(runOptions, std::cerr);
    }
#ifdef KERF_WITH_UI
    if (!size.empty() && std::sscanf(size.c_str(), "%dx%d", &hmi.width, &hmi.height) != 2) {
        std::cerr << "kerf: --size must be WIDTHxHEIGHT\n";
        return 2;
    }
    return kerf::ui::runHmi(argc, argv, hmi);
#else
    std::cerr << "kerf: built without the HMI; use 'kerf check' or 'kerf run'\n";
    return 2;
#endif
}
