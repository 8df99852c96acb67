#include "app/command_line.h"

#include <cstdio>
#include <iostream>

#include "app/runner/drive_output.h"
#include "app/runner/headless_run.h"
#include "app/runner/motion_output.h"

namespace kerf::app {

namespace {

void addProgramOptions(CLI::App& command, RunOptions& options) {
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
    // What the run does depends on these, so the check (which runs the program) takes them too.
    command.add_option("--state-dir", options.stateDir, "folder for remanent QR parameters");
    command.add_option("--max-blocks", options.maxBlocks, "stop after this many blocks");
    command.add_option("--work-offset", options.workOffset,
                       "machine coordinates of the workpiece origin on the axes named, e.g. "
                       "Z-300 (default: the machine file's presets)");
    command
        .add_option("--preset", options.preset,
                    "the active preset: row N of PRESET.PR in the NC root, its axes and basic "
                    "rotation (SPC); --work-offset still replaces the axes it names")
        ->check(CLI::NonNegativeNumber);
    command
        .add_option(
            "--operator-input", options.operatorInput,
            "the operator's inputs: IBn=value for the IB variables any FAGOR program "
            "reads (e.g. IB3=40,IB1=6.25); with --user-screen also its answers in order, "
            "e.g. F1,2.5,-3 (a key F1-F7, $FC00 or one character for WKEY, a number for IB)")
        ->allow_extra_args(false);
}

void addRunOptions(CLI::App& run, RunOptions& options) {
    run.add_option("--report", options.reportFile, "write a JSON report");
    run.add_option("--trace", options.traceFile, "write the canonical trace ('-' for stdout)");
    run.add_option("--png", options.png, "write a picture of the toolpath (and stock) as PNG");
    run.add_option("--view", options.view, "view of the picture: 3d, top, front, side, section")
        ->check(CLI::IsMember({"3d", "top", "front", "side", "section"}));
    run.add_option("--size", options.size, "picture size WxH (default 1280x800)");
    run.add_flag("--stock", options.stock, "simulate material removal (picture and report)");
    run.add_option("--drives", options.drives,
                   "run through the drive chain: can-sim (CANopen master, simulated drives)");
    run.add_option("--can-trace", options.canTrace, "write every CAN frame as a candump log");
    run.add_option("--max-drive-time", options.maxDriveTimeS,
                   "with --drives: end the run after this many simulated seconds (default 3600)")
        ->check(CLI::PositiveNumber);
    run.add_flag("--motion", options.motion,
                 "execute through planner and servo cycle in simulated time (report: motion)");
    run.add_option("--samples", options.samples,
                   "with --motion: write every servo cycle's setpoints as CSV");
    run.add_option("--emergency-stop-at", options.emergencyStopAtS,
                   "with --motion: press the simulated emergency-stop button at this simulated "
                   "time (s since the program started)")
        ->check(CLI::NonNegativeNumber);
    run.add_option("--inject-fault", options.injectFaults,
                   "NODE:KIND@SECONDS, e.g. 2:heartbeat@1.5 (repeatable; see docs/drives.md)");
}

}  // namespace

CommandLine::CommandLine()
    : m_app("Kerf: CNC control for HEIDENHAIN TNC 320 and FAGOR 8035 T programs") {
    m_app.require_subcommand(0, 1);
    m_check = m_app.add_subcommand("check", "check a program and print its diagnostics");
    addProgramOptions(*m_check, m_checkOptions);
    m_run = m_app.add_subcommand("run", "interpret a program without a window");
    addProgramOptions(*m_run, m_runOptions);
    addRunOptions(*m_run, m_runOptions);
#ifdef KERF_WITH_UI
    m_app.add_option(
        "--machine", m_hmi.machine,
        "machine for the HMI: mill, mill4, mill5, mill5h, mill5hh, lathe or a TOML file");
    m_app.add_option("--screenshot", m_hmi.screenshot,
                     "save a picture of the HMI to this PNG and exit");
    m_app.add_option("--size", m_hmiSize, "window size WxH for --screenshot (default 1280x800)");
    m_app.add_option("--nc-root", m_hmi.ncRoot,
                     "folder of programs and tables (default: user data folder)");
    m_app.add_option("--program", m_hmi.program, "program to open at start");
    m_app.add_option("--mode", m_hmi.mode,
                     "mode on screen: manual, handwheel, mdi, single, full, programming, testrun");
    m_app.add_option("--language", m_hmi.language, "HMI language: en, de, es, pl, pt");
    m_app.add_option("--layout", m_hmi.layout,
                     "workspace at start: program, graphics, status (program + status), positions");
    m_app.add_flag("--programming-station", m_hmi.programmingStation,
                   "no machine: edit, simulate and test-run programs only");
#endif
}

std::optional<int> CommandLine::parse(int argc, char** argv) {
    try {
        m_app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = m_app.exit(e);
        return code == 0 ? 0 : 2;
    }
    return std::nullopt;
}

int CommandLine::runHeadless(PictureOutputFactory makePicture) const {
    const RunOptions& options = *m_check ? m_checkOptions : m_runOptions;
    if (options.workOffset && !parseWorkOffset(*options.workOffset)) {
        std::cerr << "kerf: --work-offset must be axis letters with values, e.g. X10,Z-300\n";
        return 2;
    }
    if (*m_check) return checkProgramCommand(m_checkOptions, std::cerr);
    if (m_runOptions.size && !parsePictureSize(*m_runOptions.size)) {
        std::cerr << "kerf: --size must be WIDTHxHEIGHT (16..8192 each)\n";
        return 2;
    }
    if (m_runOptions.emergencyStopAtS && !m_runOptions.motion && !m_runOptions.samples) {
        std::cerr << "kerf: --emergency-stop-at needs --motion\n";
        return 2;
    }
    if (auto error = checkDriveOptions(m_runOptions)) {
        std::cerr << "kerf: " << *error << '\n';
        return 2;
    }
    return runProgramCommand(m_runOptions, std::cerr, makePicture);
}

#ifdef KERF_WITH_UI
std::optional<int> CommandLine::hmiOptions(ui::HmiOptions& options) const {
    options = m_hmi;
    if (!m_hmiSize.empty() &&
        std::sscanf(m_hmiSize.c_str(), "%dx%d", &options.width, &options.height) != 2) {
        std::cerr << "kerf: --size must be WIDTHxHEIGHT\n";
        return 2;
    }
    return std::nullopt;
}
#endif

}  // namespace kerf::app
