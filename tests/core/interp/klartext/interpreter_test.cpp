#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "core/base/atomic_file.h"
#include "core/interp/klartext/klartext_interpreter.h"
#include "core/machine/machine_loader.h"
#include "core/program/mapped_copy.h"

namespace kerf::klartext {
namespace {

namespace fs = std::filesystem;

class Recorder : public canon::Sink {
public:
    void consume(const canon::Command& c) override { commands.push_back(c); }
    std::vector<canon::Command> commands;
    template <typename T>
    std::vector<T> all() const {
        std::vector<T> out;
        for (const auto& c : commands) {
            if (const auto* t = std::get_if<T>(&c.body)) out.push_back(*t);
        }
        return out;
    }
};

class InterpreterTest : public testing::Test {
protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("kerf_interp_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
        machine = *machine::loadMachine("mill");
    }
    void TearDown() override { fs::remove_all(dir); }

    std::unique_ptr<KlartextInterpreter> make() {
        KlartextSettings settings;
        settings.machine = &machine;
        settings.ncRoot = dir;
        settings.remanentFile = dir / "qr.txt";
        return std::make_unique<KlartextInterpreter>(sources, settings);
    }
    // Runs a program to its end, answering syncs with the given position.
    interp::RunStatus runText(KlartextInterpreter& k, const std::string& text,
                              const Pose* world = nullptr) {
        const fs::path path = dir / "P.H";
        writeFileAtomically(path, text);
        if (!k.load(path)) return interp::RunStatus::Failed;
        for (;;) {
            auto status = k.run(out, 1000);
            if (status == interp::RunStatus::NeedsSync) {
                interp::WorldSnapshot w;
                w.position = world ? *world : k.nominalPosition();
                k.resume(w);
                continue;
            }
            if (status != interp::RunStatus::BudgetUsed) return status;
        }
    }

