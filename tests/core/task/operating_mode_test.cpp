#include "core/task/operating_mode.h"

#include <gtest/gtest.h>

namespace kerf::task {
namespace {

TEST(ModeMachine, MachineModeChangesOnlyWhenNothingMoves) {
    ModeMachine modes;
    EXPECT_EQ(modes.machineMode(), MachineMode::Manual);
    EXPECT_FALSE(modes.setMachineMode(MachineMode::FullSequence, false));
    // While a program moves: switching single block on the fly is fine, leaving is not.
    EXPECT_FALSE(modes.setMachineMode(MachineMode::SingleBlock, true));
    EXPECT_TRUE(modes.setMachineMode(MachineMode::Manual, true));
    EXPECT_EQ(modes.machineMode(), MachineMode::SingleBlock);
    EXPECT_FALSE(modes.setMachineMode(MachineMode::Manual, false));
    // Programming modes are independent of the machine.
    modes.setProgrammingMode(ProgrammingMode::TestRun);
    EXPECT_EQ(modes.programmingMode(), ProgrammingMode::TestRun);
    EXPECT_STREQ(machineModeName(MachineMode::Mdi), "Positioning with manual data input");
}

TEST(ModeMachine, ProgrammingStationRefusesEveryMachineMode) {
    ModeMachine station(false);
    EXPECT_FALSE(station.machineConnected());
    for (MachineMode mode : {MachineMode::Manual, MachineMode::Handwheel, MachineMode::Mdi,
                             MachineMode::SingleBlock, MachineMode::FullSequence}) {
        auto refusal = station.setMachineMode(mode, false);
        ASSERT_TRUE(refusal);
        EXPECT_NE(refusal->messageTemplate.find("programming station"), std::string::npos);
    }
    station.setProgrammingMode(ProgrammingMode::TestRun);
    EXPECT_EQ(station.programmingMode(), ProgrammingMode::TestRun);
}

}  // namespace
}  // namespace kerf::task
