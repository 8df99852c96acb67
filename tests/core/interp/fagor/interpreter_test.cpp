// Interpreter features a golden case cannot reach: files a program writes, interrupts, the M06
// subroutine, machine parameters other than the defaults, tables saved at the end. Expected
// values come from spec parts 1 and 2 and hand geometry.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/canon/trace_format.h"
#include "core/interp/fagor/fagor_interpreter.h"
#include "core/machine/machine_loader.h"

namespace kerf::fagor {
namespace {

namespace fs = std::filesystem;

class Recorder final : public canon::Sink {
public:
    void consume(const canon::Command& c) override {
        std::string line;
        canon::TraceFormat format;
        format.axes = axisBit(Axis::X) | axisBit(Axis::Z);
        canon::appendCommand(line, c, format);
        lines.push_back(line);
    }
    std::vector<std::string> lines;
};

std::string readFile(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

class FagorRun : public testing::Test {
protected:
    void SetUp() override {
        const auto* info = testing::UnitTest::GetInstance()->current_test_info();
        root = fs::temp_directory_path() /
               ("kerf_fagor_" + std::to_string(::getpid()) + "_" + info->name());
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
    }
    void TearDown() override { fs::remove_all(root); }

    void write(const std::string& name, const std::string& text) {
        std::ofstream(root / name, std::ios::binary) << text;
    }

    // Runs program.pim one block at a time; `beforeBlock(n)` is called before block n (0-based).
    interp::RunStatus run(const std::string& text,
                          const std::function<void(FagorInterpreter&, int)>& beforeBlock = {}) {
        write("program.pim", text);
        interpreter = std::make_unique<FagorInterpreter>(sources, settings);
        if (!interpreter->load(root / "program.pim")) return interp::RunStatus::Failed;
        interp::RunStatus status = interp::RunStatus::BudgetUsed;
        for (int block = 0; block < 100000; ++block) {
            if (beforeBlock) beforeBlock(*interpreter, block);
            status = interpreter->run(out, 1);
            if (status == interp::RunStatus::NeedsSync) {
                interp::WorldSnapshot world;
                world.position = interpreter->nominalPosition();
                interpreter->resume(world);
            } else if (status != interp::RunStatus::BudgetUsed) {
                break;
            }
        }
        return status;
    }

    std::string diagnostics() const {
        std::string text;
        for (const Diagnostic& d : interpreter->diagnostics())
            text += d.format() + "\n";
        return text;
    }

    fs::path root;
    machine::MachineConfig lathe;
    FagorSettings settings;
    program::SourceRegistry sources;
    std::unique_ptr<FagorInterpreter> interpreter;
    Recorder out;
};

TEST_F(FagorRun, WriteSubstitutesLikeTheManual) {
    // Spec part 2 EX-12.11: ISO text always substituted, high-level text only after '?'.
    const auto status =
        run("(P100=10, P101=20, P102=55, P103=222, P104=25)\n"
            "(OPEN P123, \"GENERATED\")\n"
            "(WRITE G1 XP100 ZP101 F100)\n"
            "(WRITE (SUB P102))\n"
            "(WRITE (SUB ?P102))\n"
            "(WRITE (ORGX54=P103))\n"
            "(WRITE (ORGX54=?P103))\n"
            "(WRITE (PCALL P104))\n"
            "(WRITE (PCALL ?P104))\n"
            "M30\n");
    ASSERT_EQ(status, interp::RunStatus::Finished) << diagnostics();
    EXPECT_EQ(readFile(root / "P000123.PIM"),
              "%GENERATED,,\n"
              "G1 X10 Z20 F100\n"
              "(SUB P102)\n"
              "(SUB 55)\n"
              "(ORGX54=P103)\n"
              "(ORGX54=222)\n"
              "(PCALL P104)\n"
              "(PCALL 25)\n");
}

TEST_F(FagorRun, OpenAppendsOrReplacesAnExistingProgram) {
    // Spec part 2 §6.7: A appends, D starts anew, neither is an error when the program exists.
    write("P000007.PIM", "%OLD,,\nG0 X1\n");
    ASSERT_EQ(run("(OPEN P7, A)\n(WRITE G0 X2)\nM30\n"), interp::RunStatus::Finished)
        << diagnostics();
    EXPECT_EQ(readFile(root / "P000007.PIM"), "%OLD,,\nG0 X1\nG0 X2\n");
    ASSERT_EQ(run("(OPEN P7, D)\n(WRITE G0 X3)\nM30\n"), interp::RunStatus::Finished)
        << diagnostics();
    EXPECT_EQ(readFile(root / "P000007.PIM"), "%,,\nG0 X3\n");
    EXPECT_EQ(run("(OPEN P7)\nM30\n"), interp::RunStatus::Failed);
}

TEST_F(FagorRun, InterruptSubroutineAndRepos) {
    // INT1SUB = 50: the subroutine runs before the next block, only with global parameters;
    // REPOS X, Z brings the plane axes back together to where the program was interrupted.
    settings.interruptSubroutines[0] = 50;
    const auto status =
        run("G152 G0 X10 Z0\n"
            "G1 Z-20 F100\n"
            "G1 X20\n"
            "M30\n"
            "(SUB 50)\n"
            "G0 X40\n"
            "(REPOS X, Z)\n"
            "(RET)\n",
            [](FagorInterpreter& in, int block) {
                if (block == 2) in.raiseInterrupt(1);
            });
    ASSERT_EQ(status, interp::RunStatus::Finished) << diagnostics();
    const std::vector<std::string> expected{"1:1 XMODE RADIUS",
                                            "1:1 RAPID X10.0000 Z0.0000",
                                            "2:1 LINE X10.0000 Z-20.0000 F100.000",
                                            "6:1 RAPID X40.0000 Z-20.0000",
                                            "7:1 RAPID X10.0000 Z-20.0000",
                                            "3:1 LINE X20.0000 Z-20.0000 F100.000",
                                            "4:1 END M30"};
    EXPECT_EQ(out.lines, expected);
}

TEST_F(FagorRun, ReposOutsideAnInterruptIsAnError) {
    EXPECT_EQ(run("(CALL 5)\nM30\n(SUB 5)\n(REPOS X)\n(RET)\n"), interp::RunStatus::Failed);
    EXPECT_NE(diagnostics().find("REPOS is only allowed in an interrupt subroutine"),
              std::string::npos);
}

TEST_F(FagorRun, ToolChangeSubroutineSeesNbtool) {
    // Spec part 2 EX-11.7 with TOFFM06: T5 preselects, M06 runs its subroutine, in which NBTOOL
    // is the tool asked for; the change happens when the subroutine ends (M06 after it).
    settings.toolChangeByM06 = true;
    for (MFunctionEntry& m : settings.mFunctions) {
        if (m.number == 6) m.subroutine = 60;
    }
    write("fagor_tool_offsets.tab", "D5 X3 Z4 F3 R0.8\n");
    const auto status =
        run("T1 D1\n"
            "M06\n"
            "T5\n"
            "M06\n"
            "M30\n"
            "(SUB 60)\n"
            "(P103 = NBTOOL)\n"
            "(MSG \"SELECIONAR T?P103 E PRESSIONAR SOFTKEY MARCHA\")\n"
            "(RET)\n");
    ASSERT_EQ(status, interp::RunStatus::Finished) << diagnostics();
    const std::vector<std::string> expected{
        "8:1 MSG INFO \"SELECIONAR T1 E PRESSIONAR SOFTKEY MARCHA\"",
        "2:1 TOOL T1 L=0.0000 R=0.0000 AXIS Z D1 TIPX=0.0000 TIPZ=0.0000 LOC 0",
        "8:1 MSG INFO \"SELECIONAR T5 E PRESSIONAR SOFTKEY MARCHA\"",
        "4:1 TOOL T5 L=0.0000 R=0.8000 AXIS Z D5 TIPX=3.0000 TIPZ=4.0000 LOC 3", "5:1 END M30"};
    EXPECT_EQ(out.lines, expected);
}

TEST_F(FagorRun, CompModeTwoIntersectsOutsideCorners) {
    // E29's outside corner at (Z40 X35 radius) with COMPMODE 2: the offset lines meet at
    // X = 36, Z = 40 + (36 - 35) * tan(56.31 / 2) = 40.5352 (centre), tip (F3) one lower/left.
    settings.compMode = 2;
    write("fagor_tool_offsets.tab", "D1 X0 Z0 F3 R1\n");
    ASSERT_EQ(run("T1 D1\nG0 G90 X110 Z100\nG1 G42 X10 Z60 F100\nX70 Z40\nX70 Z20\n"
                  "G40 G0 X110 Z100\nM30\n"),
              interp::RunStatus::Finished)
        << diagnostics();
    ASSERT_GE(out.lines.size(), 5u);
    EXPECT_EQ(out.lines[3], "4:1 LINE X35.0000 Z39.5352 F100.000");
    EXPECT_EQ(out.lines[4], "5:1 LINE X35.0000 Z19.0000 F100.000");
}

TEST_F(FagorRun, CompModeOneJoinsOutsideCornersWithArcs) {
    // The same corner with COMPMODE 1: an arc of radius 1 about the corner, from the end
    // normal of X70 Z40 to the start normal of X70 Z20 (the centre path), turning 56.31 deg.
    // The tip is the centre path moved by (-1, -1), the arc's centre too.
    settings.compMode = 1;
    write("fagor_tool_offsets.tab", "D1 X0 Z0 F3 R1\n");
    ASSERT_EQ(run("T1 D1\nG0 G90 X110 Z100\nG1 G42 X10 Z60 F100\nX70 Z40\nX70 Z20\n"
                  "G40 G0 X110 Z100\nM30\n"),
              interp::RunStatus::Finished)
        << diagnostics();
    ASSERT_GE(out.lines.size(), 6u);
    EXPECT_EQ(out.lines[3], "4:1 LINE X34.5547 Z39.8321 F100.000");
    EXPECT_EQ(out.lines[4],
              "5:1 ARC X35.0000 Z39.0000 CENTER Z39.0000 X34.0000 PLANE ZX SWEEP 56.3099 F100.000");
}

TEST_F(FagorRun, TablesAreSavedWhenTheProgramChangesThem) {
    write("fagor_tool_offsets.tab", "; offsets\nD1 X1 Z2 F3 R0.4\n");
    write("fagor_zero_offsets.tab", "G54 X0 Z100\n");
    ASSERT_EQ(run("(TOX1 = 1.5, TOF1 = 5)\n(ORGZ 55 = 240)\nG55\nM30\n"),
              interp::RunStatus::Finished)
        << diagnostics();
    // Only the fields written change; comments stay; the selection is kept for the next run.
    EXPECT_EQ(readFile(root / "fagor_tool_offsets.tab"), "; offsets\nD1 X1.5 Z2 F5 R0.4\n");
    EXPECT_EQ(readFile(root / "fagor_zero_offsets.tab"), "G54 X0 Z100\nG55 Z240\nACTIVE G55\n");
}

// The tool's NOSEA (a drill's point) travels with its tool data as NOSEW does; a NOSEA or NOSEW
// the program writes for the tool in use goes out at once, for another tool it waits for its
// tool change.
TEST_F(FagorRun, ToolDataCarryTheNoseAngleAndTheValuesTheProgramWrites) {
    write("fagor_tool_offsets.tab", "D5 F0 R0 X0 Z0\nD6 F3 R0.4 X0 Z0\n");
    write("fagor_tools.tab", "T5 D5 NOSEW8 NOSEA118\nT6 D6 NOSEA55\n");
    ASSERT_EQ(run("T5 D5\n(NOSEA5 = 90)\n(NOSEA6 = 35)\n(NOSEW5 = 6)\nT6 D6\nM30\n"),
              interp::RunStatus::Finished)
        << diagnostics();
    std::vector<std::string> tools;
    for (const std::string& line : out.lines)
        if (line.find("TOOL") != std::string::npos) tools.push_back(line);
    ASSERT_EQ(tools.size(), 4u);
    EXPECT_NE(tools[0].find("TOOL T5 "), std::string::npos) << tools[0];
    EXPECT_NE(tools[0].find(" W=8.0000 NOSEA=118.0000"), std::string::npos) << tools[0];
    EXPECT_NE(tools[1].find("TOOLDATA "), std::string::npos) << tools[1];
    EXPECT_NE(tools[1].find(" W=8.0000 NOSEA=90.0000"), std::string::npos) << tools[1];
    EXPECT_NE(tools[2].find(" W=6.0000 NOSEA=90.0000"), std::string::npos) << tools[2];
    EXPECT_NE(tools[3].find("TOOL T6 "), std::string::npos) << tools[3];
    EXPECT_NE(tools[3].find(" NOSEA=35.0000"), std::string::npos) << tools[3];
}

TEST_F(FagorRun, ActiveZeroOffsetOfTheTableIsTheStreamFrame) {
    // The offset active at the start is the stream's frame: X10 Z0 is (X5, Z0) in the stream
    // even though G54 is Z100 in machine coordinates; G55 (Z240) is 140 further.
    write("fagor_zero_offsets.tab", "G54 X0 Z100\nG55 X0 Z240\nACTIVE G54\n");
    ASSERT_EQ(run("G0 X10 Z0\nG55\nG0 X10 Z0\nM30\n"), interp::RunStatus::Finished)
        << diagnostics();
    const std::vector<std::string> expected{"1:1 RAPID X5.0000 Z0.0000",
                                            "3:1 RAPID X5.0000 Z140.0000", "4:1 END M30"};
    EXPECT_EQ(out.lines, expected);
}

TEST_F(FagorRun, BlockSkipFollowsTheFirstPlcMark) {
    settings.blockSkip = 1;
    ASSERT_EQ(run("G152 G0 X1\n/ G0 X2\n/1 G0 X3\n/2 G0 X4\nM30\n"), interp::RunStatus::Finished)
        << diagnostics();
    const std::vector<std::string> expected{"1:1 XMODE RADIUS", "1:1 RAPID X1.0000 Z0.0000",
                                            "4:1 RAPID X4.0000 Z0.0000", "5:1 END M30"};
    EXPECT_EQ(out.lines, expected);
}

TEST_F(FagorRun, BackgroundCheckFailureIsReported) {
    // With the check in a second thread, an error at the end still marks the run as failed.
    write("program.pim", "G0 X10\nG0 X20\n(GOTO N99)\nM30\n");
    FagorInterpreter in(sources, settings);
    in.load(root / "program.pim", FagorInterpreter::CheckMode::Background);
    interp::RunStatus status = interp::RunStatus::BudgetUsed;
    while (status == interp::RunStatus::BudgetUsed)
        status = in.run(out, 100);
    EXPECT_EQ(status, interp::RunStatus::Failed);
    EXPECT_TRUE(in.checkFailed());
}

TEST_F(FagorRun, AJumpBackFindsALabelReadBeforeTheFirstJump) {
    // The check indexes labels only from the first jump on; N20 comes before it and is found.
    const auto status =
        run("N10 G0 X10 Z5\nN20 (P100=P100+1)\nN30 G0 X20\nN35 G0 X10\n"
            "N40 (IF (P100 LT 3) GOTO N20)\nN50 M30\n");
    EXPECT_EQ(status, interp::RunStatus::Finished) << diagnostics();
    int third = 0;
    int fourth = 0;
    for (const std::string& line : out.lines) {
        third += line.starts_with("3:");
        fourth += line.starts_with("4:");
    }
    EXPECT_EQ(third, 3);  // P100 = 1, 2, 3
    EXPECT_EQ(fourth, 3);
}

TEST_F(FagorRun, ARepeatedLabelWarnsInAProgramWithoutJumps) {
    const auto status = run("N10 G0 X10 Z5\nN20 G0 X20\nN10 G0 X30\nN30 M30\n");
    EXPECT_EQ(status, interp::RunStatus::Finished) << diagnostics();
    EXPECT_NE(diagnostics().find(":3:1: warning: label N10 is used more than once"),
              std::string::npos)
        << diagnostics();
}

}  // namespace
}  // namespace kerf::fagor

namespace kerf::fagor {
namespace {

TEST_F(FagorRun, CannedCycleOverwritesP299) {
    // Spec part 2 §1.5: the machining cycles use global P299 for their own computation.
    ASSERT_EQ(run("(P299=5)\n(P298=7)\nG95 F0.2 S500 M3\nG0 X70 Z2\n"
                  "G81 X40 Z0 Q40 R-30 C3\nM30\n"),
              interp::RunStatus::Finished)
        << diagnostics();
    double value = -1.0;
    Problem problem;
    ASSERT_TRUE(interpreter->parameters().get(299, value, problem));
    EXPECT_EQ(value, 0.0);
    ASSERT_TRUE(interpreter->parameters().get(298, value, problem));
    EXPECT_EQ(value, 7.0);
}

TEST_F(FagorRun, CheckFailsAtAConstructThatCannotRunYet) {
    // A run would stop at the screen instruction: the check fails, nothing moves.
    EXPECT_EQ(run("G0 X130 Z120\n"
                  "G1 X100 Z100 F100\n"
                  "(ODW 1, 6, 33)\n"
                  "M30\n"),
              interp::RunStatus::Failed);
    const std::string file = (root / "program.pim").string();
    EXPECT_EQ(diagnostics(), file +
                                 ":3:2: error: ODW is a screen customisation instruction: it "
                                 "runs only in a user customisation program (the user screen)\n");
    EXPECT_TRUE(out.lines.empty());
}

TEST_F(FagorRun, CheckFailsAtAnAxisTheLatheLacks) {
    // The built-in lathe has X and Z: Y and C words are errors at their column before anything
    // runs (the run used to move X and Z first and stop at line 2).
    EXPECT_EQ(run("G90 G0 X130 Z120\n"
                  "G1 X100 Y10 F100\n"
                  "G01 C90\n"
                  "M30\n"),
              interp::RunStatus::Failed);
    const std::string file = (root / "program.pim").string();
    EXPECT_EQ(diagnostics(), file + ":2:9: error: axis Y is not available on this machine\n" +
                                 file + ":3:5: error: axis C is not available on this machine\n");
    EXPECT_TRUE(out.lines.empty());
}

TEST_F(FagorRun, CycleParametersAndArcCentresAreNotAxes) {
    // C of G81 is its pass depth, I and K an arc's centre: the lathe check accepts them.
    EXPECT_EQ(run("G90 G95 F0.3 S1000 M3\n"
                  "G00 X70 Z2\n"
                  "G81 X40 Z0 Q40 R-30 C3 D1\n"
                  "G00 X60 Z0\n"
                  "G03 X60 Z-20 I0 K-10\n"
                  "M30\n"),
              interp::RunStatus::Finished)
        << diagnostics();
}

TEST_F(FagorRun, CheckFollowsExecToAMissingProgram) {
    // The run would stop at the EXEC: the check fails at its P, before G0 moves.
    EXPECT_EQ(run("G0 X10\n(EXEC P7)\nM30\n"), interp::RunStatus::Failed);
    EXPECT_EQ(diagnostics(),
              (root / "program.pim").string() + ":2:7: error: program 7 is not in the NC root\n");
    EXPECT_TRUE(out.lines.empty());
}

TEST_F(FagorRun, CheckFollowsExecIntoAFaultyProgram) {
    // P7 runs P8, which moves an axis the lathe lacks: the check of P8 fails, and so do the
    // EXECs that lead there.
    write("P000007.PIM", "G0 X20\n(MEXEC P8)\nM30\n");
    write("P000008.PIM", "G1 Y5\nM30\n");
    EXPECT_EQ(run("G0 X10\n(EXEC P7)\nM30\n"), interp::RunStatus::Failed);
    EXPECT_EQ(diagnostics(), (root / "P000008.PIM").string() +
                                 ":1:4: error: axis Y is not available on this machine\n" +
                                 (root / "P000007.PIM").string() +
                                 ":2:8: error: program 8 has errors\n");
    EXPECT_TRUE(out.lines.empty());
}

TEST_F(FagorRun, CheckLeavesAProgramTheRunWritesToTheRun) {
    // P9 does not exist before the run: OPEN creates it, then EXEC runs it.
    EXPECT_EQ(run("(OPEN P9)\n(WRITE G0 X30)\n(WRITE M30)\n(EXEC P9)\nM30\n"),
              interp::RunStatus::Finished)
        << diagnostics();
    // P9's G0 X30 (diameter: 15 in radius) on its line 2, after the header OPEN wrote.
    EXPECT_EQ(out.lines, (std::vector<std::string>{"2:1 RAPID X15.0000 Z0.0000", "5:1 END M30"}));
}

}  // namespace
}  // namespace kerf::fagor

namespace kerf::fagor {
namespace {

// Profiles of G68 written with G70/G71, G53 and G93 (spec part 2 §1.6 allows them): each must
// give the same moves as the same profile written in mm and part coordinates.
constexpr const char* kProfileCall =
    "N1 G90 G95 F0.3 S800 M3\n"
    "N2 G00 X70 Z2\n"
    "N3 G68 X0 Z0 C3 D0.5 L0.3 M0.1 H0.1 S10 E20\n"
    "N4 G00 X70 Z2\n"
    "N5 M30\n";
// The golden cycle_g68_profile_lines_arc's profile: face to r10, r10 to Z-20, taper to r20 at
// Z-30, r20 to Z-45, convex quarter round about (Z-55, r20) to r30 at Z-55.
constexpr const char* kProfileInMm =
    "N10 G01 X20 Z0\n"
    "G01 Z-20\n"
    "G01 X40 Z-30\n"
    "G01 Z-45\n"
    "N20 G03 X60 Z-55 I0 K-10\n";

class FagorProfileFunctions : public FagorRun {
protected:
    std::vector<std::string> movesOf(const std::string& profile) {
        out.lines.clear();
        EXPECT_EQ(run(std::string(kProfileCall) + profile), interp::RunStatus::Finished)
            << diagnostics();
        return out.lines;
    }
    bool finishingPassHas(const std::string& move) const {
        return std::any_of(out.lines.begin(), out.lines.end(), [&](const std::string& line) {
            return line.find(move + " F0.100") != std::string::npos;
        });
    }
};

TEST_F(FagorProfileFunctions, InchBlocksInAProfileAreConvertedAndEndWithIt) {
    // A taper to X40.64 Z-30.48 and a cylinder to Z-45.72: 1.6, 1.2 and 1.8 inches exactly.
    const std::vector<std::string> inMm = movesOf(
        "N10 G01 X20 Z0\n"
        "G01 Z-20\n"
        "G01 X40.64 Z-30.48\n"
        "G01 Z-45.72\n"
        "N20 G01 X60 Z-55\n");
    ASSERT_TRUE(finishingPassHas("LINE X20.3200 Z-30.4800")) << testing::PrintToString(inMm);
    // N4's G00 X70 after the cycle is in mm: G70 ended with the profile.
    const std::vector<std::string> inInch = movesOf(
        "N10 G01 X20 Z0\n"
        "G01 Z-20\n"
        "G70 G01 X1.6 Z-1.2\n"
        "G01 Z-1.8\n"
        "N20 G71 G01 X60 Z-55\n");
    EXPECT_EQ(inInch, inMm);
    EXPECT_EQ(inInch.end()[-3].substr(0, 28), "4:1 N4 RAPID X35.0000 Z2.000");
}

TEST_F(FagorProfileFunctions, MachineZeroPointsOfAProfileLeaveTheZeroOffset) {
    // G54 is Z100 from machine zero: the machine's Z80 is the part's Z-20, Z55 the part's Z-45.
    write("fagor_zero_offsets.tab", "G54 X0 Z100\nACTIVE G54\n");
    const std::vector<std::string> inMm = movesOf(kProfileInMm);
    const std::vector<std::string> inMachine = movesOf(
        "N10 G01 X20 Z0\n"
        "G53 G01 Z80\n"
        "G01 X40 Z-30\n"
        "G53 G01 X40 Z55\n"
        "N20 G03 X60 Z-55 I0 K-10\n");
    EXPECT_EQ(inMachine, inMm);
    EXPECT_TRUE(finishingPassHas("LINE X10.0000 Z-20.0000"));
}

TEST_F(FagorProfileFunctions, PolarPointsAndArcsAboutTheProfilesPolarOrigin) {
    const std::vector<std::string> inMm = movesOf(kProfileInMm);
    // G93 I20 J-30: the origin at X20 (r10), Z-30; R10 Q90 is 10 up in X from it: X40 Z-30. Then
    // G93 I40 J-55 (r20, Z-55): G03 Q90 turns from Z-45 (angle 0) to the angle 90: X60 Z-55.
    const std::vector<std::string> inPolar = movesOf(
        "N10 G01 X20 Z0\n"
        "G01 Z-20\n"
        "G93 I20 J-30\n"
        "G01 R10 Q90\n"
        "G01 Z-45\n"
        "G93 I40 J-55\n"
        "N20 G03 Q90\n");
    EXPECT_EQ(inPolar, inMm);
}

TEST_F(FagorProfileFunctions, ZeroOffsetsAndG53ArcsInAProfileAreErrorsAtTheirColumn) {
    const std::string file = (root / "program.pim").string();
    EXPECT_EQ(run(std::string(kProfileCall) + "N10 G01 X20 Z0\nG54\nN20 G01 X60 Z-55\n"),
              interp::RunStatus::Failed);
    EXPECT_EQ(diagnostics(), file + ":7:1: error: G54 is not allowed in a profile\n");
    EXPECT_EQ(run(std::string(kProfileCall) + "N10 G01 X20 Z0\nG01 Z-45\n"
                                              "N20 G53 G03 X60 Z-55 I0 K-10\n"),
              interp::RunStatus::Failed);
    EXPECT_EQ(diagnostics(),
              file + ":8:5: error: G53 in a profile needs a G00 or G01 point in X, Z\n");
}

TEST_F(FagorRun, ToolThatCannotReachAValleyIsReportedAtTheCycle) {
    // The profile dips 5 mm over 5 mm (45°) at line 7. A 55° insert at CUTA 93° leaves
    // 180 - 93 - 55 = 32° behind it: the check warns at G68 and the cycle starts with the
    // message. A 35° insert leaves 52°: no message.
    write("fagor_tool_offsets.tab", "D1 F3 R0.4\n");
    const std::string program =
        "N1 G90 G95 F0.3 S800 T1 D1 M3\n"
        "N2 G00 X70 Z2\n"
        "N3 G68 X0 Z0 C3 D0.5 L0.3 M0.1 H0.1 S10 E20\n"
        "N4 M30\n"
        "N10 G01 X20 Z0\n"
        "G01 Z-10\n"
        "G01 X10 Z-15\n"
        "G01 Z-30\n"
        "N20 G01 X60 Z-40\n";
    const std::string message =
        "tool T1 cannot reach the profile at line 7: it descends 45° into "
        "the material and CUTA + NOSEA leave 32°";
    write("fagor_tools.tab", "T1 D1 NOSEA55 CUTA93\n");
    ASSERT_EQ(run(program), interp::RunStatus::Finished) << diagnostics();
    EXPECT_EQ(diagnostics(), (root / "program.pim").string() + ":3:4: warning: " + message + "\n");
    EXPECT_EQ(std::count(out.lines.begin(), out.lines.end(), "3:1 N3 MSG INFO \"" + message + "\""),
              1)
        << testing::PrintToString(out.lines);
    out.lines.clear();
    write("fagor_tools.tab", "T1 D1 NOSEA35 CUTA93\n");
    ASSERT_EQ(run(program), interp::RunStatus::Finished) << diagnostics();
    EXPECT_EQ(diagnostics(), "");
}

TEST_F(FagorRun, ACycleMachinesTheClosestProfileTheToolReaches) {
    // The valley of the test above: r10 to Z-10, down 45° to r5 at Z-15, r5 to Z-30. The 55°
    // insert descends at most 32°: the finishing pass (H) leaves r10 at Z-10 along the 32° line
    // and meets the floor r5 at Z-(10 + 5 / tan 32°); it never goes to the corner at Z-15. The
    // 35° insert follows the programmed profile.
    write("fagor_tool_offsets.tab", "D1 F3 R0.4\n");
    const std::string program =
        "N1 G90 G95 F0.3 S800 T1 D1 M3\n"
        "N2 G00 X70 Z2\n"
        "N3 G68 X0 Z0 C3 D0.5 H0.1 S10 E20\n"
        "N4 M30\n"
        "N10 G01 X20 Z0\n"
        "G01 Z-10\n"
        "G01 X10 Z-15\n"
        "G01 Z-30\n"
        "N20 G01 X60 Z-40\n";
    char bridgeEnd[64];
    std::snprintf(bridgeEnd, sizeof bridgeEnd, "LINE X5.0000 Z%.4f F0.100",
                  -(10.0 + 5.0 / std::tan(32.0 * 3.14159265358979323846 / 180.0)));
    auto count = [&](const std::string& text) {
        return std::count_if(out.lines.begin(), out.lines.end(), [&](const std::string& line) {
            return line.find(text) != std::string::npos;
        });
    };
    write("fagor_tools.tab", "T1 D1 NOSEA55 CUTA93\n");
    ASSERT_EQ(run(program), interp::RunStatus::Finished) << diagnostics();
    EXPECT_EQ(count(bridgeEnd), 1) << bridgeEnd << testing::PrintToString(out.lines);
    EXPECT_EQ(count("X5.0000 Z-15.0000"), 0);
    out.lines.clear();
    write("fagor_tools.tab", "T1 D1 NOSEA35 CUTA93\n");
    ASSERT_EQ(run(program), interp::RunStatus::Finished) << diagnostics();
    EXPECT_EQ(count(bridgeEnd), 0);
    EXPECT_EQ(count("LINE X5.0000 Z-15.0000 F0.100"), 1) << testing::PrintToString(out.lines);
}

TEST_F(FagorRun, ACoveTighterThanTheNoseIsMachinedAsFarAsTheNoseReaches) {
    // A half-round cove R1 about (Z-11, r20) in r20, nose R1.5 and no tool table: the check warns
    // at G68 (line 7 named), and the finishing pass runs over the arc of the nose resting on the
    // cove's edges (centre sqrt(1.5^2 - 1) = 1.1180 above r20, bottom at r19.6180), never at the
    // cove's bottom r19.
    write("fagor_tool_offsets.tab", "D1 F3 R1.5\n");
    const std::string program =
        "N1 G90 G95 F0.3 S800 T1 D1 M3\n"
        "N2 G00 X70 Z2\n"
        "N3 G68 X0 Z0 C3 D0.5 H0.1 S10 E20\n"
        "N4 M30\n"
        "N10 G01 X40 Z0\n"
        "G01 Z-10\n"
        "G02 X40 Z-12 R1\n"
        "G01 Z-30\n"
        "N20 G01 X60 Z-30\n";
    ASSERT_EQ(run(program), interp::RunStatus::Finished) << diagnostics();
    EXPECT_EQ(diagnostics(), (root / "program.pim").string() +
                                 ":3:4: warning: tool T1 cannot reach the profile at line 7: the "
                                 "arc's radius 1 is smaller than the nose radius 1.5\n");
    auto count = [&](const std::string& text) {
        return std::count_if(out.lines.begin(), out.lines.end(), [&](const std::string& line) {
            return line.find(text) != std::string::npos;
        });
    };
    EXPECT_EQ(count("ARC X19.6180 Z-11.0000 CENTER Z-11.0000 X21.1180 PLANE ZX SWEEP -41.8103 "
                    "F0.100"),
              1)
        << testing::PrintToString(out.lines);
    EXPECT_EQ(count("X19.0000"), 0);
    // A nose of R1 fits: the cove is followed.
    out.lines.clear();
    write("fagor_tool_offsets.tab", "D1 F3 R1\n");
    ASSERT_EQ(run(program), interp::RunStatus::Finished) << diagnostics();
    EXPECT_EQ(diagnostics(), "");
    EXPECT_EQ(count("ARC X19.0000 Z-11.0000 CENTER Z-11.0000 X20.0000"), 1)
        << testing::PrintToString(out.lines);
}

TEST_F(FagorRun, G84RefusesAHollowArcTighterThanTheNose) {
    // G84 from (Z0, r10) to (Z-1, r11) about (Z0, r11): a hollow quarter of R1 (it bulges away
    // from the call point). With the nose R1.5 it is refused at the cycle; R0.8 runs; the
    // convex quarter about (Z-1, r10) runs with R1.5.
    write("fagor_tool_offsets.tab", "D1 F3 R1.5\n");
    const std::string hollow =
        "N1 G90 G95 F0.3 S800 T1 D1 M3\n"
        "N2 G00 X60 Z5\n"
        "N3 G84 X20 Z0 Q22 R-1 C1 I1 K0\n"
        "N4 M30\n";
    EXPECT_EQ(run(hollow), interp::RunStatus::Failed);
    EXPECT_EQ(diagnostics(), (root / "program.pim").string() +
                                 ":3:4: error: the arc's radius 1 is smaller than the tool nose "
                                 "radius 1.5: the nose cannot follow it\n");
    write("fagor_tool_offsets.tab", "D1 F3 R0.8\n");
    EXPECT_EQ(run(hollow), interp::RunStatus::Finished) << diagnostics();
    write("fagor_tool_offsets.tab", "D1 F3 R1.5\n");
    std::string convex = hollow;
    convex.replace(convex.find("I1 K0"), 5, "I0 K-1");
    EXPECT_EQ(run(convex), interp::RunStatus::Finished) << diagnostics();
}

TEST_F(FagorRun, CycleFeedsKeepThePerRevolutionModeWhenTheCallHasNoFeed) {
    // G95 without any F: the roughing passes run at the maximum feed (per minute, as F0), but
    // the finishing pass H0.1 is 0.1 mm/rev: the stream switches to per revolution before it
    // (it stayed per minute: 0.1 mm/min). G68 leaves the feed H active: N4 runs at 0.1 mm/rev.
    const std::string program =
        "N1 G90 G95 S800 M3\n"
        "N2 G00 X70 Z2\n"
        "N3 G68 X40 Z0 C5 H0.1 S10 E20\n"
        "N4 G01 X80\n"
        "N5 M30\n"
        "N10 G01 X40 Z-10\n"
        "N20 G01 X60\n";
    ASSERT_EQ(run(program), interp::RunStatus::Finished) << diagnostics();
    const auto at = [&](const std::string& line) {
        return std::find(out.lines.begin(), out.lines.end(), line) - out.lines.begin();
    };
    const auto perRevolution = at("3:1 N3 FEEDMODE PER-REV");
    const auto finishing = at("3:1 N3 LINE X20.0000 Z0.0000 F0.100");
    ASSERT_LT(finishing, static_cast<long>(out.lines.size())) << testing::PrintToString(out.lines);
    EXPECT_EQ(perRevolution + 1, finishing) << testing::PrintToString(out.lines);
    EXPECT_EQ(at("4:1 N4 LINE X40.0000 Z2.0000 F0.100") + 1, at("5:1 N5 SPINDLE STOP S800.000"))
        << testing::PrintToString(out.lines);
}

TEST_F(FagorRun, ANewSpeedWhileTheSpindleTurnsIsOneSpindleLine) {
    // The spindle turns at S800. N2: S and M3 in one block, M3 sends the new speed (the S used to
    // send it first: two lines). N3: S alone sends it. N4: S with M4 reverses at the new speed.
    // N5: the machine's M table runs M5 after the block's motion, so the S900 reaches the
    // spindle first (for that motion) and M5 then stops it: two commands, not a duplicate.
    const std::string program =
        "N1 G90 S800 M3\n"
        "N2 S1200 M3\n"
        "N3 S1500\n"
        "N4 S1000 M4\n"
        "N5 S900 M5\n"
        "N6 M30\n";
    ASSERT_EQ(run(program), interp::RunStatus::Finished) << diagnostics();
    std::vector<std::string> spindle;
    for (const std::string& line : out.lines) {
        if (line.find(" SPINDLE ") != std::string::npos) spindle.push_back(line);
    }
    const std::vector<std::string> expected = {
        "1:1 N1 SPINDLE CW S800.000",  "2:1 N2 SPINDLE CW S1200.000",
        "3:1 N3 SPINDLE CW S1500.000", "4:1 N4 SPINDLE CCW S1000.000",
        "5:1 N5 SPINDLE CCW S900.000", "5:1 N5 SPINDLE STOP S900.000"};
    EXPECT_EQ(spindle, expected);
}

TEST_F(FagorRun, CycleFeedsAreInInchesUnderG70) {
    // G70: F0.01 in/rev is 0.254 mm/rev, the finishing feed H0.004 of G81 0.1016 mm/rev (it
    // was sent as 0.004 mm/rev).
    const std::string program =
        "N1 G70 G90 G95 F0.01 S800 M3\n"
        "N2 G00 X2.8 Z0.1\n"
        "N3 G81 X2.4 Z0 Q2.4 R-0.4 C0.2 H0.004\n"
        "N4 M30\n";
    ASSERT_EQ(run(program), interp::RunStatus::Finished) << diagnostics();
    const auto count = [&](const std::string& line) {
        return std::count(out.lines.begin(), out.lines.end(), line);
    };
    EXPECT_EQ(count("3:1 N3 LINE X30.4800 Z-10.1600 F0.254"), 1)
        << testing::PrintToString(out.lines);
    EXPECT_EQ(count("3:1 N3 LINE X30.4800 Z-10.1600 F0.102"), 1)
        << testing::PrintToString(out.lines);
}

}  // namespace
}  // namespace kerf::fagor