    fs::path dir;
    machine::MachineConfig machine;
    program::SourceRegistry sources;
    Recorder out;
};

TEST_F(InterpreterTest, RemanentParametersSurviveARun) {
    {
        auto k = make();
        EXPECT_EQ(runText(*k, "0 BEGIN PGM A MM\n1 QR5 = 42\n2 END PGM A MM\n"),
                  interp::RunStatus::Finished);
    }
    auto k = make();
    EXPECT_EQ(runText(*k, "0 BEGIN PGM A MM\n1 L X+QR5 Y+0 Z+0 R0 FMAX\n2 END PGM A MM\n"),
              interp::RunStatus::Finished);
    EXPECT_DOUBLE_EQ(k->nominalPosition()[Axis::X], 42);
}

// A damaged QR file ("nan", "inf", "5xyz" after the '=') was read as NaN or 5 and rewritten at the
// end of the run without the damage: now it is an error at its line and column, nothing runs and
// the file stays as it is.
TEST_F(InterpreterTest, ADamagedRemanentFileIsAnErrorAndStaysAsItIs) {
    const std::string program = "0 BEGIN PGM A MM\n1 QR5 = 1\n2 END PGM A MM\n";
    for (const std::string bad : {"nan", "inf", "-inf", "5xyz", "1e999", ""}) {
        const std::string damaged = "QR1=2\nQR3=" + bad + "\n";
        writeFileAtomically(dir / "qr.txt", damaged);
        auto k = make();
        EXPECT_EQ(runText(*k, program), interp::RunStatus::Failed) << bad;
        ASSERT_FALSE(k->diagnostics().empty()) << bad;
        const Diagnostic& d = k->diagnostics().front();
        EXPECT_EQ(d.file, (dir / "qr.txt").string());
        EXPECT_EQ(d.line, 2u) << bad;
        EXPECT_EQ(d.column, 5u) << bad;  // the first character after "QR3="
        EXPECT_EQ(d.severity, Severity::Error);
        EXPECT_TRUE(out.commands.empty()) << bad;
        EXPECT_EQ(*readWholeFile(dir / "qr.txt"), damaged) << bad;
    }
    // The same file with a number there is read and written back with QR5.
    writeFileAtomically(dir / "qr.txt", "QR1=2\nQR3=-0.5\n");
    auto k = make();
    EXPECT_EQ(runText(*k, program), interp::RunStatus::Finished);
    EXPECT_EQ(*readWholeFile(dir / "qr.txt"), "QR1=2\nQR3=-0.5\nQR5=1\n");
}

TEST_F(InterpreterTest, FPrintWritesInsideTheNcRoot) {
    writeFileAtomically(dir / "MASK.A", "\"R = %5.2F\", Q1;\n");
    auto k = make();
    EXPECT_EQ(runText(*k,
                      "0 BEGIN PGM A MM\n1 Q1 = 2.5\n2 FN 16: F-PRINT MASK.A / OUT.TXT\n"
                      "3 END PGM A MM\n"),
              interp::RunStatus::Finished);
    auto text = readWholeFile(dir / "OUT.TXT");
    ASSERT_TRUE(text.ok());
    EXPECT_EQ(*text, "R =  2.50\n");
    auto bad = make();
    EXPECT_EQ(runText(*bad,
                      "0 BEGIN PGM A MM\n1 FN 16: F-PRINT MASK.A / ../../OUT.TXT\n"
                      "2 END PGM A MM\n"),
              interp::RunStatus::Failed);
}

TEST_F(InterpreterTest, WaitForSyncWaitsForTheMachineAndContinuesFromWhereItIs) {
    // FN 20 stops the read-ahead: the interpreter asks for the machine (a sync) after the
    // move before it, and an incremental move after it starts from where the machine is.
    const std::string text =
        "0 BEGIN PGM A MM\n1 L X+10 Y+0 Z+0 R0 FMAX\n2 FN 20: WAIT FOR SYNC\n"
        "3 L IX+5 FMAX\n4 END PGM A MM\n";
    writeFileAtomically(dir / "P.H", text);
    auto k = make();
    ASSERT_TRUE(k->load(dir / "P.H"));
    EXPECT_EQ(k->run(out, 1000), interp::RunStatus::NeedsSync);
    EXPECT_DOUBLE_EQ(k->nominalPosition()[Axis::X], 10);  // block 3 not read yet
    interp::WorldSnapshot world;
    world.position = k->nominalPosition();
    world.position[Axis::X] = 12;  // the operator moved the axis at a stop
    k->resume(world);
    EXPECT_EQ(k->run(out, 1000), interp::RunStatus::Finished);
    EXPECT_DOUBLE_EQ(k->nominalPosition()[Axis::X], 17);

    auto other = make();
    EXPECT_EQ(runText(*other, "0 BEGIN PGM A MM\n1 FN 20: WAIT FOR I1\n2 END PGM A MM\n"),
              interp::RunStatus::Failed);
}

TEST_F(InterpreterTest, ContinuesFromWhereTheOperatorMovedTheMachine) {
    // After a stop the machine was jogged to X50: FN 18 reads it and L IX moves from there.
    Pose jogged;
    jogged[Axis::X] = 50;
    auto k = make();
    EXPECT_EQ(runText(*k,
                      "0 BEGIN PGM A MM\n1 L X+10 Y+0 Z+0 R0 FMAX\n2 STOP\n"
                      "3 FN 18: SYSREAD Q1 = ID270 NR1 IDX1\n4 L IX+5 FMAX\n5 END PGM A MM\n",
                      &jogged),
              interp::RunStatus::Finished);
    EXPECT_DOUBLE_EQ(k->parameters().get({QKind::Q, 1}), 50);
    EXPECT_DOUBLE_EQ(k->nominalPosition()[Axis::X], 55);
}

TEST_F(InterpreterTest, BackgroundCheckGivesTheSameResult) {
    const char* program =
        "0 BEGIN PGM A MM\n1 L X+0 Y+0 Z+0 R0 FMAX\n2 LBL 1\n3 L IX+1 F100\n"
        "4 CALL LBL 1 REP 3\n5 END PGM A MM\n";
    writeFileAtomically(dir / "B.H", program);
    auto k = make();
    ASSERT_TRUE(k->load(dir / "B.H", KlartextInterpreter::CheckMode::Background));
    while (k->run(out, 2) == interp::RunStatus::BudgetUsed) {
    }
    EXPECT_FALSE(k->checkFailed());
    EXPECT_DOUBLE_EQ(k->nominalPosition()[Axis::X], 4);
    // With an error near the end the run is rejected even though it started.
    writeFileAtomically(dir / "C.H",
                        "0 BEGIN PGM A MM\n1 L X+5 Y+0 Z+0 R0 FMAX\n2 BOGUS\n"
                        "3 END PGM A MM\n");
    auto bad = make();
    ASSERT_TRUE(bad->load(dir / "C.H", KlartextInterpreter::CheckMode::Background));
    while (bad->run(out, 1) == interp::RunStatus::BudgetUsed) {
    }
    EXPECT_TRUE(bad->checkFailed());
    ASSERT_FALSE(bad->diagnostics().empty());
    EXPECT_EQ(bad->diagnostics().front().line, 3u);
}

// A program longer than kMappedCopyMinBytes runs from a mapped copy whose pages are dropped
// behind the run: calling a subroutine at its start from its end reads those pages again.
TEST_F(InterpreterTest, ALongProgramCallsASubroutineItsRunHasLeftFarBehind) {
    std::string text =
        "0 BEGIN PGM A MM\n1 L X+0 Y+0 Z+0 R0 FMAX\n2 FN 9: IF +0 EQU +0 GOTO LBL 2\n"
        "3 LBL 1\n4 L IX+1 F100\n5 LBL 0\n6 LBL 2\n";
    int fillers = 0;
    while (text.size() < 6 * program::kTextReleaseStep) {
        text += "L Y+" + std::to_string(fillers % 7 + 1) + " F100\n";
        ++fillers;
    }
    text += "CALL LBL 1\nCALL LBL 1\nEND PGM A MM\n";
    writeFileAtomically(dir / "LONG.H", text);
    ASSERT_GE(text.size(), program::kMappedCopyMinBytes);

    class MoveCounter : public canon::Sink {
    public:
        void consume(const canon::Command& c) override {
            moves += std::holds_alternative<canon::LinearMove>(c.body);
        }
        int moves = 0;
    } counter;
    auto k = make();
    ASSERT_TRUE(k->load(dir / "LONG.H", KlartextInterpreter::CheckMode::Background));
    while (k->run(counter, 10000) == interp::RunStatus::BudgetUsed) {
    }
    EXPECT_FALSE(k->checkFailed());
    EXPECT_EQ(counter.moves, fillers + 2);
    EXPECT_DOUBLE_EQ(k->nominalPosition()[Axis::X], 2);
    EXPECT_DOUBLE_EQ(k->nominalPosition()[Axis::Y], (fillers - 1) % 7 + 1);
}

TEST_F(InterpreterTest, TheCheckFollowsProgramCalls) {
    // A called program that is missing, or has an error, fails the main program's check at the
    // call (or at the callee's own line), before the first block runs.
    writeFileAtomically(dir / "M.H",
                        "0 BEGIN PGM M MM\n1 L X+1 R0 FMAX\n2 CALL PGM GONE.H\n"
                        "3 END PGM M MM\n");
    auto missing = make();
    EXPECT_FALSE(missing->load(dir / "M.H"));
    ASSERT_TRUE(hasErrors(missing->diagnostics()));
    const Diagnostic& call = missing->diagnostics().back();
    EXPECT_EQ(call.file, (dir / "M.H").string());
    EXPECT_EQ(call.line, 3u);
    EXPECT_EQ(call.column, 12u);  // "2 CALL PGM GONE.H": the name starts at column 12

    // M2 calls A, A calls B (without extension), B has an unknown block on its line 2.
    writeFileAtomically(dir / "M2.H", "0 BEGIN PGM M2 MM\n1 CALL PGM A.H\n2 END PGM M2 MM\n");
    writeFileAtomically(dir / "A.H", "0 BEGIN PGM A MM\n1 CALL PGM B\n2 END PGM A MM\n");
    writeFileAtomically(dir / "B.H",
                        "0 BEGIN PGM B MM\n1 L X+1 R0 FMAX\n2 BOGUS\n"
                        "3 END PGM B MM\n");
    auto nested = make();
    EXPECT_FALSE(nested->load(dir / "M2.H"));
    ASSERT_TRUE(hasErrors(nested->diagnostics()));
    EXPECT_EQ(nested->diagnostics().front().file, (dir / "B.H").string());
    EXPECT_EQ(nested->diagnostics().front().line, 3u);

    // Repaired, the same chain passes, and a program calling itself is checked once.
    writeFileAtomically(dir / "B.H", "0 BEGIN PGM B MM\n1 CALL PGM A.H\n2 END PGM B MM\n");
    auto fine = make();
    EXPECT_TRUE(fine->load(dir / "M2.H"));
    EXPECT_FALSE(hasErrors(fine->diagnostics()));
}

TEST_F(InterpreterTest, CallSelectedPgmCallsTheProgramOfTheLastSelPgm) {
    // SUB moves 5 mm along X incrementally; it is selected by name, then by a string parameter.
    writeFileAtomically(dir / "SUB.H", "0 BEGIN PGM SUB MM\n1 L IX+5 F100\n2 END PGM SUB MM\n");
    auto k = make();
    EXPECT_EQ(runText(*k,
                      "0 BEGIN PGM A MM\n1 L X+0 Y+0 Z+0 R0 FMAX\n2 SEL PGM \"SUB.H\"\n"
                      "3 L Y+1 FMAX\n4 CALL SELECTED PGM\n5 QS1 = \"SUB\"\n6 SEL PGM QS1\n"
                      "7 CALL SELECTED PGM\n8 END PGM A MM\n"),
              interp::RunStatus::Finished);
    EXPECT_DOUBLE_EQ(k->nominalPosition()[Axis::X], 10);
    EXPECT_DOUBLE_EQ(k->nominalPosition()[Axis::Y], 1);

    auto none = make();
    EXPECT_EQ(runText(*none, "0 BEGIN PGM A MM\n1 CALL SELECTED PGM\n2 END PGM A MM\n"),
              interp::RunStatus::Failed);
    ASSERT_FALSE(none->diagnostics().empty());
    EXPECT_EQ(none->diagnostics().back().messageTemplate,
              "CALL SELECTED PGM: no program was selected with SEL PGM");

    // A selected program named in the text is checked before the run, like CALL PGM.
    writeFileAtomically(dir / "S.H", "0 BEGIN PGM S MM\n1 SEL PGM GONE.H\n2 END PGM S MM\n");
    auto missing = make();
    EXPECT_FALSE(missing->load(dir / "S.H"));
    ASSERT_TRUE(hasErrors(missing->diagnostics()));
    EXPECT_EQ(missing->diagnostics().back().line, 2u);
}

TEST_F(InterpreterTest, M120LookAheadIsAWholeNumberOfBlocksUpTo99) {
    auto k = make();
    EXPECT_EQ(runText(*k, "0 BEGIN PGM A MM\n1 L X+0 Y+0 Z+0 R0 F100 M120 LA99\n2 END PGM A MM\n"),
              interp::RunStatus::Finished);
    auto bad = make();
    EXPECT_EQ(runText(*bad,
                      "0 BEGIN PGM A MM\n1 L X+0 Y+0 Z+0 R0 F100 M120 LA100\n"
                      "2 END PGM A MM\n"),
              interp::RunStatus::Failed);
    ASSERT_FALSE(bad->diagnostics().empty());
    EXPECT_EQ(bad->diagnostics().back().messageTemplate,
              "M120 LA: a whole number of blocks from 0 to 99");
}

TEST_F(InterpreterTest, NothingIsWrittenWhenACalledProgramHasAnError) {
    // The background check covers the called programs too: the F-PRINT before the call to a
    // faulty program must not write.
    writeFileAtomically(dir / "MASK.A", "\"X\";\n");
    writeFileAtomically(dir / "SUB.H", "0 BEGIN PGM SUB MM\n1 BOGUS\n2 END PGM SUB MM\n");
    writeFileAtomically(dir / "W.H",
                        "0 BEGIN PGM W MM\n1 FN 16: F-PRINT MASK.A / OUT.TXT\n"
                        "2 CALL PGM SUB.H\n3 END PGM W MM\n");
    auto k = make();
    ASSERT_TRUE(k->load(dir / "W.H", KlartextInterpreter::CheckMode::Background));
    while (k->run(out, 1) == interp::RunStatus::BudgetUsed) {
    }
    EXPECT_TRUE(k->checkFailed());
    EXPECT_FALSE(fs::exists(dir / "OUT.TXT"));
}

TEST_F(InterpreterTest, NothingIsWrittenWhenCycle12CallsAFaultyProgram) {
    // Cycle 12 names its program in the CYCL DEF: the check reads it like a CALL PGM, so the
    // F-PRINT before the cycle call must not write.
    writeFileAtomically(dir / "MASK.A", "\"X\";\n");
    writeFileAtomically(dir / "SUB.H", "0 BEGIN PGM SUB MM\n1 BOGUS\n2 END PGM SUB MM\n");
    writeFileAtomically(dir / "W.H",
                        "0 BEGIN PGM W MM\n1 FN 16: F-PRINT MASK.A / OUT.TXT\n"
                        "2 CYCL DEF 12.0 PGM CALL\n3 CYCL DEF 12.1 PGM SUB.H\n"
                        "4 CYCL CALL\n5 END PGM W MM\n");
    auto k = make();
    ASSERT_TRUE(k->load(dir / "W.H", KlartextInterpreter::CheckMode::Background));
    while (k->run(out, 1) == interp::RunStatus::BudgetUsed) {
    }
    EXPECT_TRUE(k->checkFailed());
    EXPECT_FALSE(fs::exists(dir / "OUT.TXT"));

    // A cycle 12 program that does not exist fails the check at its name.
    writeFileAtomically(dir / "M.H",
                        "0 BEGIN PGM M MM\n1 CYCL DEF 12.0 PGM CALL\n"
                        "2 CYCL DEF 12.1 PGM NOPE.H\n3 END PGM M MM\n");
    auto missing = make();
    EXPECT_FALSE(missing->load(dir / "M.H"));
    ASSERT_TRUE(hasErrors(missing->diagnostics()));
    const Diagnostic& d = missing->diagnostics().front();
    EXPECT_EQ(d.line, 3u);
    EXPECT_EQ(d.column, 21u);  // "2 CYCL DEF 12.1 PGM NOPE.H": the name starts at column 21

    // Repaired, the same program runs the called program's blocks.
    writeFileAtomically(dir / "SUB.H", "0 BEGIN PGM SUB MM\n1 L Z+7 R0 FMAX\n2 END PGM SUB MM\n");
    auto fine = make();
    ASSERT_EQ(runText(*fine,
                      "0 BEGIN PGM P MM\n1 CYCL DEF 12.0 PGM CALL\n"
                      "2 CYCL DEF 12.1 PGM SUB.H\n3 CYCL CALL\n4 END PGM P MM\n"),
              interp::RunStatus::Finished);
}

TEST_F(InterpreterTest, ATableTheProgramSelectsMustBeReadableBeforeItRuns) {
    // SEL PATTERN and SEL TABLE name their tables literally: a missing or unreadable one fails
    // the check at the name, so a run cannot stop there after the program's writes.
    writeFileAtomically(dir / "BAD.PNT", "not a point table\n");
    writeFileAtomically(dir / "HOLES.PNT",
                        "BEGIN HOLES.PNT MM\nNR  X    Y    Z\n0   +10  +10  +0\n[END]\n");
    const std::string program = "0 BEGIN PGM S MM\n1 SEL PATTERN \"NAME\"\n2 END PGM S MM\n";
    auto check = [&](const std::string& table) {
        std::string text = program;
        text.replace(text.find("NAME"), 4, table);
        writeFileAtomically(dir / "S.H", text);
        auto k = make();
        const bool loaded = k->load(dir / "S.H");
        return std::make_pair(loaded, k->diagnostics());
    };
    auto [missingLoads, missing] = check("NOPE");
    EXPECT_FALSE(missingLoads);
    ASSERT_TRUE(hasErrors(missing));
    EXPECT_EQ(missing.front().line, 2u);
    EXPECT_EQ(missing.front().column, 16u);  // `1 SEL PATTERN "NOPE"`: NOPE starts at 16
    EXPECT_NE(missing.front().message().find("point table NOPE"), std::string::npos);
    auto [badLoads, bad] = check("BAD");
    EXPECT_FALSE(badLoads);
    EXPECT_TRUE(hasErrors(bad));
    auto [goodLoads, good] = check("HOLES");  // the extension may be left out
    EXPECT_TRUE(goodLoads);
    EXPECT_FALSE(hasErrors(good));

    writeFileAtomically(dir / "T.H",
                        "0 BEGIN PGM T MM\n1 SEL TABLE \"NODATUMS.D\"\n2 END PGM T MM\n");
    auto datums = make();
    EXPECT_FALSE(datums->load(dir / "T.H"));
    ASSERT_TRUE(hasErrors(datums->diagnostics()));
    EXPECT_NE(datums->diagnostics().front().message().find("datum table NODATUMS.D"),
              std::string::npos);
}

TEST_F(InterpreterTest, AnAxisTheMachineLacksIsAnError) {
    // The built-in mill has X, Y and Z: an A word is refused at its column instead of being
    // dropped from the move.
    ASSERT_EQ(machine.enabledAxisLetters(), "XYZ");
    writeFileAtomically(dir / "R.H",
                        "0 BEGIN PGM R MM\n1 L X+10 IA+90 R0 FMAX\n"
                        "2 END PGM R MM\n");
    auto k = make();
    EXPECT_FALSE(k->load(dir / "R.H"));
    ASSERT_TRUE(hasErrors(k->diagnostics()));
    const Diagnostic& axis = k->diagnostics().front();
    EXPECT_EQ(axis.line, 2u);
    EXPECT_EQ(axis.column, 10u);  // "1 L X+10 IA+90": IA starts at column 10
    EXPECT_EQ(axis.message(), "this machine has no axis A");
    // A machine that has the axis accepts the same block.
    machine::AxisConfig rotary;
    rotary.letter = 'A';
    machine.axes.push_back(rotary);
    auto fourAxes = make();
    EXPECT_TRUE(fourAxes->load(dir / "R.H"));
}

TEST_F(InterpreterTest, ProgramCallsCannotRecurseForever) {
    writeFileAtomically(dir / "SELF.H",
                        "0 BEGIN PGM SELF MM\n1 CALL PGM SELF.H\n2 END PGM SELF MM\n");
    auto k = make();
    ASSERT_TRUE(k->load(dir / "SELF.H"));
    while (k->run(out, 100) == interp::RunStatus::BudgetUsed) {
    }
    EXPECT_EQ(k->diagnostics().back().code, "nesting");
}

TEST_F(InterpreterTest, HelixSignMustMatchDirection) {
    auto k = make();
    EXPECT_EQ(runText(*k,
                      "0 BEGIN PGM A MM\n1 CC X+0 Y+0\n2 L X+5 Y+0 Z+0 R0 FMAX\n"
                      "3 CP IPA-90 DR+ F100\n4 END PGM A MM\n"),
              interp::RunStatus::Failed);
    EXPECT_EQ(k->diagnostics().back().message(), "the sign of IPA does not match DR");
}

TEST_F(InterpreterTest, ToolAxisMovesWaitInsideCompensation) {
    // L Z-moves between compensated elements stay at the corner's tool position.
    writeFileAtomically(dir / "TOOL.T",
                        "BEGIN TOOL.T MM\nT    NAME    L      R\n1    A       +10    +2\n[END]\n");
    auto tools = tables::ToolTable::load(dir / "TOOL.T");
    ASSERT_TRUE(tools.ok());
    KlartextSettings settings;
    settings.machine = &machine;
    settings.ncRoot = dir;
    settings.tools = &*tools;
    KlartextInterpreter k(sources, settings);
    writeFileAtomically(dir / "Z.H",
                        "0 BEGIN PGM Z MM\n1 TOOL CALL 1 Z\n2 L X+0 Y+0 Z+0 R0 FMAX\n"
                        "3 L X+10 RL F100\n4 L X+20\n5 L IZ-1\n6 L Y+10\n7 L Y+20 R0\n"
                        "8 END PGM Z MM\n");
    ASSERT_TRUE(k.load(dir / "Z.H"));
    while (k.run(out, 100) == interp::RunStatus::BudgetUsed) {
    }
    auto lines = out.all<canon::LinearMove>();
    // Activation to (10,2); then (20,2)... the corner at (20,0) is a left turn (inside for RL):
    // the offsets y=2 and x=18 meet at (18,2); Z goes down there; then up the side x=18.
    ASSERT_GE(lines.size(), 4u);
    EXPECT_NEAR(lines[1].target[Axis::X], 18, 1e-9);
    EXPECT_NEAR(lines[1].target[Axis::Y], 2, 1e-9);
    EXPECT_NEAR(lines[2].target[Axis::X], 18, 1e-9);
    EXPECT_NEAR(lines[2].target[Axis::Z], -1, 1e-9);
    EXPECT_NEAR(lines[3].target[Axis::X], 18, 1e-9);
    EXPECT_NEAR(lines[3].target[Axis::Y], 10, 1e-9);
}

// Inputs the fuzzer found crashing the interpreter: they must give diagnostics instead.
TEST_F(InterpreterTest, FuzzerFindingsGiveDiagnostics) {
    const std::string longName(5000, 'x');
    const std::vector<std::string> programs = {
        "0 BEGIN PGM A MM\n1 CALL PGM ../" + longName + "\n2 END PGM A MM\n",
        "0 BEGIN PGM A MM\n1 FN 14: ERROR = 99999999999999999999\n2 FN 18: SYSREAD Q1 = "
        "ID99999999999999 NR-99999999999999\n"
        "3 END PGM A MM\n",
        "0 BEGIN PGM A MM\n2 CYCL DEF ~\n 200 DRILLING\n3 END PGM A MM\n",
        "0 BEGIN PGM A MM\n1 FN 26: TABOPEN .\n2 END PGM A MM\n",
        "0 BEGIN PGM A MM\n1 QS1 = \"ab\"\n2 QS2 = SUBSTR ( SRC_QS1 BEG99999999999999 "
        "LEN99999999999999 )\n"
        "3 END PGM A MM\n",
    };
    // The first four are errors; the fifth is a valid program (SUBSTR beyond the end is empty).
    for (size_t i = 0; i < programs.size(); ++i) {
        auto k = make();
        auto status = runText(*k, programs[i]);
        if (i < 4) {
            EXPECT_EQ(status, interp::RunStatus::Failed) << programs[i].substr(0, 60);
            EXPECT_TRUE(hasErrors(k->diagnostics()));
        } else {
            EXPECT_EQ(status, interp::RunStatus::Finished);
            EXPECT_EQ(k->parameters().getString(2), "");
        }
    }
}

}  // namespace
}  // namespace kerf::klartext

