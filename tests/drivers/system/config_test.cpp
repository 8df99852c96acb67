// The drive bus from the machine configuration: joints in motion's order, one node per axis, and
// the 80 % bus-load limit with the spec's figures (A2.5).
#include <gtest/gtest.h>

#include "core/machine/machine_loader.h"
#include "drivers/setup/can_bus_config.h"
#include "drivers/setup/can_drive_stack.h"
#include "drivers/setup/can_sim_drive_set.h"
#include "drivers/setup/socketcan_bus.h"
#include "motion/kinematics/machine_model.h"
#include "tests/drivers/system/test_machines.h"

namespace kerf::drivers {
namespace {

using namespace std::chrono_literals;

TEST(CanBusConfig, TheMillUsesFourNodesAtTwoMilliseconds) {
    Expected<CanBusConfig> bus = makeCanBusConfig(test::mill());
    ASSERT_TRUE(bus.ok()) << bus.error().message();
    EXPECT_EQ(bus->interface, "can0");
    EXPECT_EQ(bus->bitrate, 1000000u);
    EXPECT_EQ(bus->cyclePeriod, 2ms);
    EXPECT_EQ(bus->servoPeriod, 1ms);
    EXPECT_EQ(bus->nodeCount(), 4);
    ASSERT_EQ(bus->joints.size(), 4u);
    EXPECT_EQ(bus->joints[0].axis, 'X');
    EXPECT_EQ(bus->joints[0].node, 1);
    EXPECT_EQ(bus->joints[0].mode, cia402::Mode::CyclicPosition);
    EXPECT_EQ(bus->joints[3].axis, 'S');
    EXPECT_EQ(bus->joints[3].node, 4);
    EXPECT_EQ(bus->joints[3].mode, cia402::Mode::CyclicVelocity);
    EXPECT_EQ(bus->vendorId, 0x4B455246u);
    // 4 x (6-byte RPDO + 6-byte TPDO) + SYNC: 807-975 of 2000 bit times (40-49 %).
    EXPECT_EQ(bus->load.cycleBitsMin, 807u);
    EXPECT_EQ(bus->load.cycleBitsMax, 975u);
    EXPECT_EQ(bus->load.cycleBitTimes, 2000u);
}

TEST(CanBusConfig, RefusesABusAbove80PercentAndGivesTheLoad) {
    machine::MachineConfig config = test::mill();
    config.drives.cyclePeriodMs = 1.0;
    Expected<CanBusConfig> bus = makeCanBusConfig(config);
    ASSERT_FALSE(bus.ok());
    EXPECT_EQ(bus.error().code, "drives.bus-load");
    EXPECT_EQ(
        bus.error().message(),
        "CAN bus load 100.8 % is above the 80 % limit (4 nodes, 1000 kbit/s, 1 ms cycle: "
        "807-975 of 1000 bit times per cycle, 80.7-97.5 % (worst case 100.8 % with "
        "heartbeats)); lengthen drives.cycle_period, raise drives.bitrate or split the drives "
        "over two buses");
    EXPECT_FALSE(CanSimDriveSet::create(config, {}).ok()) << "the simulated set refuses it too";
}

TEST(CanBusConfig, BusLoadOfOtherConfigurations) {
    // Three nodes at 1 ms (62-75 %) pass, eight at 2 ms (78-95 %) do not, at 4 ms they do.
    EXPECT_TRUE(canBusLoad(3, 1000000, 1ms, 100ms).acceptable());
    EXPECT_FALSE(canBusLoad(8, 1000000, 2ms, 100ms).acceptable());
    EXPECT_TRUE(canBusLoad(8, 1000000, 4ms, 100ms).acceptable());
    // Half the bit rate needs twice the cycle.
    EXPECT_FALSE(canBusLoad(4, 500000, 2ms, 100ms).acceptable());
    EXPECT_TRUE(canBusLoad(4, 500000, 4ms, 100ms).acceptable());
}

TEST(CanBusConfig, EveryEnabledAxisNeedsANode) {
    machine::MachineConfig config = test::mill();
    config.axes[1].driveNode = 0;
    Expected<CanBusConfig> bus = makeCanBusConfig(config);
    ASSERT_FALSE(bus.ok());
    EXPECT_EQ(bus.error().message(),
              "axes.Y.drive_node is 0: every enabled axis needs a CANopen drive on the drive bus");
}

// The adapter's joints must be motion's joints: the enabled axes in axis order, then the spindle.
TEST(CanBusConfig, JointsAreInMotionsOrder) {
    machine::MachineConfig lathe =
        machine::parseMachine("base = \"lathe\"\n[axes.C]\nenabled = true\n", "l.toml").value();
    for (const machine::MachineConfig& config : {test::mill(), lathe}) {
        motion::MachineModel model = motion::makeMachineModel(config, {});
        CanBusConfig bus = makeCanBusConfig(config).value();
        ASSERT_EQ(static_cast<int>(bus.joints.size()), model.jointCount);
        for (int j = 0; j < model.jointCount; ++j) {
            int axis = model.jointAxis[static_cast<size_t>(j)];
            char letter = axis < 0 ? 'S' : "XYZABCUVW"[axis];
            EXPECT_EQ(bus.joints[static_cast<size_t>(j)].axis, letter) << j;
        }
        EXPECT_EQ(bus.joints.back().axis, 'S');
        EXPECT_EQ(model.spindleJoint, model.jointCount - 1);
    }
}

TEST(CanBusConfig, IntervalOfTheDrivesInterpolationFollowsTheCycle) {
    // 0x60C2 = {value, exponent}: 2 ms = {2, -3}, 1.5 ms = {15, -4}.
    machine::MachineConfig config = test::mill();
    CanBusConfig bus = makeCanBusConfig(config).value();
    canopen::MasterConfig master = makeMasterConfig(bus);
    auto findWrite = [&](canopen::ObjectAddress a) -> int64_t {
        for (const canopen::BootStep& s : master.nodes[0].boot.steps()) {
            if (s.kind == canopen::BootStepKind::Write && s.address == a) return s.value;
        }
        return -1;
    };
    EXPECT_EQ(findWrite({0x60C2, 1}), 2);
    EXPECT_EQ(findWrite({0x60C2, 2}), 0xFD);
    bus.cyclePeriod = std::chrono::microseconds(1500);
    master = makeMasterConfig(bus);
    EXPECT_EQ(findWrite({0x60C2, 1}), 15);
    EXPECT_EQ(findWrite({0x60C2, 2}), 0xFC);
    // The spindle is configured for CSV: mode 9, target velocity in RPDO1.
    EXPECT_EQ(master.nodes[3].rpdo.entries[1], (canopen::PdoEntry{0x60FF, 0, 32}));
}

// The master takes only its nodes' heartbeat/boot-up, EMCY, TPDO1 and SDO responses.
TEST(SocketCanBus, FiltersTheNodesFrames) {
    CanBusConfig bus = makeCanBusConfig(test::oneAxis()).value();
    std::vector<can::CanFilter> filters = driveBusFilters(bus);
    ASSERT_EQ(filters.size(), 4u);
    EXPECT_EQ(filters[0].id, 0x701u);
    EXPECT_EQ(filters[1].id, 0x081u);
    EXPECT_EQ(filters[2].id, 0x181u);
    EXPECT_EQ(filters[3].id, 0x581u);
    for (const can::CanFilter& f : filters)
        EXPECT_EQ(f.mask, 0x7FFu);
}

TEST(SocketCanBus, OpensTheConfiguredInterface) {
    CanBusConfig bus = makeCanBusConfig(test::oneAxis()).value();
    can::SocketCanChannel channel;
    std::error_code error = openDriveBus(bus, channel);
    if (std::error_code probe = can::probeSocketCan()) {
        EXPECT_EQ(error, probe);
        GTEST_SKIP() << "PF_CAN unavailable in this kernel (" << probe.message()
                     << "): opening can0 is tested only on a machine with kernel CAN";
    }
    if (error) GTEST_SKIP() << "no " << bus.interface << ": " << error.message();
    EXPECT_TRUE(channel.isOpen());
}

}  // namespace
}  // namespace kerf::drivers
