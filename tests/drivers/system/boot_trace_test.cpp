// The boot of one drive against a golden frame trace written by hand from CiA 301/402 and the
// spec's boot sequence (A2.4): NMT reset communication, boot-up, identity and mode checks,
// heartbeats, quick-stop and following-error settings, interpolation period, the remap procedure
// of RPDO1/TPDO1 (A2.1), the other PDOs switched off, mode 8 read back, NMT start, then the SYNC
// rhythm and the enable sequence 0x06, 0x07, 0x0F, each confirmed by the statusword.
#include <gtest/gtest.h>

#include "drivers/setup/can_sim_drive_set.h"
#include "tests/drivers/system/test_machines.h"

namespace kerf::drivers {
namespace {

using Frames = std::vector<std::string>;

// Each SDO request of node 1 (0x601) with the drive's answer (0x581).
const Frames kBoot = {
    "000#8201",  // reset communication of node 1 (the drive is still booting and ignores it)
    "701#00",    // boot-up: pre-operational
    // 0x1000 device type: profile 0x0192 (402), servo drive.
    "601#4000100000000000",
    "581#4300100092010200",
    // 0x1018 vendor, product (compared with drives.vendor_id / product_code), revision.
    "601#4018100100000000",
    "581#431810014652454B",
    "601#4018100200000000",
    "581#4318100202040000",
    "601#4018100300000000",
    "581#4318100300000100",
    // 0x6502 supported modes: bit 7 (CSP) needed; the drive has PV, CSP, CSV (0x184).
    "601#4002650000000000",
    "581#4302650084010000",
    // 0x1017 = 100 ms; 0x1016 sub 1 = master 127, 250 ms; 0x6007 = 3 quick stop on master loss.
    "601#2B17100064000000",
    "581#6017100000000000",
    "601#23161001FA007F00",
    "581#6016100100000000",
    "601#2B07600003000000",
    "581#6007600000000000",
    // 0x605A = 6 (ramp and hold), 0x6085 = 2000 mm/s^2 * 10000 counts/mm = 0x01312D00.
    "601#2B5A600006000000",
    "581#605A600000000000",
    "601#23856000002D3101",
    "581#6085600000000000",
    // 0x6065 = 1 mm = 10000 counts, 0x6066 = 10 ms.
    "601#2365600010270000",
    "581#6065600000000000",
    "601#2B6660000A000000",
    "581#6066600000000000",
    // 0x60C2 = {1, -3}: 1 ms.
    "601#2FC2600101000000",
    "581#60C2600100000000",
    "601#2FC26002FD000000",
    "581#60C2600200000000",
    // RPDO1: invalidate, clear, controlword + target position, count 2, type 1, validate 0x201.
    "601#2300140101020080",
    "581#6000140100000000",
    "601#2F00160000000000",
    "581#6000160000000000",
    "601#2300160110004060",
    "581#6000160100000000",
    "601#2300160220007A60",
    "581#6000160200000000",
    "601#2F00160002000000",
    "581#6000160000000000",
    "601#2F00140201000000",
    "581#6000140200000000",
    "601#2300140101020000",
    "581#6000140100000000",
    // RPDO2-4 do not exist.
    "601#2301140101030080",
    "581#6001140100000000",
    "601#2302140101040080",
    "581#6002140100000000",
    "601#2303140101050080",
    "581#6003140100000000",
    // TPDO1: statusword + position actual, type 1, no inhibit time, no event timer, 0x181.
    "601#2300180181010080",
    "581#6000180100000000",
    "601#2F001A0000000000",
    "581#60001A0000000000",
    "601#23001A0110004160",
    "581#60001A0100000000",
    "601#23001A0220006460",
    "581#60001A0200000000",
    "601#2F001A0002000000",
    "581#60001A0000000000",
    "601#2F00180201000000",
    "581#6000180200000000",
    "601#2B00180300000000",
    "581#6000180300000000",
    "601#2B00180500000000",
    "581#6000180500000000",
    "601#2300180181010000",
    "581#6000180100000000",
    // TPDO2-4 do not exist.
    "601#2301180181020080",
    "581#6001180100000000",
    "601#2302180181030080",
    "581#6002180100000000",
    "601#2303180181040080",
    "581#6003180100000000",
    // 0x6060 = 8 (CSP), 0x6061 read back.
    "601#2F60600008000000",
    "581#6060600000000000",
    "601#4061600000000000",
    "581#4F61600008000000",
    // Start, then the first cycle. The master's controller sends its frames in the order they
    // were written (one FIFO, as a SocketCAN queue), RPDOs before the SYNC: the drive applies an
    // RPDO that arrived before a SYNC at that SYNC, then answers with its TPDO.
    "000#0101",
    "201#000000000000",
    "080#",
    "181#600200000000",
};

// One line per SYNC cycle: the master's controlword, the SYNC, and the statusword the drive
// answers with (ready to switch on 0x0231, switched on 0x0233, operation enabled with CSP's
// "follows target" bit 12: 0x1237). The master steps only on the statusword of the previous
// cycle, so every transition takes one cycle: 0x06, 0x07, 0x0F, then the target follows.
const Frames kEnable = {
    "201#060000000000", "080#", "181#310200000000", "201#070000000000", "080#", "181#330200000000",
    "201#0F0000000000", "080#", "181#371200000000", "201#0F0000000000", "080#", "181#371200000000",
};

TEST(BootTrace, OneDriveMatchesTheGoldenFrames) {
    std::filesystem::path log = test::tempFile("boot_trace.log");
    CanSimOptions options;
    options.tracePath = log;
    // Heartbeats every 100 ms (250 ms consumer time): none falls into the boot's frames.
    machine::MachineConfig config = test::oneAxis();
    config.drives.heartbeatPeriodMs = 100;
    config.drives.heartbeatTimeoutMs = 250;
    auto set = CanSimDriveSet::create(config, options);
    ASSERT_TRUE(set.ok()) << set.error().message();
    MaybeError booted = (*set)->boot();
    ASSERT_FALSE(booted) << booted->message();
    ASSERT_FALSE((*set)->finish());
    Frames expected = kBoot;
    expected.insert(expected.end(), kEnable.begin(), kEnable.end());
    EXPECT_EQ(test::traceFrames(log), expected);
}

// Timestamps are the end of each transmission at 1 Mbit/s: the NMT frame (69 bits) sent at 0
// ends at 69 us; the boot-up message (59 bits) sent at 10 ms ends at 10.059 ms.
TEST(BootTrace, TimestampsAreTheEndOfEachTransmission) {
    std::filesystem::path log = test::tempFile("boot_times.log");
    CanSimOptions options;
    options.tracePath = log;
    auto set = CanSimDriveSet::create(test::oneAxis(), options);
    ASSERT_TRUE(set.ok());
    ASSERT_FALSE((*set)->boot());
    ASSERT_FALSE((*set)->finish());
    std::vector<std::string> lines = test::traceLines(log);
    ASSERT_GE(lines.size(), 2u);
    EXPECT_EQ(lines[0], "(0000000000.000069) can0 000#8201");
    EXPECT_EQ(lines[1], "(0000000000.010059) can0 701#00");
}

}  // namespace
}  // namespace kerf::drivers
