#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace kerf::task {

// The TNC operating concept: one machine mode and one programming mode are active at a time,
// and the screen header names both.
enum class MachineMode : uint8_t { Manual, Handwheel, Mdi, SingleBlock, FullSequence };
enum class ProgrammingMode : uint8_t { Programming, TestRun };

const char* machineModeName(MachineMode mode);  // English, translated by the UI
const char* programmingModeName(ProgrammingMode mode);

// Why a mode change is refused, or nothing when it is allowed.
struct ModeRefusal {
    std::string messageTemplate;
};

// Keeps the active modes and enforces when they may change: the machine mode may not change
// while a program or MDI block is moving the machine (it may while the program is stopped, to
// jog away and return to the contour); the programming modes are always free.
//
// On a programming station (no machine connected) the machine modes are refused: only the
// programming modes (Programming, Test run) are available.
class ModeMachine {
public:
    explicit ModeMachine(bool machineConnected = true) : m_connected(machineConnected) {}

    bool machineConnected() const { return m_connected; }
    MachineMode machineMode() const { return m_machine; }
    ProgrammingMode programmingMode() const { return m_programming; }

    // `moving`: a program run or MDI block is executing and not stopped.
    std::optional<ModeRefusal> setMachineMode(MachineMode mode, bool moving);
    void setProgrammingMode(ProgrammingMode mode) { m_programming = mode; }

private:
    bool m_connected = true;
    MachineMode m_machine = MachineMode::Manual;
    ProgrammingMode m_programming = ProgrammingMode::Programming;
};

}  // namespace kerf::task
