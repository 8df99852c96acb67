#include "core/task/program_loader.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <unistd.h>

#include "core/machine/machine_loader.h"
#include "core/task/dry_run.h"

// The one loader of kerf run/check, the HMI and the editor's check: the same program gives the
// same verdict whether it comes from the file or from an editor's text.
namespace kerf::task {
namespace {

namespace fs = std::filesystem;

class ProgramLoaderTest : public testing::Test {
protected:
    void SetUp() override {
        root = fs::temp_directory_path() / ("kerf_loader_" + std::to_string(::getpid()));
        fs::remove_all(root);
        fs::create_directories(root);
        std::ofstream(root / "TOOL.T") << "BEGIN TOOL.T MM\nT    NAME   L      R\n"
                                          "1    MILL   +50    +4\n[END]\n";
        mill = *machine::loadMachine("mill");
    }
    void TearDown() override { fs::remove_all(root); }

    // From the file, then from the same text as the editor holds it.
    std::pair<LoadedProgram, LoadedProgram> loadBoth(const std::string& name,
                                                     const std::string& text) {
        std::ofstream(root / name) << text;
        ProgramRequest request;
        request.path = root / name;
        request.ncRoot = root;
        LoadedProgram file = loadProgram(mill, request);
        request.text = text;
        return {std::move(file), loadProgram(mill, request)};
    }

