#include "core/machine/machine_loader.h"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/machine/machine_validation.h"
#include "core/machine/machine_writer.h"

namespace kerf::machine {
namespace {

using Lines = std::vector<std::string>;

// Every problem of a file named mymill.toml, formatted as the user sees it.
Lines problemsOf(std::string_view toml) {
    DiagnosticList problems;
    Expected<MachineConfig> config = parseMachine(toml, "mymill.toml", &problems);
    Lines lines;
    for (const Diagnostic& d : problems)
        lines.push_back(d.format());
    if (config.ok()) lines.push_back("(loaded)");
    return lines;
}

MachineConfig loaded(std::string_view toml) {
    DiagnosticList problems;
    Expected<MachineConfig> config = parseMachine(toml, "part.toml", &problems);
    EXPECT_TRUE(problems.empty()) << problems.front().format();
    return config.ok() ? *config : MachineConfig{};
}

MachineConfig builtin(std::string_view name) {
    return loadMachine(name).value();
}

// --- bad input: one diagnostic per problem, at the right place -----------------------------

TEST(MachineLoaderErrors, ValueOutOfRangeNamesKeyValueRangeAndUnit) {
    EXPECT_EQ(problemsOf("base = \"mill\"\n"
                         "\n"
                         "# the X axis\n"
                         "[axes.X]\n"
                         "max_velocity = 400.0\n"
                         "max_jerk = 50000.0\n"
                         "max_acceleration=-5\n"),
              Lines{"mymill.toml:7:18: error: axes.X.max_acceleration = -5 is outside the "
                    "allowed range 1 … 100000 mm/s^2"});
}

TEST(MachineLoaderErrors, RotaryAxesUseAngularUnits) {
    EXPECT_EQ(problemsOf("base = \"lathe\"\n"
                         "[axes.C]\n"
                         "max_velocity = 0\n"),
              Lines{"mymill.toml:3:16: error: axes.C.max_velocity = 0 is outside the allowed "
                    "range 0.1 … 100000 deg/s"});
}

TEST(MachineLoaderErrors, NewAxisTypeIsKnownBeforeItsRangesAreChecked) {
    // "type" sorts after "max_jerk" but decides the unit of the message.
    EXPECT_EQ(problemsOf("base = \"mill\"\n"
                         "[axes.W]\n"
                         "max_jerk = 0.5\n"
                         "type = \"rotary\"\n"),
              Lines{"mymill.toml:3:12: error: axes.W.max_jerk = 0.5 is outside the allowed range "
                    "1 … 10000000 deg/s^3"});
}

TEST(MachineLoaderErrors, UnknownKeySuggestsTheClosestKey) {
    EXPECT_EQ(problemsOf("base = \"mill\"\n"
                         "[axes.X]\n"
                         "max_velocty = 100.0\n"
                         "[spindle]\n"
                         "max_rmp = 100\n"
                         "rapid_velocity = 10.0\n"),
              (Lines{"mymill.toml:3:1: error: unknown key axes.X.max_velocty; did you mean "
                     "axes.X.max_velocity?",
                     "mymill.toml:5:1: error: unknown key spindle.max_rmp; did you mean "
                     "spindle.max_rpm?",
                     "mymill.toml:6:1: error: unknown key spindle.rapid_velocity"}));
}

TEST(MachineLoaderErrors, UnknownTopLevelKey) {
    EXPECT_EQ(problemsOf("base = \"mill\"\n"
                         "colour = \"red\"\n"
                         "rapid_velocty = 10.0\n"),
              (Lines{"mymill.toml:2:1: error: unknown key colour",
                     "mymill.toml:3:1: error: unknown key rapid_velocty; did you mean "
                     "rapid_velocity?"}));
}

TEST(MachineLoaderErrors, WrongTypes) {
    EXPECT_EQ(problemsOf("base = \"mill\"\n"
                         "rapid_velocity = \"fast\"\n"
                         "name = 42\n"
                         "[spindle]\n"
                         "max_rpm = 12000.5\n"
                         "[axes.X]\n"
                         "enabled = \"yes\"\n"
                         "max_limit = [1, 2]\n"
                         "[axes.Y.home]\n"),
              (Lines{"mymill.toml:2:18: error: rapid_velocity = \"fast\" is a string; expected "
                     "a number (mm/s)",
                     "mymill.toml:3:8: error: name = 42 is an integer; expected a string",
                     "mymill.toml:5:11: error: spindle.max_rpm = 12000.5 is a floating-point "
                     "number; expected an integer (rpm)",
                     "mymill.toml:7:11: error: axes.X.enabled = \"yes\" is a string; expected "
                     "true or false",
                     "mymill.toml:8:13: error: axes.X.max_limit = [ 1, 2 ] is an array; expected "
                     "a number (mm)",
                     "mymill.toml:9:1: error: axes.Y.home is a table; expected a number (mm)"}));
}

TEST(MachineLoaderErrors, EnumValueNotAllowed) {
    EXPECT_EQ(problemsOf("base = \"mill\"\n"
                         "kind = \"router\"\n"
                         "[axes.X]\n"
                         "type = \"circular\"\n"),
              (Lines{"mymill.toml:2:8: error: kind = \"router\" is not one of mill, lathe",
                     "mymill.toml:4:8: error: axes.X.type = \"circular\" is not one of linear, "
                     "rotary"}));
}

TEST(MachineLoaderErrors, MinLimitNotBelowMaxLimit) {
    EXPECT_EQ(problemsOf("base = \"mill\"\n"
                         "[axes.Y]\n"
                         "min_limit = 10.0\n"
                         "max_limit = 10.0\n"
                         "[axes.Z]\n"
                         "max_limit = -600.0\n"),
              (Lines{"mymill.toml:3:13: error: axes.Y.min_limit = 10 must be less than "
                     "axes.Y.max_limit = 10",
                     "mymill.toml:6:13: error: axes.Z.min_limit = -500 must be less than "
                     "axes.Z.max_limit = -600"}));
}

TEST(MachineLoaderErrors, HomeOutsideTheSoftLimits) {
    EXPECT_EQ(problemsOf("base = \"mill\"\n"
                         "[axes.X]\n"
                         "home = 500.0\n"),
              Lines{"mymill.toml:3:8: error: axes.X.home = 500 is outside the soft limits "
                    "-400 … 400 mm"});
}

TEST(MachineLoaderErrors, UnknownAxisLetter) {
    EXPECT_EQ(problemsOf("base = \"mill\"\n"
                         "[axes.Q]\n"
                         "max_velocity = 1.0\n"
                         "[axes.x]\n"),
              (Lines{"mymill.toml:2:7: error: axes.Q: Q is not an axis letter; use one of X, Y, "
                     "Z, A, B, C, U, V, W",
                     "mymill.toml:4:7: error: axes.x: x is not an axis letter; use one of X, Y, "
                     "Z, A, B, C, U, V, W"}));
}

TEST(MachineLoaderErrors, ToolAxisMustBeAnEnabledLinearAxis) {
    EXPECT_EQ(problemsOf("base = \"lathe\"\n"
                         "tool_axis = \"Y\"\n"),
              Lines{"mymill.toml:2:13: error: tool_axis = \"Y\" is not an enabled axis of this "
                    "machine (X, Z)"});
    EXPECT_EQ(problemsOf("base = \"lathe\"\n"
                         "tool_axis = \"C\"\n"),
              Lines{"mymill.toml:2:13: error: tool_axis = \"C\" is not an enabled axis of this "
                    "machine (X, Z)"});
    EXPECT_EQ(problemsOf("base = \"lathe\"\n"
                         "tool_axis = \"C\"\n"
                         "axes.C.enabled = true\n"),
              Lines{"mymill.toml:2:13: error: tool_axis = \"C\" must be a linear axis"});
    EXPECT_EQ(problemsOf("base = \"mill\"\n"
                         "tool_axis = \"K\"\n"),
              Lines{"mymill.toml:2:13: error: tool_axis = \"K\" is not one of X, Y, Z, A, B, C, "
                    "U, V, W"});
}

TEST(MachineLoaderErrors, OnlyOptionalAxesMayBeDisabled) {
    EXPECT_EQ(problemsOf("base = \"mill\"\n"
                         "[axes.Y]\n"
                         "enabled = false\n"),
              Lines{"mymill.toml:3:11: error: axes.Y.enabled = false is only allowed when "
                    "axes.Y.optional = true"});
}

TEST(MachineLoaderErrors, DiameterModeOnlyOnLinearLatheAxes) {
    EXPECT_EQ(problemsOf("base = \"mill\"\n"
                         "[axes.X]\n"
                         "diameter_mode = true\n"),
              Lines{"mymill.toml:3:17: error: axes.X.diameter_mode = true is only allowed on a "
                    "linear axis of a lathe"});
}

TEST(MachineLoaderErrors, SpindleMinAboveMax) {
    EXPECT_EQ(problemsOf("base = \"lathe\"\n"
                         "[spindle]\n"
                         "min_rpm = 5000\n"),
              Lines{"mymill.toml:3:11: error: spindle.min_rpm = 5000 must not exceed "
                    "spindle.max_rpm = 4000"});
}

TEST(MachineLoaderErrors, BarBoreMustBeSmallerThanTheBar) {
    EXPECT_EQ(problemsOf("base = \"lathe\"\n"
                         "[bar]\n"
                         "bore_diameter = 60\n"),
              Lines{"mymill.toml:3:17: error: bar.bore_diameter = 60 must be smaller than "
                    "bar.diameter = 60"});
}

TEST(MachineLoader, LatheBarFromTheFile) {
    DiagnosticList problems;
    auto config = parseMachine(
        "base = \"lathe\"\n[bar]\ndiameter = 80\nlength = 200.5\n"
        "face_z = 2\nbore_diameter = 20\n",
        "mylathe.toml", &problems);
    ASSERT_TRUE(config) << (problems.empty() ? "" : problems.front().format());
    EXPECT_EQ(config->bar.diameterMm, 80.0);
    EXPECT_EQ(config->bar.lengthMm, 200.5);
    EXPECT_EQ(config->bar.faceZMm, 2.0);
    EXPECT_EQ(config->bar.boreDiameterMm, 20.0);
}

TEST(MachineLoaderErrors, SimulatedProbeBoxNeedsLowerBoundsBelowUpperOnes) {
    // "z_min = 5" is at line 4, column 9 of the file.
    EXPECT_EQ(problemsOf("base = \"lathe\"\n"
                         "[simulation.probe]\n"
                         "enabled = true\n"
                         "z_min = 5\n"
                         "z_max = -2\n"),
              Lines{"mymill.toml:4:9: error: simulation.probe.z_min = 5 must be less than "
                    "simulation.probe.z_max = -2"});
    // Switched off, the bounds are not checked.
    EXPECT_EQ(problemsOf("base = \"lathe\"\n[simulation.probe]\nz_min = 5\nz_max = -2\n"),
              Lines{"(loaded)"});
}

TEST(MachineLoader, SetupErrorOfTheSimulatedPart) {
    const MachineConfig config =
        loaded("base = \"mill\"\n[simulation.setup]\nshift = [1.5, -0.8, -0.2]\nrotation = 0.7\n");
    EXPECT_EQ(config.setupError.shiftXMm, 1.5);
    EXPECT_EQ(config.setupError.shiftYMm, -0.8);
    EXPECT_EQ(config.setupError.shiftZMm, -0.2);
    EXPECT_EQ(config.setupError.rotationDeg, 0.7);
    // The writer spells the shift as a table of x, y, z; it reads back the same.
    EXPECT_EQ(loaded(toToml(config)), config);
    EXPECT_EQ(builtin("mill").setupError, SetupErrorConfig{});
}

TEST(MachineLoaderErrors, SetupErrorNeedsThreeNumbersInRange) {
    EXPECT_EQ(problemsOf("base = \"mill\"\n[simulation.setup]\nshift = [1.5, -0.8]\n"),
              Lines{"mymill.toml:3:9: error: simulation.setup.shift must be an array of three "
                    "numbers [x, y, z], not 2"});
    EXPECT_EQ(problemsOf("base = \"mill\"\n[simulation.setup]\nshift = [1, \"a\", 0]\n"),
              Lines{"mymill.toml:3:13: error: simulation.setup.shift.y = \"a\" is a string; "
                    "expected a number (mm)"});
    EXPECT_EQ(problemsOf("base = \"mill\"\n[simulation.setup]\nrotation = 200\n"),
              Lines{"mymill.toml:3:12: error: simulation.setup.rotation = 200 is outside the "
                    "allowed range -180 … 180 deg"});
}

TEST(MachineLoader, ToolTouchProbeAndToolErrors) {
    const MachineConfig config = loaded(
        "base = \"mill\"\n[simulation.tool_probe]\nenabled = true\n"
        "centre = [-200.0, 50.0, -300.0]\ndiameter = 30.0\ntype = \"cube\"\n"
        "[[simulation.tool_error]]\ntool = 3\nlength = -0.05\nradius = -0.012\n"
        "[[simulation.tool_error]]\ntool = 7\nlength = 0.1\n"
        "[[simulation.tool_error]]\ntool = 1\ncentre_offset = [0.03, -2]\n");
    EXPECT_TRUE(config.toolProbe.enabled);
    EXPECT_EQ(config.toolProbe.centreXMm, -200.0);
    EXPECT_EQ(config.toolProbe.centreYMm, 50.0);
    EXPECT_EQ(config.toolProbe.centreZMm, -300.0);
    EXPECT_EQ(config.toolProbe.diameterMm, 30.0);
    EXPECT_EQ(config.toolProbe.shape, ToolProbeShape::Cube);
    ASSERT_EQ(config.toolErrors.size(), 3u);
    EXPECT_EQ(config.toolErrors[0], (ToolErrorConfig{3, -0.05, -0.012}));
    EXPECT_EQ(config.toolErrors[1], (ToolErrorConfig{7, 0.1, 0.0}));
    EXPECT_EQ(config.toolErrors[2], (ToolErrorConfig{1, 0.0, 0.0, {0.03, -2.0}}));
    ASSERT_NE(config.toolError(7), nullptr);
    EXPECT_EQ(config.toolError(7)->lengthMm, 0.1);
    EXPECT_EQ(config.toolError(4), nullptr);
    // The writer gives [[simulation.tool_error]] tables back; they read back the same.
    EXPECT_EQ(loaded(toToml(config)), config);
    EXPECT_TRUE(builtin("mill").toolErrors.empty());
    EXPECT_FALSE(builtin("mill").toolProbe.enabled);
}

TEST(MachineLoaderErrors, ToolErrorsNeedAToolOnceAndSmallLengths) {
    EXPECT_EQ(problemsOf("base = \"mill\"\n[[simulation.tool_error]]\nlength = 0.1\n"),
              Lines{"mymill.toml:2:1: error: simulation.tool_error needs a tool number"});
    EXPECT_EQ(problemsOf("base = \"mill\"\n[[simulation.tool_error]]\ntool = 3\nlength = 11\n"),
              Lines{"mymill.toml:4:10: error: simulation.tool_error.length = 11 is out of "
                    "range: a tool number 0 ... 32767, lengths within +-10 mm"});
    EXPECT_EQ(problemsOf("base = \"mill\"\n[[simulation.tool_error]]\ntool = 3\n"
                         "[[simulation.tool_error]]\ntool = 3\n"),
              Lines{"mymill.toml:4:1: error: simulation.tool_error: tool 3 is given twice"});
    EXPECT_EQ(problemsOf("base = \"mill\"\n[[simulation.tool_error]]\ntool = 1\n"
                         "centre_offset = [1, 12]\n"),
              Lines{"mymill.toml:4:17: error: simulation.tool_error.centre_offset must be an "
                    "array of two numbers [x, y] within +-10 mm, not [ 1, 12 ]"});
    EXPECT_EQ(problemsOf("base = \"mill\"\n[[simulation.tool_error]]\ntool = 1\n"
                         "centre_offset = 0.1\n"),
              Lines{"mymill.toml:4:17: error: simulation.tool_error.centre_offset must be an "
                    "array of two numbers [x, y] within +-10 mm, not 0.1"});
    EXPECT_EQ(problemsOf("base = \"mill\"\n[[simulation.tool_error]]\ntool = 3\nlenght = 1\n"),
              Lines{"mymill.toml:4:1: error: unknown key simulation.tool_error.lenght"});
    EXPECT_EQ(problemsOf("base = \"mill\"\n[simulation]\ntool_error = 3\n"),
              Lines{"mymill.toml:3:14: error: simulation.tool_error must be tables "
                    "[[simulation.tool_error]] with tool, length and radius"});
    EXPECT_EQ(problemsOf("base = \"mill\"\n[simulation.tool_probe]\ntype = \"ball\"\n"),
              Lines{"mymill.toml:3:8: error: simulation.tool_probe.type = \"ball\" is not one "
                    "of disc, cube"});
}

TEST(MachineLoader, PresetAndSimulatedProbeFromTheFile) {
    const MachineConfig config = loaded(
        "base = \"lathe\"\n[axes.Z]\npreset = -100\n"
        "[simulation.probe]\nenabled = true\nx_max = 30\nz_max = -102.5\n");
    EXPECT_EQ(config.axis('Z')->presetPosition, -100.0);
    EXPECT_EQ(config.axis('X')->presetPosition, 0.0);
    EXPECT_TRUE(config.probeWorkpiece.enabled);
    EXPECT_EQ(config.probeWorkpiece.xMaxMm, 30.0);
    EXPECT_EQ(config.probeWorkpiece.zMaxMm, -102.5);
    // Bounds not given stay open.
    EXPECT_EQ(config.probeWorkpiece.xMinMm, -100000.0);
    EXPECT_EQ(config.probeWorkpiece.zMinMm, -100000.0);
    // The built-in mill's workpiece origin is 400 mm below its Z home (the top of a part on the
    // table); every other built-in preset is the machine origin. Neither has a probe box.
    for (const char* name : {"mill", "lathe"}) {
        const MachineConfig machine = builtin(name);
        for (const AxisConfig& axis : machine.axes) {
            const bool millZ = std::string(name) == "mill" && axis.letter == 'Z';
            EXPECT_EQ(axis.presetPosition, millZ ? -400.0 : 0.0) << name << " " << axis.letter;
        }
        EXPECT_FALSE(machine.probeWorkpiece.enabled) << name;
    }
}

TEST(MachineLoaderErrors, DriveNodesAreUniqueAndNotTheMasters) {
    EXPECT_EQ(problemsOf("base = \"mill\"\n"
                         "[drives]\n"
                         "master_node = 4\n"
                         "[axes.Y]\n"
                         "drive_node = 1\n"),
              (Lines{"mymill.toml:3:15: error: spindle.drive_node = 4 is the node-ID of "
                     "drives.master_node",
                     "mymill.toml:5:14: error: axes.Y.drive_node = 1 is already the node of "
                     "axes.X.drive_node"}));
}

TEST(MachineLoaderErrors, DriveCycleIsAWholeNumberOfServoPeriods) {
    EXPECT_EQ(problemsOf("base = \"mill\"\n"
                         "[drives]\n"
                         "cycle_period = 1.5\n"),
              (Lines{"mymill.toml:3:16: error: drives.cycle_period = 1.5 must be a whole multiple "
                     "of servo_period = 1"}));
}

TEST(MachineLoaderErrors, DriveBusRules) {
    EXPECT_EQ(problemsOf("base = \"mill\"\n"
                         "[drives]\n"
                         "bitrate = 600000\n"
                         "heartbeat_timeout = 10\n"
                         "vendor_id = \"acme\"\n"),
              (Lines{"mymill.toml:3:11: error: drives.bitrate = 600000 is not a CiA 301 bit rate "
                     "(10000, 20000, 50000, 125000, 250000, 500000, 800000, 1000000)",
                     "mymill.toml:4:21: error: drives.heartbeat_timeout = 10 must exceed "
                     "drives.heartbeat_period = 10",
                     "mymill.toml:5:13: error: drives.vendor_id = \"acme\" is not a 32-bit number "
                     "such as 0x0000029C"}));
}

TEST(MachineLoader, DriveRulesApplyOnlyWithDriveNodes) {
    // Without any drive node the bus settings are not used, so they are not checked together.
    Expected<MachineConfig> config = parseMachine(
        "tool_axis = \"X\"\n[axes.X]\n[drives]\ncycle_period = 1.5\nbitrate = 600000\n", "m.toml");
    EXPECT_TRUE(config.ok()) << config.error().format();
}

TEST(MachineLoader, DriveIdentityIsHexadecimalOrDecimal) {
    EXPECT_EQ(parseDriveIdentity("0x0000029C"), 0x29Cu);
    EXPECT_EQ(parseDriveIdentity("668"), 668u);
    EXPECT_EQ(parseDriveIdentity("0xFFFFFFFF"), 0xFFFFFFFFu);
    EXPECT_FALSE(parseDriveIdentity("0x100000000"));
    EXPECT_FALSE(parseDriveIdentity("4294967296"));
    EXPECT_FALSE(parseDriveIdentity("0x"));
    EXPECT_FALSE(parseDriveIdentity("12a"));
}

TEST(MachineLoaderErrors, TomlSyntaxErrorUsesTomlPosition) {
    EXPECT_EQ(problemsOf("base = \"mill\"\n"
                         "\n"
                         "rapid_velocity = = 5\n"),
              Lines{"mymill.toml:3:18: error: TOML syntax error: Error while parsing value: "
                    "could not determine value type"});
    EXPECT_EQ(problemsOf("base = \"mill\"\nmax_feed = 1.0\nmax_feed = 2.0\n"),
              Lines{"mymill.toml:3:12: error: TOML syntax error: Error while parsing key-value "
                    "pair: cannot redefine existing floating-point 'max_feed'"});
}

TEST(MachineLoaderErrors, BadBase) {
    EXPECT_EQ(problemsOf("base = \"router\"\n"),
              Lines{"mymill.toml:1:8: error: base = \"router\" is not a built-in machine (mill, "
                    "mill4, mill5, mill5h, mill5hh, lathe)"});
}

TEST(MachineLoaderErrors, NoAxesAtAll) {
    EXPECT_EQ(problemsOf("name = \"empty\"\n"),
              Lines{"mymill.toml: error: the machine has no axes; add [axes.X] tables or start "
                    "from a built-in machine with base = \"mill\""});
}

TEST(MachineLoaderErrors, AxesMustBeTables) {
    EXPECT_EQ(problemsOf("base = \"mill\"\naxes = 5\n"),
              Lines{"mymill.toml:2:1: error: axes must be a table of axes such as [axes.X]"});
    EXPECT_EQ(problemsOf("base = \"mill\"\naxes.X = 5\nspindle = 3\n"),
              (Lines{"mymill.toml:2:10: error: axes.X must be a table",
                     "mymill.toml:3:11: error: spindle must be a table"}));
}

TEST(MachineLoaderErrors, AllProblemsAreReportedInFileOrder) {
    std::string_view toml =
        "base = \"mill\"\n"
        "[axes.Z]\n"
        "max_velocity = -1.0\n"
        "[axes.X]\n"
        "max_jerk = true\n"
        "speed = 3\n";
    DiagnosticList problems;
    Expected<MachineConfig> config = parseMachine(toml, "mymill.toml", &problems);
    ASSERT_FALSE(config.ok());
    ASSERT_EQ(problems.size(), 3u);
    EXPECT_EQ(problems[0].line, 3u);
    EXPECT_EQ(problems[1].line, 5u);
    EXPECT_EQ(problems[2].line, 6u);
    // The result carries the first problem; each one is an error of code "config".
    EXPECT_EQ(config.error().format(), problems[0].format());
    for (const Diagnostic& d : problems) {
        EXPECT_EQ(d.severity, Severity::Error);
        EXPECT_EQ(d.code, "config");
        EXPECT_EQ(d.file, "mymill.toml");
    }
    // Placeholders stay in the template so the UI can translate it.
    EXPECT_EQ(problems[0].messageTemplate, "{1} = {2} is outside the allowed range {3}");
    EXPECT_EQ(problems[0].args,
              (std::vector<std::string>{"axes.Z.max_velocity", "-1", "0.1 … 100000 mm/s"}));
}

TEST(MachineLoaderErrors, MissingFile) {
    DiagnosticList problems;
    Expected<MachineConfig> config = loadMachine("/nonexistent/kerf/mymill.toml", &problems);
    ASSERT_FALSE(config.ok());
    EXPECT_EQ(config.error().format(),
              "/nonexistent/kerf/mymill.toml: error: cannot open the file: No such file or "
              "directory");
    EXPECT_EQ(problems.size(), 1u);
}

// --- partial files inherit --------------------------------------------------------------------

TEST(MachineLoader, PartialFileKeepsTheBaseValues) {
    MachineConfig config = loaded(
        "base = \"mill\"\n"
        "name = \"Shop mill\"\n"
        "rapid_velocity = 400   # an integer is a number too\n"
        "[axes.Z]\n"
        "min_limit = -450.5\n");
    MachineConfig expected = builtin("mill");
    expected.name = "Shop mill";
    expected.rapidVelocityMmPerS = 400.0;
    expected.axis('Z')->minLimit = -450.5;
    EXPECT_EQ(config, expected);
}

TEST(MachineLoader, FileWithoutBaseStartsFromSchemaDefaults) {
    MachineConfig config = loaded(
        "kind = \"lathe\"\n"
        "[axes.Z]\n"
        "max_velocity = 250.0\n"
        "[axes.X]\n"
        "diameter_mode = true\n");
    MachineConfig expected;
    expected.kind = MachineKind::Lathe;
    expected.axes = {defaultAxis('X'), defaultAxis('Z')};
    expected.axes[0].diameterMode = true;
    expected.axes[1].maxVelocityPerS = 250.0;
    EXPECT_EQ(config, expected);
    EXPECT_EQ(config.enabledAxisLetters(), "XZ");  // display order, not file order
}

TEST(MachineLoader, NewAxesTakeTheirTypeFromTheLetter) {
    MachineConfig config = loaded(
        "base = \"mill\"\n"
        "[axes.A]\n"
        "optional = true\n"
        "[axes.U]\n"
        "[axes.B]\n"
        "type = \"linear\"\n");
    EXPECT_EQ(config.enabledAxisLetters(), "XYZABU");
    EXPECT_EQ(config.axis('A')->type, AxisType::Rotary);
    EXPECT_EQ(config.axis('B')->type, AxisType::Linear);
    EXPECT_EQ(config.axis('U')->type, AxisType::Linear);
}

TEST(MachineLoader, DottedKeysAndInlineTablesWork) {
    MachineConfig config = loaded(
        "base = \"mill\"\n"
        "spindle.max_rpm = 8000\n"
        "axes.X.max_velocity = 100.0\n"
        "axes.Y = { max_velocity = 90.0, home = 1.5 }\n");
    EXPECT_EQ(config.spindle.maxRpm, 8000);
    EXPECT_EQ(config.axis('X')->maxVelocityPerS, 100.0);
    EXPECT_EQ(config.axis('Y')->maxVelocityPerS, 90.0);
    EXPECT_EQ(config.axis('Y')->homePosition, 1.5);
}

TEST(MachineLoader, LoadsAFileByPath) {
    std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "kerf_machine_loader";
    std::filesystem::create_directories(dir);
    std::filesystem::path file = dir / "shop.toml";
    ASSERT_FALSE(writeFileAtomically(file, "base = \"lathe\"\nmax_feed = 150.0\n"));
    Expected<MachineConfig> config = loadMachine(file.string());
    ASSERT_TRUE(config.ok()) << config.error().format();
    EXPECT_EQ(config->maxFeedMmPerS, 150.0);
    EXPECT_EQ(config->kind, MachineKind::Lathe);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace kerf::machine
