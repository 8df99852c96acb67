// The CiA 402 tables against the spec (A2.3): statusword patterns and the transition table,
// written out here transition by transition.
#include "drivers/cia402/state_machine.h"

#include <gtest/gtest.h>

namespace kerf::drivers::cia402 {
namespace {

State decoded(uint16_t statusword) {
    State s = State::NotReadyToSwitchOn;
    EXPECT_TRUE(decodeStatusword(statusword, s)) << std::hex << statusword;
    return s;
}

TEST(Cia402Statusword, DecodesTypicalDriveStatuswords) {
    // Values as drives report them, with remote (bit 9) and voltage enabled (bit 4).
    EXPECT_EQ(decoded(0x0000), State::NotReadyToSwitchOn);
    EXPECT_EQ(decoded(0x0250), State::SwitchOnDisabled);
    EXPECT_EQ(decoded(0x0231), State::ReadyToSwitchOn);
    EXPECT_EQ(decoded(0x0233), State::SwitchedOn);
    EXPECT_EQ(decoded(0x1237), State::OperationEnabled);
    EXPECT_EQ(decoded(0x0217), State::QuickStopActive);
    EXPECT_EQ(decoded(0x021F), State::FaultReactionActive);
    EXPECT_EQ(decoded(0x0218), State::Fault);
    EXPECT_EQ(decoded(0x0238), State::Fault);  // bit 5 is not part of the Fault pattern
}

TEST(Cia402Statusword, EveryStateReportsItsOwnPattern) {
    for (const StatusPattern& p : kStatusPatterns) {
        EXPECT_EQ(decoded(statuswordFor(p.state)), p.state) << stateName(p.state);
    }
}

struct Case {
    int number;
    State from;
    uint16_t controlword;
    State to;
};

// A2.3: command bytes of each transition (x bits don't care, fault reset bit 7 clear).
const Case kCases[] = {
    {2, State::SwitchOnDisabled, 0x06, State::ReadyToSwitchOn},
    {3, State::ReadyToSwitchOn, 0x07, State::SwitchedOn},
    {3, State::ReadyToSwitchOn, 0x0F, State::SwitchedOn},  // "many drives also accept 0x0F"
    {4, State::SwitchedOn, 0x0F, State::OperationEnabled},
    {5, State::OperationEnabled, 0x07, State::SwitchedOn},
    {6, State::SwitchedOn, 0x06, State::ReadyToSwitchOn},
    {7, State::ReadyToSwitchOn, 0x00, State::SwitchOnDisabled},
    {7, State::ReadyToSwitchOn, 0x02, State::SwitchOnDisabled},
    {8, State::OperationEnabled, 0x06, State::ReadyToSwitchOn},
    {9, State::OperationEnabled, 0x00, State::SwitchOnDisabled},
    {10, State::SwitchedOn, 0x00, State::SwitchOnDisabled},
    {10, State::SwitchedOn, 0x02, State::SwitchOnDisabled},
    {11, State::OperationEnabled, 0x0B, State::QuickStopActive},
    {11, State::OperationEnabled, 0x02, State::QuickStopActive},
    {12, State::QuickStopActive, 0x00, State::SwitchOnDisabled},
    {16, State::QuickStopActive, 0x0F, State::OperationEnabled},
};

TEST(Cia402Transitions, EachCommandSelectsItsTransition) {
    for (const Case& c : kCases) {
        const Transition* t = transitionFor(c.from, c.controlword);
        ASSERT_NE(t, nullptr) << "transition " << c.number;
        EXPECT_EQ(t->number, c.number);
        EXPECT_EQ(t->to, c.to) << "transition " << c.number;
    }
}

TEST(Cia402Transitions, OtherCommandsChangeNothing) {
    // "Sending 0x0F in Switch on disabled does nothing - it is not the Shutdown pattern."
    EXPECT_EQ(transitionFor(State::SwitchOnDisabled, 0x0F), nullptr);
    EXPECT_EQ(transitionFor(State::SwitchOnDisabled, 0x07), nullptr);
    EXPECT_EQ(transitionFor(State::OperationEnabled, 0x0F), nullptr);
    EXPECT_EQ(transitionFor(State::QuickStopActive, 0x0B), nullptr);  // stays while held
    EXPECT_EQ(transitionFor(State::QuickStopActive, 0x06), nullptr);
    // Fault and the automatic states take no command; fault reset is an edge (the caller's).
    EXPECT_EQ(transitionFor(State::Fault, 0x06), nullptr);
    EXPECT_EQ(transitionFor(State::Fault, 0x80), nullptr);
    EXPECT_EQ(transitionFor(State::FaultReactionActive, 0x00), nullptr);
    EXPECT_EQ(transitionFor(State::NotReadyToSwitchOn, 0x06), nullptr);
    // With bit 7 set none of the patterns match.
    EXPECT_EQ(transitionFor(State::SwitchOnDisabled, 0x86), nullptr);
}

TEST(Cia402Transitions, MasterSendsTheDocumentedCommandBytes) {
    EXPECT_EQ(controlwordFor(Command::Shutdown), 0x06);
    EXPECT_EQ(controlwordFor(Command::SwitchOn), 0x07);
    EXPECT_EQ(controlwordFor(Command::EnableOperation), 0x0F);
    EXPECT_EQ(controlwordFor(Command::DisableOperation), 0x07);
    EXPECT_EQ(controlwordFor(Command::DisableVoltage), 0x00);
    EXPECT_EQ(controlwordFor(Command::QuickStop), 0x0B);
    EXPECT_EQ(controlwordFor(Command::FaultReset), 0x80);
}

uint16_t nextCommand(State from, State goal) {
    const Transition* t = nextStep(from, goal);
    return t ? controlwordFor(t->command) : 0xFFFF;
}

// Enable: 0x06 -> 0x07 -> 0x0F, one step at a time (A2.4 step 11).
TEST(Cia402Transitions, MasterWalksTowardsTheGoalOneStepAtATime) {
    EXPECT_EQ(nextCommand(State::SwitchOnDisabled, State::OperationEnabled), 0x06);
    EXPECT_EQ(nextCommand(State::ReadyToSwitchOn, State::OperationEnabled), 0x07);
    EXPECT_EQ(nextCommand(State::SwitchedOn, State::OperationEnabled), 0x0F);
    EXPECT_EQ(nextCommand(State::QuickStopActive, State::OperationEnabled), 0x0F);
    // Disabling a moving axis goes through disable operation (5), never straight to 8 or 9.
    EXPECT_EQ(nextCommand(State::OperationEnabled, State::SwitchOnDisabled), 0x07);
    EXPECT_EQ(nextCommand(State::SwitchedOn, State::SwitchOnDisabled), 0x00);
    EXPECT_EQ(nextCommand(State::ReadyToSwitchOn, State::SwitchOnDisabled), 0x00);
    EXPECT_EQ(nextCommand(State::QuickStopActive, State::SwitchOnDisabled), 0x00);
    // No path out of Fault without the reset, none out of the automatic states.
    EXPECT_EQ(nextStep(State::Fault, State::OperationEnabled), nullptr);
    EXPECT_EQ(nextStep(State::FaultReactionActive, State::SwitchOnDisabled), nullptr);
    EXPECT_EQ(nextStep(State::OperationEnabled, State::OperationEnabled), nullptr);
}

}  // namespace
}  // namespace kerf::drivers::cia402
