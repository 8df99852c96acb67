#include "core/machine/machine_writer.h"

#include <filesystem>

#include <gtest/gtest.h>

#include "core/machine/builtin_machines.h"
#include "core/machine/machine_loader.h"

namespace kerf::machine {
namespace {

MachineConfig reparse(const MachineConfig& config) {
    std::string toml = toToml(config);
    DiagnosticList problems;
    Expected<MachineConfig> back = parseMachine(toml, "written.toml", &problems);
    EXPECT_TRUE(problems.empty()) << problems.front().format() << "\n" << toml;
    return back.ok() ? *back : MachineConfig{};
}

TEST(MachineWriter, BuiltinsRoundTrip) {
    for (std::string_view name : builtinMachineNames()) {
        MachineConfig config = loadMachine(name).value();
        EXPECT_EQ(reparse(config), config) << name;
    }
}

TEST(MachineWriter, AwkwardValuesRoundTripExactly) {
    MachineConfig config = loadMachine("lathe").value();
    config.name = "Quote \" backslash \\ tab \t newline \n unicode µ";
    config.pathToleranceMm = 0.1 + 0.2;
    config.servoPeriodMs = 0.125;
    config.axis('C')->enabled = true;
    config.axis('C')->homePosition = -1.0 / 3.0;
    config.axis('Z')->maxJerkPerS3 = 9999999.999;
    config.spindle.minRpm = 17;
    EXPECT_EQ(reparse(config), config);
}

TEST(MachineWriter, WritesSectionsValuesAndUnits) {
    std::string toml = toToml(loadMachine("lathe").value());
    EXPECT_EQ(toml.rfind("# Kerf machine configuration", 0), 0u);
    for (std::string_view line :
         {"\nname = \"Kerf lathe\"\n", "\nkind = \"lathe\"\n", "\nrapid_velocity = 300.0  # mm/s\n",
          "\n[spindle]\nmin_rpm = 0  # rpm\nmax_rpm = 4000  # rpm\n",
          "\n[axes.X]\ntype = \"linear\"\nmin_limit = -10.0  # mm\n", "\ndiameter_mode = true\n",
          "\n[axes.C]\ntype = \"rotary\"\n", "\nmax_velocity = 720.0  # deg/s\n",
          "\npath_tolerance = 0.01  # mm\n"}) {
        EXPECT_NE(toml.find(line), std::string::npos) << line << "\nnot in\n" << toml;
    }
    EXPECT_LT(toml.find("[axes.X]"), toml.find("[axes.Z]"));
    EXPECT_LT(toml.find("[axes.Z]"), toml.find("[axes.C]"));
}

TEST(MachineWriter, SavesAtomicallyAndLoadsBack) {
    std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "kerf_machine_writer";
    std::filesystem::create_directories(dir);
    std::filesystem::path file = dir / "saved.toml";
    MachineConfig config = loadMachine("mill").value();
    config.axis('Y')->maxLimit = 275.25;
    ASSERT_FALSE(saveMachine(config, file));
    Expected<MachineConfig> back = loadMachine(file.string());
    ASSERT_TRUE(back.ok()) << back.error().format();
    EXPECT_EQ(*back, config);
    std::filesystem::remove_all(dir);

    MaybeError error = saveMachine(config, dir / "missing-folder" / "x.toml");
    ASSERT_TRUE(error);
    EXPECT_EQ(error->code, "io");
}

}  // namespace
}  // namespace kerf::machine