namespace kerf::klartext {
namespace {

// Spec §8: M functions in a contour subprogram are ignored. The M8 of LBL 1 used to switch the
// coolant on in the interpreter's state without a command, so END PGM then switched it off.
TEST_F(InterpreterTest, MFunctionsOfAContourSubprogramHaveNoEffect) {
    auto k = make();
    const std::string text =
        "0 BEGIN PGM P MM\n"
        "1 TOOL DEF 1 L+0 R+4\n"
        "2 TOOL CALL 1 Z S3000\n"
        "3 L Z+100 R0 FMAX\n"
        "4 CYCL DEF 14.0 CONTOUR\n"
        "5 CYCL DEF 14.1 CONTOUR LABEL 1\n"
        "6 CYCL DEF 20 CONTOUR DATA\n"
        "  Q1=-5 ;DEPTH\n  Q2=1\n  Q3=+0\n  Q4=+0\n  Q5=+0\n  Q6=2\n"
        "  Q7=+50\n  Q8=0\n  Q9=+1\n"
        "7 CYCL DEF 22 ROUGH-OUT\n"
        "  Q10=5\n  Q11=100\n  Q12=500\n  Q18=0\n  Q19=0\n"
        "8 CYCL CALL M3\n"
        "9 L Z+100 R0 FMAX M2\n"
        "10 LBL 1\n"
        "11 L X+10 Y+10 RL F200 M8\n"
        "12 L X+30\n"
        "13 L Y+30\n"
        "14 L X+10\n"
        "15 L Y+10\n"
        "16 LBL 0\n"
        "17 END PGM P MM\n";
    ASSERT_EQ(runText(*k, text), interp::RunStatus::Finished);
    EXPECT_TRUE(out.all<canon::CoolantControl>().empty());
}

}  // namespace
}  // namespace kerf::klartext

