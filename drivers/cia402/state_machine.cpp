#include "drivers/cia402/state_machine.h"

namespace kerf::drivers::cia402 {

const char* stateName(State state) noexcept {
    switch (state) {
        case State::NotReadyToSwitchOn:
            return "not ready to switch on";
        case State::SwitchOnDisabled:
            return "switch on disabled";
        case State::ReadyToSwitchOn:
            return "ready to switch on";
        case State::SwitchedOn:
            return "switched on";
        case State::OperationEnabled:
            return "operation enabled";
        case State::QuickStopActive:
            return "quick stop active";
        case State::FaultReactionActive:
            return "fault reaction active";
        case State::Fault:
            return "fault";
    }
    return "?";
}

const Transition* transitionFor(State from, uint16_t controlword) noexcept {
    for (const Transition& t : kTransitions) {
        if (t.from == from && matches(t.command, controlword)) return &t;
    }
    return nullptr;
}

const Transition* nextStep(State from, State goal) noexcept {
    if (from == goal) return nullptr;
    // Breadth-first search backwards from the goal over eight states: `via[s]` is the first
    // master step from s on a shortest path.
    std::array<const Transition*, kStateCount> via{};
    std::array<bool, kStateCount> reached{};
    std::array<State, kStateCount> queue{};
    size_t head = 0;
    size_t tail = 0;
    reached[static_cast<size_t>(goal)] = true;
    queue[tail++] = goal;
    while (head < tail) {
        State to = queue[head++];
        for (const Transition& t : kTransitions) {
            auto s = static_cast<size_t>(t.from);
            if (!t.masterStep || t.to != to || reached[s]) continue;
            reached[s] = true;
            via[s] = &t;
            queue[tail++] = t.from;
        }
    }
    return via[static_cast<size_t>(from)];
}

}  // namespace kerf::drivers::cia402
