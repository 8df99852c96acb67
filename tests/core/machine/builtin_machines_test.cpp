#include "core/machine/builtin_machines.h"

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/machine/machine_loader.h"
#include "core/machine/machine_validation.h"

namespace kerf::machine {
namespace {

MachineConfig load(std::string_view name) {
    DiagnosticList problems;
    Expected<MachineConfig> config = loadMachine(name, &problems);
    EXPECT_TRUE(problems.empty()) << problems.front().format();
    return config.ok() ? *config : MachineConfig{};
}

void expectAxis(const MachineConfig& machine, char letter, double minLimit, double maxLimit,
                double velocity, double acceleration, double jerk, double home = 0.0) {
    SCOPED_TRACE(std::string("axis ") + letter);
    const AxisConfig* axis = machine.axis(letter);
    ASSERT_NE(axis, nullptr);
    EXPECT_EQ(axis->letter, letter);
    EXPECT_EQ(axis->minLimit, minLimit);
    EXPECT_EQ(axis->maxLimit, maxLimit);
    EXPECT_EQ(axis->maxVelocityPerS, velocity);
    EXPECT_EQ(axis->maxAccelerationPerS2, acceleration);
    EXPECT_EQ(axis->maxJerkPerS3, jerk);
    EXPECT_EQ(axis->homePosition, home);
}

TEST(BuiltinMachines, NamesAreMillAndLathe) {
    EXPECT_EQ(builtinMachineNames(), (std::vector<std::string_view>{"mill", "mill4", "mill5",
                                                                    "mill5h", "mill5hh", "lathe"}));
    EXPECT_TRUE(builtinMachineToml("router").empty());
}

TEST(BuiltinMachines, MillIsAVertical3AxisMill) {
    MachineConfig mill = load("mill");
    EXPECT_EQ(mill.name, "Kerf vertical mill");
    EXPECT_EQ(mill.kind, MachineKind::Mill);
    ASSERT_EQ(mill.axes.size(), 3u);
    EXPECT_EQ(mill.enabledAxisLetters(), "XYZ");
    EXPECT_EQ(mill.toolAxis, 'Z');
    EXPECT_EQ(mill.rapidVelocityMmPerS, 500.0);
    EXPECT_EQ(mill.maxFeedMmPerS, 250.0);
    EXPECT_EQ(mill.spindle.minRpm, 0);
    EXPECT_EQ(mill.spindle.maxRpm, 12000);
    EXPECT_EQ(mill.servoPeriodMs, 1.0);
    EXPECT_EQ(mill.pathToleranceMm, 0.01);
    expectAxis(mill, 'X', -400.0, 400.0, 500.0, 2000.0, 1000000.0);
    expectAxis(mill, 'Y', -300.0, 300.0, 500.0, 2000.0, 1000000.0);
    expectAxis(mill, 'Z', -500.0, 50.0, 500.0, 2000.0, 1000000.0);
    for (const AxisConfig& axis : mill.axes) {
        EXPECT_EQ(axis.type, AxisType::Linear);
        EXPECT_TRUE(axis.enabled);
        EXPECT_FALSE(axis.optional);
        EXPECT_FALSE(axis.diameterMode);
    }
    EXPECT_EQ(mill.axis('A'), nullptr);
}

TEST(BuiltinMachines, MillWithCanUsesFourNodesAtTwoMilliseconds) {
    MachineConfig mill = load("mill");
    EXPECT_EQ(mill.axis('X')->driveNode, 1);
    EXPECT_EQ(mill.axis('Y')->driveNode, 2);
    EXPECT_EQ(mill.axis('Z')->driveNode, 3);
    EXPECT_EQ(mill.spindle.driveNode, 4);
    EXPECT_EQ(mill.spindle.driveMode, SpindleDriveMode::Csv);
    EXPECT_EQ(mill.drives.interface, "can0");
    EXPECT_EQ(mill.drives.bitrate, 1000000);
    EXPECT_EQ(mill.drives.cyclePeriodMs, 2.0);
    EXPECT_EQ(mill.drives.heartbeatPeriodMs, 10);
    EXPECT_EQ(mill.drives.heartbeatTimeoutMs, 30);
    EXPECT_EQ(parseDriveIdentity(mill.drives.vendorId), 0x4B455246u);
    EXPECT_EQ(parseDriveIdentity(mill.drives.productCode), 0x402u);
}

TEST(BuiltinMachines, LatheDrivesAreXZAndTheSpindleWithCAsNodeThree) {
    MachineConfig lathe = load("lathe");
    EXPECT_EQ(lathe.axis('X')->driveNode, 1);
    EXPECT_EQ(lathe.axis('Z')->driveNode, 2);
    EXPECT_EQ(lathe.axis('C')->driveNode, 3);
    EXPECT_EQ(lathe.spindle.driveNode, 4);
    EXPECT_EQ(lathe.drives.cyclePeriodMs, 2.0);
}

TEST(BuiltinMachines, LatheHasDiameterXAndADisabledC) {
    MachineConfig lathe = load("lathe");
    EXPECT_EQ(lathe.name, "Kerf lathe");
    EXPECT_EQ(lathe.kind, MachineKind::Lathe);
    ASSERT_EQ(lathe.axes.size(), 3u);
    EXPECT_EQ(lathe.axes[0].letter, 'X');
    EXPECT_EQ(lathe.axes[1].letter, 'Z');
    EXPECT_EQ(lathe.axes[2].letter, 'C');
    EXPECT_EQ(lathe.enabledAxisLetters(), "XZ");
    EXPECT_EQ(lathe.toolAxis, 'Z');
    EXPECT_EQ(lathe.rapidVelocityMmPerS, 300.0);
    EXPECT_EQ(lathe.maxFeedMmPerS, 200.0);
    EXPECT_EQ(lathe.spindle.minRpm, 0);
    EXPECT_EQ(lathe.spindle.maxRpm, 4000);
    EXPECT_EQ(lathe.servoPeriodMs, 1.0);
    EXPECT_EQ(lathe.pathToleranceMm, 0.01);
    // The reference points: X out at radius 250, Z at the end away from the chuck.
    expectAxis(lathe, 'X', -10.0, 300.0, 300.0, 1500.0, 30000.0, 250.0);
    expectAxis(lathe, 'Z', -600.0, 50.0, 300.0, 1500.0, 30000.0, 50.0);
    expectAxis(lathe, 'C', -36000.0, 36000.0, 720.0, 1500.0, 30000.0);
    EXPECT_TRUE(lathe.axis('X')->diameterMode);
    EXPECT_FALSE(lathe.axis('Z')->diameterMode);
    EXPECT_TRUE(lathe.axis('X')->enabled);
    EXPECT_TRUE(lathe.axis('Z')->enabled);
    const AxisConfig* c = lathe.axis('C');
    EXPECT_EQ(c->type, AxisType::Rotary);
    EXPECT_TRUE(c->optional);
    EXPECT_FALSE(c->enabled);
    EXPECT_FALSE(c->diameterMode);
}

TEST(BuiltinMachines, AFileCanEnableTheLatheCAxis) {
    Expected<MachineConfig> lathe =
        parseMachine("base = \"lathe\"\n[axes.C]\nenabled = true\n", "c.toml");
    ASSERT_TRUE(lathe.ok()) << lathe.error().format();
    EXPECT_EQ(lathe->enabledAxisLetters(), "XZC");
}

TEST(BuiltinMachines, EmbeddedTextIsThePresetFile) {
    for (std::string_view name : builtinMachineNames()) {
        std::string path =
            std::string(KERF_SOURCE_DIR) + "/core/machine/presets/" + std::string(name) + ".toml";
        Expected<std::string> file = readWholeFile(path);
        ASSERT_TRUE(file.ok()) << file.error().format();
        EXPECT_EQ(*file, builtinMachineToml(name)) << "rebuild after editing " << path;
    }
}

}  // namespace
}  // namespace kerf::machine