namespace kerf::klartext {
namespace {

// Cycle 23's approach arc in the stream. The 60 x 40 pocket about the origin, R5, allowances 0.5,
// depth 10: the first floor pass starts at Y-4.5 along +X (sl_cycles_test), so the
// quarter arc from Z-5 to Z-10 about Z-5 lies in the ZX plane: in ZX
// coordinates (Z, X) from (0, -5) to (-5, 0) about the centre, turning clockwise (-pi / 2).
// Rotated by 30 degrees (cycle 10) the arc's plane is no plane of two axes: straight pieces
// within 0.5 µm, r (1 - cos(s / 2)) <= 0.5e-3 with r = 5, ceil((pi / 2) / 0.0282843) = 56, every
// point at 5 from the rotated centre in the rotated vertical plane.
std::string floorFinishingProgram(const std::string& rotation) {
    return "0 BEGIN PGM P MM\n"
           "1 TOOL DEF 1 L+0 R+5\n"
           "2 TOOL CALL 1 Z S3000\n"
           "3 L Z+100 R0 FMAX\n" +
           rotation +
           "4 CYCL DEF 14.0 CONTOUR\n"
           "5 CYCL DEF 14.1 CONTOUR LABEL 1\n"
           "6 CYCL DEF 20 CONTOUR DATA\n"
           "  Q1=-10 ;DEPTH\n  Q2=1\n  Q3=+0.5\n  Q4=+0.5\n  Q5=+0\n  Q6=2\n"
           "  Q7=+50\n  Q8=0\n  Q9=+1\n"
           "7 CYCL DEF 23 FLOOR FINISHING\n"
           "  Q11=100\n  Q12=350\n  Q208=0\n"
           "8 CYCL CALL M3\n"
           "9 L Z+100 R0 FMAX M2\n"
           "10 LBL 1\n"
           "11 L X-30 Y-20 RL\n"
           "12 L X+30\n"
           "13 L Y+20\n"
           "14 L X-30\n"
           "15 L Y-20\n"
           "16 LBL 0\n"
           "17 END PGM P MM\n";
}

TEST_F(InterpreterTest, FloorFinishingApproachArcIsAZxArcOrPiecesWhenRotated) {
    {
        auto k = make();
        ASSERT_EQ(runText(*k, floorFinishingProgram("")), interp::RunStatus::Finished);
        std::vector<canon::ArcMove> vertical;
        for (const canon::ArcMove& a : out.all<canon::ArcMove>()) {
            if (a.plane != Plane::XY) vertical.push_back(a);
        }
        ASSERT_EQ(vertical.size(), 1u);
        const canon::ArcMove& a = vertical.front();
        EXPECT_EQ(a.plane, Plane::ZX);
        EXPECT_NEAR(a.target[Axis::X], -14.5, 1e-9);
        EXPECT_NEAR(a.target[Axis::Y], -4.5, 1e-9);
        EXPECT_NEAR(a.target[Axis::Z], -10.0, 1e-9);
        EXPECT_NEAR((a.center - Vec3(-14.5, -4.5, -5.0)).norm(), 0.0, 1e-9);
        EXPECT_NEAR(a.sweepRad, -kPi / 2.0, 1e-12);
        EXPECT_DOUBLE_EQ(a.feed, 100.0);
    }
    out.commands.clear();
    auto k = make();
    ASSERT_EQ(runText(*k, floorFinishingProgram("3 CYCL DEF 10.0 ROTATION\n"
                                                "3 CYCL DEF 10.1 ROT+30\n")),
              interp::RunStatus::Finished);
    for (const canon::ArcMove& a : out.all<canon::ArcMove>())
        EXPECT_EQ(a.plane, Plane::XY);
    const double c = std::cos(kPi / 6.0);
    const double s = std::sin(kPi / 6.0);
    const Vec3 centre(-14.5 * c + 4.5 * s, -14.5 * s - 4.5 * c, -5.0);
    const Vec3 normal(-s, c, 0.0);  // across the rotated X direction
    size_t pieces = 0;
    for (const canon::LinearMove& m : out.all<canon::LinearMove>()) {
        const Vec3 p = m.target.xyz();
        if (std::fabs((p - centre).norm() - 5.0) > 1e-9 || p.z() > -5.0 + 1e-9) continue;
        EXPECT_NEAR((p - centre).dot(normal), 0.0, 1e-9);
        ++pieces;
        if (p.z() < -10.0 + 1e-9) break;  // the floor (the first ring returns there later)
    }
    EXPECT_EQ(pieces, 56u);
}

}  // namespace
}  // namespace kerf::klartext
