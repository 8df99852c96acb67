// The Klartext interpreter's programStatus() while a small program runs: every value below is
// read off the program and the tool table by hand.
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>
#include <unistd.h>

#include "core/base/atomic_file.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/machine/machine_loader.h"

namespace kerf::klartext {
namespace {

namespace fs = std::filesystem;
using Status = interp::ProgramStatus;

class NullSink : public canon::Sink {
public:
    void consume(const canon::Command&) override {}
};

class ProgramStatusTest : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_status_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
        machine = *machine::loadMachine("mill");
        writeFileAtomically(dir / "TOOL.T",
                            "BEGIN TOOL.T MM\n"
                            "T  NAME        L    R    DL    DR\n"
                            "3  MILL_D12    +40  +6   +0.5  +0.1\n"
                            "[END]\n");
        auto loaded = tables::ToolTable::load(dir / "TOOL.T");
        ASSERT_TRUE(loaded.ok());
        tools = std::move(*loaded);
    }
    void TearDown() override { fs::remove_all(dir); }

    std::unique_ptr<KlartextInterpreter> load(const std::string& name, const std::string& text) {
        KlartextSettings settings;
        settings.machine = &machine;
        settings.ncRoot = dir;
        settings.tools = &*tools;
        auto k = std::make_unique<KlartextInterpreter>(sources, settings);
        writeFileAtomically(dir / name, text);
        EXPECT_TRUE(k->load(dir / name));
        return k;
    }
    // Runs one block at a time until the block on `line` has been executed.
    Status runThroughLine(KlartextInterpreter& k, uint32_t line) {
        NullSink sink;
        for (int i = 0; i < 200; ++i) {
            if (k.run(sink, 1) != interp::RunStatus::BudgetUsed) break;
            Status s = k.programStatus();
            if (s.line == line) return s;
        }
        std::string messages;
        for (const auto& d : k.diagnostics())
            messages += d.message() + "\n";
        ADD_FAILURE() << "line " << line << " was not reached\n" << messages;
        return {};
    }

    fs::path dir;
    machine::MachineConfig machine;
    std::optional<tables::ToolTable> tools;
    program::SourceRegistry sources;
};

// The 1-based line of the text on which `start` begins a line.
uint32_t lineOf(const std::string& text, const std::string& start) {
    const size_t at = text.find("\n" + start);
    EXPECT_NE(at, std::string::npos) << start;
    return static_cast<uint32_t>(
        std::count(text.begin(), text.begin() + static_cast<long>(at), '\n') + 2);
}

const std::string kProgram =
    "0 BEGIN PGM STAT MM\n"
    "1 TOOL CALL 3 Z S1000 DL+0.2 DR-0.3\n"
    "2 Q5 = 12.5\n"
    "3 QL2 = 3\n"
    "4 QS1 = \"abc\"\n"
    "5 CYCL DEF 7.0 DATUM SHIFT\n"
    "6 CYCL DEF 7.1 X+10\n"
    "7 CYCL DEF 7.2 Y-5\n"
    "8 CYCL DEF 8.0 MIRROR IMAGE\n"
    "9 CYCL DEF 8.1 X\n"
    "10 CYCL DEF 10.0 ROTATION\n"
    "11 CYCL DEF 10.1 ROT+30\n"
    "12 CYCL DEF 11.0 SCALING\n"
    "13 CYCL DEF 11.1 SCL 0.5\n"
    "14 CYCL DEF 200 DRILLING\n"
    "  Q200=2\n  Q201=-3\n  Q206=100\n  Q202=5\n  Q210=0\n  Q203=+0\n  Q204=10\n  Q211=0\n"
    "  Q395=0\n"
    "15 L X+0 Y+0 Z+50 R0 FMAX M3 M8\n"
    "16 CALL LBL 1\n"
    "17 L Z+100 R0 FMAX\n"
    "18 M30\n"
    "19 LBL 1\n"
    "20 Q7 = Q5 * 2\n"
    "21 LBL 0\n"
    "22 END PGM STAT MM\n";

TEST_F(ProgramStatusTest, BeforeTheFirstBlockNothingIsActive) {
    auto k = load("STAT.H", kProgram);
    const Status s = k->programStatus();
    EXPECT_EQ(s.tool.number, -1);
    EXPECT_FALSE(s.cycle.has_value());
    EXPECT_TRUE(s.parameters.empty());
    EXPECT_EQ(s.transformations.mirrored, 0);
    EXPECT_EQ(s.transformations.scale[0], 1.0);
}

