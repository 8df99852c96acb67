#pragma once

#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "app/runner/picture_output.h"
#include "app/runner/run_options.h"

#ifdef KERF_WITH_UI
#include "ui/shell/hmi_main.h"
#endif

namespace kerf::app {

// The command line of `kerf` and of kerf-gui, defined once: both parse, explain (--help) and
// refuse arguments alike, whichever of them ends up doing the work.
class CommandLine {
public:
    CommandLine();
    CommandLine(const CommandLine&) = delete;
    CommandLine& operator=(const CommandLine&) = delete;

    // An exit code when parsing ends the process (help printed, bad arguments).
    std::optional<int> parse(int argc, char** argv);
    // `kerf check` or `kerf run`: no window.
    bool headless() const { return *m_check || *m_run; }
    // The command needs the graphics libraries: the operator panel or a picture (run --png).
    bool needsGraphics() const { return !headless() || (*m_run && m_runOptions.png); }
    // Runs `check` or `run`; the exit code.
    int runHeadless(PictureOutputFactory makePicture) const;
#ifdef KERF_WITH_UI
    // The operator panel's options, or the exit code for a malformed --size.
    std::optional<int> hmiOptions(ui::HmiOptions& options) const;
#endif

private:
    CLI::App m_app;
    RunOptions m_checkOptions;
    RunOptions m_runOptions;
    CLI::App* m_check = nullptr;
    CLI::App* m_run = nullptr;
#ifdef KERF_WITH_UI
    ui::HmiOptions m_hmi;
    std::string m_hmiSize;
#endif
};

}  // namespace kerf::app
