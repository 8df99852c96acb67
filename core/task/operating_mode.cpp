#include "core/task/operating_mode.h"

#include "core/base/translate.h"

namespace kerf::task {

const char* machineModeName(MachineMode mode) {
    switch (mode) {
        case MachineMode::Manual:
            return KERF_TR_NOOP("Manual operation");
        case MachineMode::Handwheel:
            return KERF_TR_NOOP("Electronic handwheel");
        case MachineMode::Mdi:
            return KERF_TR_NOOP("Positioning with manual data input");
        case MachineMode::SingleBlock:
            return KERF_TR_NOOP("Program run, single block");
        case MachineMode::FullSequence:
            return KERF_TR_NOOP("Program run, full sequence");
    }
    return "";
}

const char* programmingModeName(ProgrammingMode mode) {
    return mode == ProgrammingMode::TestRun ? KERF_TR_NOOP("Test run")
                                            : KERF_TR_NOOP("Programming");
}

std::optional<ModeRefusal> ModeMachine::setMachineMode(MachineMode mode, bool moving) {
    if (!m_connected) {
        return ModeRefusal{
            KERF_TR_NOOP("programming station: no machine is connected, only Programming and "
                         "Test run are available")};
    }
    if (mode == m_machine) return std::nullopt;
    // Between the two program-run modes the switch is allowed at any time (the TNC changes
    // single block on the fly); away from them only when nothing moves.
    const bool programRun = [](MachineMode m) {
        return m == MachineMode::SingleBlock || m == MachineMode::FullSequence;
    }(m_machine);
    const bool toProgramRun = mode == MachineMode::SingleBlock || mode == MachineMode::FullSequence;
    if (moving && !(programRun && toProgramRun)) {
        return ModeRefusal{KERF_TR_NOOP("stop the program before changing the operating mode")};
    }
    m_machine = mode;
    return std::nullopt;
}

}  // namespace kerf::task