    fs::path root;
    machine::MachineConfig mill;
};

TEST_F(ProgramLoaderTest, AToolNeitherInTheTableNorDefinedFailsTheCheckAsTheRunWould) {
    const auto [file, text] = loadBoth("T.H",
                                       "0 BEGIN PGM T MM\n1 TOOL CALL 1 Z S1000\n"
                                       "2 TOOL CALL 77 Z\n3 END PGM T MM\n");
    for (const LoadedProgram* loaded : {&file, &text}) {
        EXPECT_FALSE(loaded->ready);
        const DiagnosticList all = loaded->diagnostics();
        ASSERT_EQ(all.size(), 1u);
        EXPECT_EQ(all[0].line, 3u);
        EXPECT_EQ(all[0].message(), "tool 77 is not in the tool table");
    }
    // Defined in the program (TOOL DEF), or named as in the table: it runs.
    const auto [defined, definedText] =
        loadBoth("D.H",
                 "0 BEGIN PGM D MM\n1 TOOL DEF 77 L+10 R+3\n2 TOOL CALL 77 Z S1000\n"
                 "3 TOOL CALL \"MILL\" Z\n4 END PGM D MM\n");
    EXPECT_TRUE(defined.ready) << defined.diagnostics().front().message();
    EXPECT_TRUE(definedText.ready);
    ASSERT_NE(defined.tools, nullptr);
    EXPECT_EQ(defined.tools->byNumber(1)->length, 50.0);
}

TEST_F(ProgramLoaderTest, TheFileNameDecidesTheDialectAndAnUnreadableTableStopsTheLoad) {
    const auto [iso, isoText] = loadBoth("P.I",
                                         "%P G71 *\nN1 T1 G17 S1000 *\nN2 G00 G90 X+0 *\n"
                                         "N99999999 %P G71 *\n");
    EXPECT_EQ(iso.dialect, program::Dialect::TncIso);
    EXPECT_TRUE(iso.ready);
    EXPECT_TRUE(isoText.ready);
    std::ofstream(root / "TOOL.T") << "not a tool table\n";
    const auto [broken, brokenText] = loadBoth("B.H", "0 BEGIN PGM B MM\n1 END PGM B MM\n");
    EXPECT_FALSE(broken.ready);
    EXPECT_EQ(broken.interpreter, nullptr);
    ASSERT_FALSE(broken.setupDiagnostics.empty());
    EXPECT_NE(broken.setupDiagnostics.front().file.find("TOOL.T"), std::string::npos);
}

// kerf run stops at a feed move before any feed is programmed: the check says so at that block.
// Where the order of execution is not the file's (a subprogram sets the feed), it stays silent.
TEST_F(ProgramLoaderTest, AFeedMoveBeforeAnyFeedFailsTheCheck) {
    const auto [missing, missingText] =
        loadBoth("F.H",
                 "0 BEGIN PGM F MM\n1 TOOL CALL 1 Z S1000\n2 L Z+5 R0 FMAX\n"
                 "3 L M3\n4 L X+10 Y+0\n5 END PGM F MM\n");
    for (const LoadedProgram* loaded : {&missing, &missingText}) {
        EXPECT_FALSE(loaded->ready);
        const DiagnosticList all = loaded->diagnostics();
        ASSERT_EQ(all.size(), 1u);
        EXPECT_EQ(all[0].line, 5u);
        EXPECT_EQ(all[0].message(), "feed rate is missing");
    }
    const auto [given, givenText] = loadBoth(
        "G.H", "0 BEGIN PGM G MM\n1 TOOL CALL 1 Z S1000\n2 L X+10 F200\n3 L Y+5\n4 END PGM G MM\n");
    EXPECT_TRUE(given.ready);
    const auto [called, calledText] =
        loadBoth("S.H",
                 "0 BEGIN PGM S MM\n1 TOOL CALL 1 Z S1000\n2 CALL LBL 1\n3 L X+10\n"
                 "4 M30\n5 LBL 1\n6 L Z+5 F100\n7 LBL 0\n8 END PGM S MM\n");
    EXPECT_TRUE(called.ready) << called.diagnostics().front().message();
}

// FAUTO is the feed of the TOOL CALL: without an F there the run stops at the FAUTO block.
TEST_F(ProgramLoaderTest, FautoWithoutAFeedInTheToolCallFailsTheCheck) {
    const auto [missing, missingText] =
        loadBoth("A.H",
                 "0 BEGIN PGM A MM\n1 TOOL CALL 1 Z S1000\n2 L Z+5 R0 FMAX\n"
                 "3 L X+10 Y+0 FAUTO\n4 END PGM A MM\n");
    for (const LoadedProgram* loaded : {&missing, &missingText}) {
        EXPECT_FALSE(loaded->ready);
        const DiagnosticList all = loaded->diagnostics();
        ASSERT_EQ(all.size(), 1u);
        EXPECT_EQ(all[0].line, 4u);
        EXPECT_EQ(all[0].message(), "FAUTO: the TOOL CALL block gave no feed rate F");
    }
    const auto [given, givenText] =
        loadBoth("B.H",
                 "0 BEGIN PGM B MM\n1 TOOL CALL 1 Z S1000 F250\n2 L X+10 FAUTO\n"
                 "3 END PGM B MM\n");
    EXPECT_TRUE(given.ready) << given.diagnostics().front().message();
}

// The panel starts a lathe program where the tool stands: its first move starts there, as it
// does on a mill, not at the workpiece origin (the program's picture drew it from there).
TEST_F(ProgramLoaderTest, ALatheProgramStartsWhereThePanelSaysTheToolStands) {
    const machine::MachineConfig lathe = *machine::loadMachine("lathe");
    ProgramRequest request;
    request.path = root / "P1.PIM";
    request.text = "G00 X20 Z5\nM30\n";
    request.ncRoot = root;
    request.presetInMachine.values[2] = 200.0;  // workpiece origin at machine Z200
    request.startPosition = Pose{};
    request.startPosition->values[0] = 40.0;  // X and Z of the tool, workpiece coordinates
    request.startPosition->values[2] = 80.0;
    const LoadedProgram loaded = loadProgram(lathe, request);
    ASSERT_TRUE(loaded.ready) << (loaded.diagnostics().empty() ? ""
                                                               : loaded.diagnostics()[0].format());
    ASSERT_TRUE(loaded.streamOrigin.has_value());
    EXPECT_DOUBLE_EQ(loaded.streamOrigin->values[2], 200.0);
    const Pose start = loaded.interpreter->nominalPosition();
    EXPECT_DOUBLE_EQ(start.values[0], 40.0);
    EXPECT_DOUBLE_EQ(start.values[2], 80.0);
    // Without a start (kerf run) the program starts at its origin.
    request.startPosition.reset();
    EXPECT_DOUBLE_EQ(loadProgram(lathe, request).interpreter->nominalPosition().values[2], 0.0);
}

// The machine file's sl_return_to_start (the TNC's posAfterContPocket) reaches the SL cycles:
// false ends cycle 22 at the clearance height Q7 = 80 above its last cut, true goes on back to
// where the tool stood before the cycle, X+7 Y-3 Z+120.
TEST_F(ProgramLoaderTest, SlReturnToStartEndsTheSlCyclesWhereTheyStarted) {
    const std::string text =
        "0 BEGIN PGM S MM\n1 TOOL CALL 1 Z S2000\n2 L X+7 Y-3 Z+120 R0 FMAX M3\n"
        "3 CYCL DEF 14.0 CONTOUR\n4 CYCL DEF 14.1 CONTOUR LABEL 1\n"
        "5 CYCL DEF 20 CONTOUR DATA Q1=-5 Q2=1 Q3=+0 Q4=+0 Q5=+0 Q6=2 Q7=+80 Q8=0 Q9=-1\n"
        "6 CYCL DEF 22 ROUGH-OUT Q10=5 Q11=100 Q12=350 Q18=0 Q19=0 Q208=0\n"
        "7 CYCL CALL\n8 M30\n9 LBL 1\n10 L X+10 Y+10 RL\n11 L X+60\n12 L Y+50\n"
        "13 L X+10\n14 L Y+10\n15 LBL 0\n16 END PGM S MM\n";
    auto endOfCycle = [&](bool returnToStart) {
        mill.slReturnToStart = returnToStart;
        ProgramRequest request;
        request.path = root / "S.H";
        request.text = text;
        request.ncRoot = root;
        LoadedProgram loaded = loadProgram(mill, request);
        EXPECT_TRUE(loaded.ready) << (loaded.diagnostics().empty()
                                          ? ""
                                          : loaded.diagnostics()[0].format());
        if (!loaded.ready) return Pose{};
        EXPECT_EQ(runDry(*loaded.interpreter, {}).end, DryRunEnd::Finished);
        for (const Diagnostic& d : loaded.interpreter->diagnostics())
            EXPECT_NE(d.severity, Severity::Error) << d.format();
        return loaded.interpreter->nominalPosition();
    };
    const Pose atClearance = endOfCycle(false);
    EXPECT_NEAR(atClearance.values[2], 80.0, 1e-9);
    // Above the last cut, inside the pocket (tool radius 4: X 14..56, Y 14..46).
    EXPECT_GT(atClearance.values[0], 13.9);
    EXPECT_LT(atClearance.values[0], 56.1);
    const Pose back = endOfCycle(true);
    EXPECT_NEAR(back.values[0], 7.0, 1e-9);
    EXPECT_NEAR(back.values[1], -3.0, 1e-9);
    EXPECT_NEAR(back.values[2], 120.0, 1e-9);
}

}  // namespace
}  // namespace kerf::task
