#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

// The CiA 402 drive state machine as tables (spec A2.3): statusword decoding by mask/value,
// controlword command patterns and the numbered transitions. Both sides use them: the master
// (DriveAxis) walks the table towards a goal state, the simulated drive applies the transition a
// controlword selects. Pure and constexpr; any thread.
namespace kerf::drivers::cia402 {

enum class State : uint8_t {
    NotReadyToSwitchOn,
    SwitchOnDisabled,
    ReadyToSwitchOn,
    SwitchedOn,
    OperationEnabled,
    QuickStopActive,
    FaultReactionActive,
    Fault,
};
inline constexpr std::size_t kStateCount = 8;

const char* stateName(State state) noexcept;

struct StatusPattern {
    State state;
    uint16_t mask;
    uint16_t value;
};

// CiA 402 statusword coding (bits 0-3, 5, 6), the same numbers as python-canopen's p402.py.
inline constexpr std::array<StatusPattern, kStateCount> kStatusPatterns{{
    {State::NotReadyToSwitchOn, 0x4F, 0x00},
    {State::SwitchOnDisabled, 0x4F, 0x40},
    {State::ReadyToSwitchOn, 0x6F, 0x21},
    {State::SwitchedOn, 0x6F, 0x23},
    {State::OperationEnabled, 0x6F, 0x27},
    {State::QuickStopActive, 0x6F, 0x07},
    {State::FaultReactionActive, 0x4F, 0x0F},
    {State::Fault, 0x4F, 0x08},
}};

// Statusword bits beyond the state.
inline constexpr uint16_t kStatusVoltageEnabled = 1u << 4;
inline constexpr uint16_t kStatusQuickStop = 1u << 5;  // 0 = quick stop active
inline constexpr uint16_t kStatusRemote = 1u << 9;
inline constexpr uint16_t kStatusTargetReached = 1u << 10;
inline constexpr uint16_t kStatusInternalLimit = 1u << 11;
inline constexpr uint16_t kStatusFollowsTarget = 1u << 12;   // CSP/CSV: 0 = target ignored
inline constexpr uint16_t kStatusFollowingError = 1u << 13;  // CSP: following error

// False when the statusword matches no pattern (then `state` is unchanged).
constexpr bool decodeStatusword(uint16_t statusword, State& state) noexcept {
    for (const StatusPattern& p : kStatusPatterns) {
        if ((statusword & p.mask) == p.value) {
            state = p.state;
            return true;
        }
    }
    return false;
}

// The state bits a drive reports in `state` (bit 5 set outside quick stop, bit 4 with voltage).
constexpr uint16_t statuswordFor(State state) noexcept {
    uint16_t bits = kStatusPatterns[static_cast<std::size_t>(state)].value;
    switch (state) {
        case State::SwitchOnDisabled:
        case State::Fault:
        case State::NotReadyToSwitchOn:
            return static_cast<uint16_t>(bits | kStatusQuickStop);
        default:
            return static_cast<uint16_t>(bits | kStatusVoltageEnabled);
    }
}

enum class Command : uint8_t {
    Shutdown,
    SwitchOn,
    DisableVoltage,
    QuickStop,
    DisableOperation,
    EnableOperation,
    FaultReset,
};

struct CommandPattern {
    Command command;
    uint16_t mask;  // controlword bits 0-3 and 7 that select the command
    uint16_t value;
    uint16_t send;  // what the master sends
};

// Controlword coding: bit 0 switch on, 1 enable voltage, 2 quick stop (active low), 3 enable
// operation, 7 fault reset (rising edge). Quick stop is sent as 0x000B: bits 0, 1, 3 stay set.
inline constexpr std::array<CommandPattern, 7> kCommandPatterns{{
    {Command::Shutdown, 0x87, 0x06, 0x0006},
    {Command::SwitchOn, 0x8F, 0x07, 0x0007},
    {Command::DisableVoltage, 0x82, 0x00, 0x0000},
    {Command::QuickStop, 0x86, 0x02, 0x000B},
    {Command::DisableOperation, 0x8F, 0x07, 0x0007},
    {Command::EnableOperation, 0x8F, 0x0F, 0x000F},
    {Command::FaultReset, 0x80, 0x80, 0x0080},
}};

constexpr uint16_t controlwordFor(Command command) noexcept {
    return kCommandPatterns[static_cast<std::size_t>(command)].send;
}

constexpr bool matches(Command command, uint16_t controlword) noexcept {
    const CommandPattern& p = kCommandPatterns[static_cast<std::size_t>(command)];
    return (controlword & p.mask) == p.value;
}

struct Transition {
    uint8_t number;
    State from;
    State to;
    Command command;
    bool masterStep;  // the master walks this transition towards a goal
};

// Commanded transitions of CiA 402 (0, 1, 13, 14 and the automatic 12 are the drive's own).
// 3 with 0x0F: many drives accept enable operation in Ready to switch on (the master does not
// rely on it). 8 and 9 cut the power stage of a moving axis: the master disables through 5.
inline constexpr std::array<Transition, 15> kTransitions{{
    {2, State::SwitchOnDisabled, State::ReadyToSwitchOn, Command::Shutdown, true},
    {3, State::ReadyToSwitchOn, State::SwitchedOn, Command::SwitchOn, true},
    {3, State::ReadyToSwitchOn, State::SwitchedOn, Command::EnableOperation, false},
    {4, State::SwitchedOn, State::OperationEnabled, Command::EnableOperation, true},
    {5, State::OperationEnabled, State::SwitchedOn, Command::DisableOperation, true},
    {6, State::SwitchedOn, State::ReadyToSwitchOn, Command::Shutdown, true},
    {7, State::ReadyToSwitchOn, State::SwitchOnDisabled, Command::DisableVoltage, true},
    {7, State::ReadyToSwitchOn, State::SwitchOnDisabled, Command::QuickStop, false},
    {8, State::OperationEnabled, State::ReadyToSwitchOn, Command::Shutdown, false},
    {9, State::OperationEnabled, State::SwitchOnDisabled, Command::DisableVoltage, false},
    {10, State::SwitchedOn, State::SwitchOnDisabled, Command::DisableVoltage, true},
    {10, State::SwitchedOn, State::SwitchOnDisabled, Command::QuickStop, false},
    {11, State::OperationEnabled, State::QuickStopActive, Command::QuickStop, true},
    {12, State::QuickStopActive, State::SwitchOnDisabled, Command::DisableVoltage, true},
    {16, State::QuickStopActive, State::OperationEnabled, Command::EnableOperation, true},
}};

// Drive side: the transition `controlword` selects in `from`, or nullptr (no change). Fault reset
// (15) is an edge and is handled by the caller.
const Transition* transitionFor(State from, uint16_t controlword) noexcept;

// Master side: the first transition of the shortest path of master steps from `from` to `goal`,
// or nullptr when `from` is the goal or no path exists (Fault needs a reset first).
const Transition* nextStep(State from, State goal) noexcept;

}  // namespace kerf::drivers::cia402