TEST_F(ProgramStatusTest, InsideALabelAfterToolCallCyclesAndParameters) {
    auto k = load("STAT.H", kProgram);
    const Status s = runThroughLine(*k, lineOf(kProgram, "20 Q7"));

    EXPECT_EQ(s.mainProgram, "STAT.H");
    EXPECT_EQ(s.activeProgram, "STAT.H");
    EXPECT_EQ(s.label, "LBL 1");
    ASSERT_TRUE(s.cycle.has_value());
    EXPECT_EQ(s.cycle->number, 200);
    EXPECT_EQ(s.cycle->name, "DRILLING");
    EXPECT_EQ(s.activeM, (std::vector<int>{3, 8}));  // spindle on clockwise, coolant on
    EXPECT_FALSE(s.inch);
    EXPECT_EQ(s.parameterLetter, 'Q');

    // Tool 3 of the table, with the TOOL CALL deltas added to the table's.
    EXPECT_EQ(s.tool.number, 3);
    EXPECT_EQ(s.tool.name, "MILL_D12");
    EXPECT_DOUBLE_EQ(s.tool.lengthMm, 40.0);
    EXPECT_DOUBLE_EQ(s.tool.radiusMm, 6.0);
    EXPECT_NEAR(s.tool.deltaLengthMm, 0.5 + 0.2, 1e-12);
    EXPECT_NEAR(s.tool.deltaRadiusMm, 0.1 - 0.3, 1e-12);
    EXPECT_EQ(s.tool.axis, Axis::Z);
    EXPECT_FALSE(s.tool.lathe.has_value());

    const auto& t = s.transformations;
    EXPECT_DOUBLE_EQ(t.datumShift[Axis::X], 10.0);
    EXPECT_DOUBLE_EQ(t.datumShift[Axis::Y], -5.0);
    EXPECT_DOUBLE_EQ(t.datumShift[Axis::Z], 0.0);
    EXPECT_EQ(t.mirrored, axisBit(Axis::X));
    EXPECT_DOUBLE_EQ(t.rotationDeg, 30.0);
    EXPECT_DOUBLE_EQ(t.scale[static_cast<size_t>(axisIndex(Axis::X))], 0.5);
    EXPECT_DOUBLE_EQ(t.scale[static_cast<size_t>(axisIndex(Axis::Z))], 0.5);
    EXPECT_DOUBLE_EQ(t.scale[static_cast<size_t>(axisIndex(Axis::A))], 1.0);  // rotary: unscaled

    // The program's parameters and those TOOL CALL sets: Q108 radius R+DR = 6+0.1-0.3,
    // Q109 tool axis (2 = Z), Q114 length L+DL = 40+0.5+0.2.
    struct Expected {
        const char* name;
        double value;
        Status::ParameterScope scope;
    };
    const Expected expected[] = {
        {"Q5", 12.5, Status::ParameterScope::Global},
        {"Q7", 25.0, Status::ParameterScope::Global},
        {"Q108", 5.8, Status::ParameterScope::Global},
        {"Q109", 2.0, Status::ParameterScope::Global},
        {"Q114", 40.7, Status::ParameterScope::Global},
        {"QL2", 3.0, Status::ParameterScope::Local},
        {"QS1", 0.0, Status::ParameterScope::Text},
    };
    ASSERT_EQ(s.parameters.size(), std::size(expected));
    for (size_t i = 0; i < std::size(expected); ++i) {
        EXPECT_EQ(s.parameters[i].name, expected[i].name);
        EXPECT_NEAR(s.parameters[i].value, expected[i].value, 1e-12) << expected[i].name;
        EXPECT_EQ(s.parameters[i].scope, expected[i].scope) << expected[i].name;
    }
    EXPECT_EQ(s.parameters.back().text, "abc");
}

TEST_F(ProgramStatusTest, ReturningFromTheLabelClearsIt) {
    auto k = load("STAT.H", kProgram);
    const Status s = runThroughLine(*k, lineOf(kProgram, "17 L"));
    EXPECT_EQ(s.label, "");
    EXPECT_EQ(s.mainProgram, "STAT.H");
}

TEST_F(ProgramStatusTest, CalledProgramIsNamedWhileItRuns) {
    writeFileAtomically(dir / "SUB.H", "0 BEGIN PGM SUB MM\n1 Q1 = 1\n2 END PGM SUB MM\n");
    auto k = load("MAIN.H", "0 BEGIN PGM MAIN MM\n1 CALL PGM SUB.H\n2 END PGM MAIN MM\n");
    // Line 2 of SUB.H: "1 Q1 = 1" (MAIN.H's line 2 is the call itself).
    NullSink sink;
    Status inside;
    for (int i = 0; i < 20 && k->run(sink, 1) == interp::RunStatus::BudgetUsed; ++i) {
        const Status s = k->programStatus();
        if (s.activeProgram == "SUB.H" && s.line == 2) inside = s;
    }
    EXPECT_EQ(inside.mainProgram, "MAIN.H");
    EXPECT_EQ(inside.activeProgram, "SUB.H");
}

TEST_F(ProgramStatusTest, InchProgramsSayInch) {
    auto k = load("INCH.H",
                  "0 BEGIN PGM INCH INCH\n1 CYCL DEF 7.0 DATUM SHIFT\n2 CYCL DEF 7.1 X+1\n"
                  "3 L X+0 R0 FMAX\n4 END PGM INCH INCH\n");
    const Status s = runThroughLine(*k, 3);
    EXPECT_TRUE(s.inch);
    EXPECT_DOUBLE_EQ(s.transformations.datumShift[Axis::X], 25.4);  // 1 inch, kept in mm
    ASSERT_TRUE(s.cycle.has_value());
    EXPECT_EQ(s.cycle->number, 7);
    EXPECT_EQ(s.cycle->name, "DATUM SHIFT");
}

}  // namespace
}  // namespace kerf::klartext
