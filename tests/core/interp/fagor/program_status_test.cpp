// The FAGOR interpreter's programStatus() while a small program runs: every value below is read
// off the program and the tables by hand.
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

#include "core/interp/fagor/fagor_interpreter.h"
#include "core/machine/machine_loader.h"

namespace kerf::fagor {
namespace {

namespace fs = std::filesystem;
using Status = interp::ProgramStatus;

class NullSink final : public canon::Sink {
public:
    void consume(const canon::Command&) override {}
};

class FagorStatus : public testing::Test {
protected:
    void SetUp() override {
        const auto* info = testing::UnitTest::GetInstance()->current_test_info();
        root = fs::temp_directory_path() /
               ("kerf_fagor_status_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(root);
        fs::create_directories(root);
        auto loaded = machine::loadMachine("lathe");
        ASSERT_TRUE(static_cast<bool>(loaded));
        lathe = std::move(*loaded);
        settings.machine = &lathe;
        settings.ncRoot = root;
        settings.toolOffsetFile = root / "fagor_tool_offsets.tab";
        settings.zeroOffsetFile = root / "fagor_zero_offsets.tab";
        settings.toolFile = root / "fagor_tools.tab";
        write("fagor_tool_offsets.tab", "D1 X1 Z2 F3 R0.4 I0.1 K-0.2\n");
        write("fagor_zero_offsets.tab", "G54 X10 Z100\nG55 X0 Z240\nG58 X0 Z5\n");
    }
    void TearDown() override { fs::remove_all(root); }

    void write(const std::string& name, const std::string& text) {
        std::ofstream(root / name, std::ios::binary) << text;
    }

    // Runs program.pim one block at a time until the block on `line` has been executed.
    Status runThroughLine(const std::string& text, uint32_t line) {
        write("P000123.PIM", text);
        interpreter = std::make_unique<FagorInterpreter>(sources, settings);
        EXPECT_TRUE(interpreter->load(root / "P000123.PIM"));
        NullSink sink;
        for (int block = 0; block < 200; ++block) {
            const interp::RunStatus run = interpreter->run(sink, 1);
            if (run == interp::RunStatus::NeedsSync) {
                // The machine stops where the probe touched (or at the nominal point).
                interp::WorldSnapshot world;
                world.position = probeTouches ? probeAt : interpreter->nominalPosition();
                world.probeTriggered = probeTouches;
                world.probePosition = probeAt;
                interpreter->resume(world);
            } else if (run != interp::RunStatus::BudgetUsed) {
                break;
            }
            Status s = interpreter->programStatus();
            if (s.line == line) return s;
        }
        std::string messages;
        for (const Diagnostic& d : interpreter->diagnostics())
            messages += d.format() + "\n";
        ADD_FAILURE() << "line " << line << " was not reached\n" << messages;
        return {};
    }

    fs::path root;
    machine::MachineConfig lathe;
    FagorSettings settings;
    program::SourceRegistry sources;
    std::unique_ptr<FagorInterpreter> interpreter;
    bool probeTouches = false;
    Pose probeAt{};
};

const char* const kProgram =
    "G54\n"                     // 1
    "G11\n"                     // 2 mirror X
    "G72 S0.5\n"                // 3
    "T1 D1\n"                   // 4
    "S500 M3\n"                 // 5
    "M8\n"                      // 6
    "(P100 = 7)\n"              // 7
    "(P101 = P100 * 3)\n"       // 8
    "(PCALL 20, P0=2, P2=5)\n"  // 9
    "M30\n"                     // 10
    "(SUB 20)\n"                // 11
    "(P1 = P0 + P2)\n"          // 12
    "(RET)\n";                  // 13

TEST_F(FagorStatus, InsideASubroutineWithLocalAndGlobalParameters) {
    const Status s = runThroughLine(kProgram, 12);

    EXPECT_EQ(s.mainProgram, "P000123.PIM");
    EXPECT_EQ(s.activeProgram, "P000123.PIM");
    EXPECT_EQ(s.label, "SUB 20");
    EXPECT_FALSE(s.cycle.has_value());
    EXPECT_EQ(s.activeM, (std::vector<int>{3, 8}));
    EXPECT_FALSE(s.inch);
    EXPECT_EQ(s.parameterLetter, 'P');

    EXPECT_EQ(s.tool.number, 1);
    EXPECT_DOUBLE_EQ(s.tool.radiusMm, 0.4);
    ASSERT_TRUE(s.tool.lathe.has_value());
    EXPECT_EQ(s.tool.lathe->number, 1);
    EXPECT_DOUBLE_EQ(s.tool.lathe->xMm, 1.0);
    EXPECT_DOUBLE_EQ(s.tool.lathe->zMm, 2.0);
    EXPECT_DOUBLE_EQ(s.tool.lathe->wearXMm, 0.1);
    EXPECT_DOUBLE_EQ(s.tool.lathe->wearZMm, -0.2);
    EXPECT_EQ(s.tool.lathe->location, 3);

    const auto& t = s.transformations;
    EXPECT_EQ(t.datum, "G54");
    EXPECT_DOUBLE_EQ(t.datumShift[Axis::X], 10.0);
    EXPECT_DOUBLE_EQ(t.datumShift[Axis::Z], 100.0);
    EXPECT_EQ(t.mirrored, axisBit(Axis::X));
    EXPECT_DOUBLE_EQ(t.scale[static_cast<size_t>(axisIndex(Axis::X))], 0.5);
    EXPECT_DOUBLE_EQ(t.scale[static_cast<size_t>(axisIndex(Axis::Z))], 0.5);

    // Locals of the PCALL level (P0, P2 from the call, P1 computed) then the globals.
    using Scope = Status::ParameterScope;
    struct Expected {
        const char* name;
        double value;
        Scope scope;
        int level;
    };
    const Expected expected[] = {{"P0", 2.0, Scope::Local, 1},
                                 {"P1", 7.0, Scope::Local, 1},
                                 {"P2", 5.0, Scope::Local, 1},
                                 {"P100", 7.0, Scope::Global, 0},
                                 {"P101", 21.0, Scope::Global, 0}};
    ASSERT_EQ(s.parameters.size(), std::size(expected));
    for (size_t i = 0; i < std::size(expected); ++i) {
        EXPECT_EQ(s.parameters[i].name, expected[i].name);
        EXPECT_DOUBLE_EQ(s.parameters[i].value, expected[i].value) << expected[i].name;
        EXPECT_EQ(s.parameters[i].scope, expected[i].scope) << expected[i].name;
        EXPECT_EQ(s.parameters[i].level, expected[i].level) << expected[i].name;
    }
}

TEST_F(FagorStatus, BeforeTheSubroutineOnlyTheGlobalsAreSet) {
    const Status s = runThroughLine(kProgram, 8);
    EXPECT_EQ(s.label, "");
    ASSERT_EQ(s.parameters.size(), 2u);
    EXPECT_EQ(s.parameters[0].name, "P100");
    EXPECT_EQ(s.parameters[1].name, "P101");
}

TEST_F(FagorStatus, AdditiveZeroOffsetIsNamedAndAdded) {
    const Status s = runThroughLine("G55\nG58\nG0 X0 Z0\nM30\n", 2);
    EXPECT_EQ(s.transformations.datum, "G55 G58");
    EXPECT_DOUBLE_EQ(s.transformations.datumShift[Axis::Z], 240.0 + 5.0);
}

TEST_F(FagorStatus, ProbeResultOfG75) {
    probeTouches = true;
    probeAt[Axis::X] = 20.0;  // radius
    probeAt[Axis::Z] = 3.2;
    const char* program = "G90 G0 X40 Z10\nG75 Z-5 F100\nX50\nM30\n";
    EXPECT_FALSE(runThroughLine(program, 1).probe.has_value());
    const Status s = runThroughLine(program, 3);
    ASSERT_TRUE(s.probe.has_value());
    EXPECT_TRUE(s.probe->triggered);
    EXPECT_DOUBLE_EQ(s.probe->position[Axis::X], 20.0);
    EXPECT_DOUBLE_EQ(s.probe->position[Axis::Z], 3.2);
}

TEST_F(FagorStatus, ConstantSurfaceSpeedLimitAndFeedPerRevolution) {
    const std::string program =
        "M41\nG92 S3000\nG96 S180 M3\nG95 G1 X20 Z-5 F0.2\nG97 S1200\nM30\n";
    const Status css = runThroughLine(program, 4);
    ASSERT_TRUE(css.motion.surfaceMPerMin.has_value());
    EXPECT_DOUBLE_EQ(*css.motion.surfaceMPerMin, 180.0);
    EXPECT_DOUBLE_EQ(css.motion.spindleLimitRpm, 3000.0);
    EXPECT_DOUBLE_EQ(css.motion.feedMm, 0.2);
    EXPECT_TRUE(css.motion.feedPerRevolution);
    // G97 S1200: back to a fixed speed.
    const Status rpm = runThroughLine(program, 5);
    EXPECT_FALSE(rpm.motion.surfaceMPerMin.has_value());
    EXPECT_DOUBLE_EQ(rpm.motion.spindleRpm, 1200.0);
}

// The gear range may be selected in the G96 block itself (spec part 1 §8.6: "in that block or an
// earlier one"); the run refused it.
TEST_F(FagorStatus, TheGearRangeMayComeInTheG96Block) {
    const std::string program = "G92 S2500\nG96 S150 M41 M3\nG95 G1 X20 Z-5 F0.2\nM30\n";
    const Status css = runThroughLine(program, 3);
    ASSERT_TRUE(css.motion.surfaceMPerMin.has_value());
    EXPECT_DOUBLE_EQ(*css.motion.surfaceMPerMin, 150.0);
    EXPECT_DOUBLE_EQ(css.motion.spindleLimitRpm, 2500.0);
}

TEST_F(FagorStatus, InchProgramSaysInch) {
    const Status s = runThroughLine("G70\nG0 X1 Z0\nM30\n", 2);
    EXPECT_TRUE(s.inch);
    EXPECT_EQ(s.tool.number, -1);  // no T yet
}

TEST_F(FagorStatus, TheCannedCycleExecutedLastIsShown) {
    // G81 turns a cylinder of diameter 40 from Z0 to Z-30 out of the D70 bar in passes of C3;
    // the block after it still shows the cycle, as the TNC's PGM tab shows the last one defined.
    const char* program =
        "G90 G95 F0.3 S1000 M3\nG00 X70 Z2\n"
        "G81 X40 Z0 Q40 R-30 C3 D1\n"
        "G00 X80\nM30\n";
    EXPECT_FALSE(runThroughLine(program, 2).cycle.has_value());
    const Status s = runThroughLine(program, 4);
    ASSERT_TRUE(s.cycle.has_value());
    EXPECT_EQ(s.cycle->number, 81);
    EXPECT_EQ(s.cycle->name, "Turning cycle, straight sections");
}

}  // namespace
}  // namespace kerf::fagor
