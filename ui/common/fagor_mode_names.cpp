#include "ui/common/fagor_mode_names.h"

#include <QtGlobal>

namespace kerf::ui {

const char* fagorMachineModeName(task::MachineMode mode) {
    using task::MachineMode;
    switch (mode) {
        case MachineMode::Manual:
            return QT_TRANSLATE_NOOP("kerf", "JOG");
        case MachineMode::Handwheel:
            return QT_TRANSLATE_NOOP("kerf", "Electronic handwheel");
        case MachineMode::Mdi:
            return QT_TRANSLATE_NOOP("kerf", "MDI");
        case MachineMode::SingleBlock:
            return QT_TRANSLATE_NOOP("kerf", "Single-block execution");
        case MachineMode::FullSequence:
            return QT_TRANSLATE_NOOP("kerf", "Automatic execution");
    }
    return "";
}

const char* fagorProgrammingModeName(task::ProgrammingMode mode) {
    using task::ProgrammingMode;
    switch (mode) {
        case ProgrammingMode::Programming:
            return QT_TRANSLATE_NOOP("kerf", "Editing");
        case ProgrammingMode::TestRun:
            return QT_TRANSLATE_NOOP("kerf", "Simulation");
    }
    return "";
}

}  // namespace kerf::ui
