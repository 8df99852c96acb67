#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>

#include "app/runner/headless_run.h"

#ifdef KERF_WITH_UI
#include "ui/shell/hmi_main.h"
#endif

namespace {

void addProgramOptions(CLI::App& command, kerf::app::RunOptions& options) {
    command.add_option("program", options.program, "NC program")->required();
    command.add_option("--machine", options.machine, "mill, lathe or a machine TOML file");
    command.add_option("--dialect", options.dialect, "klartext, tnciso or fagor (default: from the file)");
    command.add_option("--tool-table", options.toolTable, "TNC tool table (.T)");
    command.add_option("--nc-root", options.ncRoot, "folder the program may read and write (default: its folder)");
    command.add_flag("--block-skip", options.blockSkip, "skip blocks marked with /");
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

#ifdef KERF_WITH_UI
    kerf::ui::HmiOptions hmi;
    app.add_option("--machine", hmi.machine, "machine for the HMI: mill, lathe or a TOML file");
    app.add_option("--screenshot", hmi.screenshot, "save a picture of the HMI to this PNG and exit");
    std::string size;
    app.add_option("--size", size, "window size WxH for --screenshot (default 1280x800)");
#endif

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }
    if (*check) return kerf::app::checkProgramCommand(checkOptions, std::cerr);
    if (*run) return kerf::app::runProgramCommand(runOptions, std::cerr);
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
