#include "ui/shell/mode_controller.h"

#include <QCoreApplication>

#include "ui/common/fagor_mode_names.h"

namespace kerf::ui {

namespace {

// core/task names its modes with KERF_TR_NOOP; repeated here so lupdate puts them into the
// "kerf" context that ModeController translates them in.
[[maybe_unused]] constexpr const char* kCoreStrings[] = {
    QT_TRANSLATE_NOOP("kerf", "Manual operation"),
    QT_TRANSLATE_NOOP("kerf", "Electronic handwheel"),
    QT_TRANSLATE_NOOP("kerf", "Positioning with manual data input"),
    QT_TRANSLATE_NOOP("kerf", "Program run, single block"),
    QT_TRANSLATE_NOOP("kerf", "Program run, full sequence"),
    QT_TRANSLATE_NOOP("kerf", "Programming"),
    QT_TRANSLATE_NOOP("kerf", "Test run"),
    QT_TRANSLATE_NOOP("kerf", "stop the program before changing the operating mode"),
    QT_TRANSLATE_NOOP("kerf",
                      "programming station: no machine is connected, only Programming and "
                      "Test run are available"),
};

}  // namespace

ModeController::ModeController(bool machineConnected, QObject* parent)
    : QObject(parent),
      m_modes(machineConnected),
      m_screen(machineConnected ? ScreenMode::Machine : ScreenMode::Programming) {}

bool ModeController::requestMachineMode(task::MachineMode mode) {
    const bool moving = m_moving ? m_moving() : false;
    if (auto refusal = m_modes.setMachineMode(mode, moving)) {
        emit refused(QCoreApplication::translate("kerf", refusal->messageTemplate.c_str()));
        return false;
    }
    m_screen = ScreenMode::Machine;
    emit modesChanged();
    return true;
}

void ModeController::requestProgrammingMode(task::ProgrammingMode mode) {
    m_modes.setProgrammingMode(mode);
    m_screen = ScreenMode::Programming;
    emit modesChanged();
}

QString ModeController::machineModeText(task::MachineMode mode) const {
    return QCoreApplication::translate(
        "kerf", m_fagorNames ? fagorMachineModeName(mode) : task::machineModeName(mode));
}

QString ModeController::programmingModeText(task::ProgrammingMode mode) const {
    return QCoreApplication::translate(
        "kerf", m_fagorNames ? fagorProgrammingModeName(mode) : task::programmingModeName(mode));
}

}  // namespace kerf::ui
