#include "ui/shell/hmi_main.h"

#include <QApplication>
#include <QStandardPaths>
#include <iostream>
#include <optional>
#include <system_error>

#include "core/machine/machine_loader.h"
#include "ui/shell/main_window.h"
#include "ui/shell/mode_controller.h"
#include "ui/shell/test_run_screen.h"
#include "ui/shell/workspace.h"

namespace kerf::ui {

namespace {

bool applyStartMode(ModeController& modes, const std::string& mode) {
    using task::MachineMode;
    if (mode.empty() && !modes.machineConnected()) {
        modes.requestProgrammingMode(task::ProgrammingMode::Programming);
        return true;
    }
    if (mode.empty() || mode == "manual") return modes.requestMachineMode(MachineMode::Manual);
    if (mode == "handwheel") return modes.requestMachineMode(MachineMode::Handwheel);
    if (mode == "mdi") return modes.requestMachineMode(MachineMode::Mdi);
    if (mode == "single") return modes.requestMachineMode(MachineMode::SingleBlock);
    if (mode == "full") return modes.requestMachineMode(MachineMode::FullSequence);
    if (mode == "programming")
        modes.requestProgrammingMode(task::ProgrammingMode::Programming);
    else if (mode == "testrun")
        modes.requestProgrammingMode(task::ProgrammingMode::TestRun);
    else
        return false;
    return true;
}

// --layout: program; program + graphics; program + status; positions + status.
std::optional<WorkspaceLayout> layoutNamed(const std::string& name) {
    if (name == "program") return WorkspaceLayout::Program;
    if (name == "graphics") return WorkspaceLayout::ProgramGraphics;
    if (name == "status") return WorkspaceLayout::ProgramStatus;
    if (name == "positions") return WorkspaceLayout::PositionsStatus;
    return std::nullopt;
}

}  // namespace

int runHmi(int argc, char** argv, const HmiOptions& options) {
    // A screenshot needs no display: without one (and unless the caller chose a platform) it
    // renders offscreen, the 3D graphics left out; under X (xvfb-run) they are in the picture.
    if (!options.screenshot.empty() && qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") &&
        qEnvironmentVariableIsEmpty("DISPLAY")) {
        qputenv("QT_QPA_PLATFORM", "offscreen");
    }
    QApplication application(argc, argv);
    QApplication::setApplicationName(QStringLiteral("kerf"));
    DiagnosticList problems;
    auto machine = machine::loadMachine(options.machine, &problems);
    if (!machine) {
        for (const Diagnostic& d : problems)
            std::cerr << d.format() << '\n';
        if (problems.empty()) std::cerr << machine.error().format() << '\n';
        return 1;
    }
    const std::filesystem::path data =
        QStandardPaths::writableLocation(QStandardPaths::AppDataLocation).toStdString();
    HmiContext context;
    context.machine = *machine;
    context.ncRoot =
        options.ncRoot.empty() ? data / "nc_prog" : std::filesystem::path(options.ncRoot);
    context.recoveryFolder = data / "recovery";
    context.programmingStation = options.programmingStation;
    context.machineSource = options.machine;
    context.machiningClock = options.machiningClock;
    if (options.connectMachine && !options.programmingStation) {
        context.motion = [connect = options.connectMachine, config = *machine] {
            return connect(config);
        };
    }
    if (options.checkMoves) {
        context.checkMoves = [check = options.checkMoves, config = *machine](const Pose& origin) {
            return check(config, origin);
        };
    }
    std::error_code error;
    std::filesystem::create_directories(context.ncRoot, error);

    MainWindow window(std::move(context));
    if (!options.language.empty() &&
        !window.setLanguage(QString::fromStdString(options.language))) {
        std::cerr << "kerf: no translation for language " << options.language << '\n';
        return 2;
    }
    if (!applyStartMode(window.modes(), options.mode)) {
        std::cerr << "kerf: unknown mode " << options.mode
                  << (options.programmingStation
                          ? " (a programming station has: programming, testrun)\n"
                          : " (manual, handwheel, mdi, single, full, programming, testrun)\n");
        return 2;
    }
    if (!options.program.empty() && !window.openProgram(options.program)) {
        std::cerr << "kerf: cannot open " << options.program << '\n';
        return 1;
    }
    if (!options.layout.empty()) {
        const auto layout = layoutNamed(options.layout);
        if (!layout) {
            std::cerr << "kerf: unknown layout " << options.layout
                      << " (program, graphics, status, positions)\n";
            return 2;
        }
        window.workspace()->setLayoutKind(*layout);
    }
    window.resize(options.width, options.height);
    window.show();
    if (!options.screenshot.empty()) {
        // Let the window lay itself out and paint before taking the picture.
        for (int i = 0; i < 5; ++i)
            application.processEvents();
        if (options.mode == "testrun" && !finishTestRunForPicture(window)) {
            std::cerr << "kerf: the test run did not finish in time\n";
            return 1;
        }
        const QString file = QString::fromStdString(options.screenshot);
        if (!window.grab().save(file)) {
            std::cerr << "kerf: cannot write " << options.screenshot << '\n';
            return 1;
        }
        return 0;
    }
    return application.exec();
}

}  // namespace kerf::ui
