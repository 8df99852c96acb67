// `kerf check` fails what `kerf run` cannot finish on the same data (docs/headless.md, "What the
// check runs"): errors that depend on values — a division by zero or a square root of a negative
// number in a Q formula, a tool the tool table lacks, a cycle the tool cannot machine, a cycle
// parameter out of range after Q substitution — at the block, with the run's message; and the
// check writes no file.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

const char* const kBlank =
    "1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n"
    "2 BLK FORM 0.2 X+100 Y+100 Z+0\n";

// Tool 1: radius 3; tool 4: radius 4.
const char* const kToolTable =
    "BEGIN TOOL.T MM\n"
    "T      NAME                L           R           R2          DL        DR        DR2\n"
    "0      NULLTOOL            +0          +0          +0          +0        +0        +0\n"
    "1      DRILL_D6            +80         +3          +0          +0        +0        +0\n"
    "4      MILL_D8             +60         +4          +0          +0        +0        +0\n"
    "[END]\n";

class CheckDryRun : public testing::Test {
protected:
    void SetUp() override {
        const auto* info = testing::UnitTest::GetInstance()->current_test_info();
        dir = fs::temp_directory_path() /
              ("kerf_check_dry_" + std::to_string(::getpid()) + "_" + info->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
        write("TOOL.T", kToolTable);
    }
    void TearDown() override { fs::remove_all(dir); }

    fs::path write(const std::string& name, const std::string& text) {
        const fs::path file = dir / name;
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }

    struct Result {
        int exitCode = -1;
        std::string errors;  // the lines with ": error: "
    };
    // `kerf check|run program` in the test folder (its NC root, with TOOL.T); the remanent QR
    // parameters are kept in <dir>/xdg/kerf.
    Result kerf(const std::string& command, const fs::path& program,
                const std::string& machine = "mill") {
        const fs::path out = dir / "stderr.txt";
        const std::string line = "XDG_DATA_HOME=\"" + (dir / "xdg").string() + "\" \"" +
                                 KERF_BINARY + "\" " + command + " --machine " + machine + " \"" +
                                 program.string() + "\" > /dev/null 2> \"" + out.string() + "\"";
        const int status = std::system(line.c_str());
        Result r;
        r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
        std::ifstream in(out);
        for (std::string text; std::getline(in, text);) {
            if (text.find(": error: ") != std::string::npos) r.errors += text + "\n";
        }
        return r;
    }
    // The check fails with exactly the run's errors, and the first one is `expected`.
    void expectCheckFailsAsTheRun(const fs::path& program, const std::string& expected) {
        const Result run = kerf("run", program);
        const Result check = kerf("check", program);
        EXPECT_EQ(run.exitCode, 1);
        EXPECT_EQ(check.exitCode, 1);
        EXPECT_EQ(check.errors, run.errors);
        EXPECT_EQ(check.errors.substr(0, expected.size()), expected) << check.errors;
    }

    fs::path dir;
};

TEST_F(CheckDryRun, DivisionByZeroInAFormulaFailsAtItsOperator) {
    const fs::path p = write("DIV.H", std::string("0 BEGIN PGM DIV MM\n") + kBlank +
                                          "3 Q1 = 0\n"
                                          "4 Q2 = 5 / Q1\n"
                                          "5 END PGM DIV MM\n");
    // Line 5 of the file, column 10: the '/' of "4 Q2 = 5 / Q1".
    expectCheckFailsAsTheRun(p, p.string() + ":5:10: error: division by zero");
}

TEST_F(CheckDryRun, SquareRootOfANegativeNumberFailsAtItsBlock) {
    const fs::path p = write("ROOT.H", std::string("0 BEGIN PGM ROOT MM\n") + kBlank +
                                           "3 Q1 = -4\n"
                                           "4 Q2 = SQRT Q1\n"
                                           "5 END PGM ROOT MM\n");
    // Line 5 of the file, column 8: the SQRT of "4 Q2 = SQRT Q1".
    expectCheckFailsAsTheRun(p, p.string() + ":5:8: error: SQRT is not defined");
}

TEST_F(CheckDryRun, ATenfoldLoopEndingInADivisionByZeroIsFollowed) {
    // Q1 counts down from 10 by 1 in a loop; at the 10th pass 100 / Q1 divides by zero.
    const fs::path p = write("LOOP.H", std::string("0 BEGIN PGM LOOP MM\n") + kBlank +
                                           "3 Q1 = 10\n"
                                           "4 LBL 1\n"
                                           "5 Q1 = Q1 - 1\n"
                                           "6 Q2 = 100 / Q1\n"
                                           "7 FN 12: IF +Q1 LT +5 GOTO LBL 2\n"
                                           "8 CALL LBL 1 REP 20\n"
                                           "9 LBL 2\n"
                                           "10 END PGM LOOP MM\n");
    // Q1 never reaches 0 before the jump at Q1 = 4: the program runs, the check passes.
    EXPECT_EQ(kerf("run", p).exitCode, 0);
    EXPECT_EQ(kerf("check", p).exitCode, 0);
    const fs::path q = write("LOOP0.H", std::string("0 BEGIN PGM LOOP0 MM\n") + kBlank +
                                            "3 Q1 = 10\n"
                                            "4 LBL 1\n"
                                            "5 Q1 = Q1 - 1\n"
                                            "6 Q2 = 100 / Q1\n"
                                            "7 CALL LBL 1 REP 20\n"
                                            "8 END PGM LOOP0 MM\n");
    // The ninth repetition makes Q1 = 0: line 7 of the file, the '/' at column 12.
    expectCheckFailsAsTheRun(q, q.string() + ":7:12: error: division by zero");
}

TEST_F(CheckDryRun, AToolCallByParameterOfAToolTheTableLacks) {
    const fs::path p = write("TOOLQ.H", std::string("0 BEGIN PGM TOOLQ MM\n") + kBlank +
                                            "3 Q1 = 99\n"
                                            "4 TOOL CALL Q1 Z S2000\n"
                                            "5 END PGM TOOLQ MM\n");
    expectCheckFailsAsTheRun(p, p.string() + ":5:1: error: tool 99 is not in the tool table");
    // Tool 4 is in the table: the same program runs and checks clean.
    const fs::path ok = write("TOOLOK.H", std::string("0 BEGIN PGM TOOLOK MM\n") + kBlank +
                                              "3 Q1 = 4\n"
                                              "4 TOOL CALL Q1 Z S2000\n"
                                              "5 END PGM TOOLOK MM\n");
    EXPECT_EQ(kerf("run", ok).exitCode, 0);
    EXPECT_EQ(kerf("check", ok).exitCode, 0);
}

// Cycle 252 with the circle diameter 6 and tool 4 of radius 4: the tool (diameter 8) does not fit.
TEST_F(CheckDryRun, ACircularPocketSmallerThanTheTool) {
    const auto program = [&](const char* name, int tool) {
        return write(name, std::string("0 BEGIN PGM P MM\n") + kBlank + "3 TOOL CALL " +
                               std::to_string(tool) +
                               " Z S2000\n"
                               "4 L X+50 Y+50 Z+50 R0 FMAX\n"
                               "5 CYCL DEF 252 CIRCULAR POCKET ~\n"
                               "  Q215=0 ;MACHINING OPERATION ~\n"
                               "  Q223=6 ;CIRCLE DIAMETER ~\n"
                               "  Q368=0 ;FINISHING ALLOWANCE FOR SIDE ~\n"
                               "  Q207=500 ;FEED RATE FOR MILLING ~\n"
                               "  Q351=+1 ;CLIMB OR UP-CUT ~\n"
                               "  Q201=-10 ;DEPTH ~\n"
                               "  Q202=5 ;PLUNGING DEPTH ~\n"
                               "  Q369=0 ;FINISHING ALLOWANCE FOR FLOOR ~\n"
                               "  Q206=150 ;FEED RATE FOR PLNGNG ~\n"
                               "  Q338=0 ;INFEED FOR FINISHING ~\n"
                               "  Q200=2 ;SET-UP CLEARANCE ~\n"
                               "  Q203=+0 ;SURFACE COORDINATE ~\n"
                               "  Q204=50 ;2ND SET-UP CLEARANCE ~\n"
                               "  Q370=1 ;TOOL PATH OVERLAP ~\n"
                               "  Q366=0 ;PLUNGE ~\n"
                               "  Q385=500 ;FINISHING FEED RATE\n"
                               "6 CYCL CALL\n"
                               "7 END PGM P MM\n");
    };
    const fs::path big = program("BIG.H", 4);
    // The cycle stops at its call, line 23 of the file.
    expectCheckFailsAsTheRun(big, big.string() + ":23:1: error: cycle 252: the tool is too large");
    // Tool 1 (diameter 6) is not bigger than the circle: it runs and checks clean.
    const fs::path fits = program("FITS.H", 1);
    EXPECT_EQ(kerf("run", fits).exitCode, 0) << kerf("run", fits).errors;
    EXPECT_EQ(kerf("check", fits).exitCode, 0);
}

TEST_F(CheckDryRun, ACycleParameterOutOfRangeAfterQSubstitution) {
    const fs::path p = write("RANGE.H", std::string("0 BEGIN PGM RANGE MM\n") + kBlank +
                                            "3 TOOL CALL 1 Z S2000\n"
                                            "4 Q5 = -3\n"
                                            "5 CYCL DEF 200 DRILLING ~\n"
                                            "  Q200=Q5 ;SET-UP CLEARANCE ~\n"
                                            "  Q201=-10 ;DEPTH ~\n"
                                            "  Q206=150 ;FEED RATE FOR PLNGNG ~\n"
                                            "  Q202=5 ;PLUNGING DEPTH ~\n"
                                            "  Q210=0 ;DWELL TIME AT TOP ~\n"
                                            "  Q203=+0 ;SURFACE COORDINATE ~\n"
                                            "  Q204=50 ;2ND SET-UP CLEARANCE ~\n"
                                            "  Q211=0 ;DWELL TIME AT DEPTH ~\n"
                                            "  Q395=0 ;DEPTH REFERENCE\n"
                                            "6 L X+10 Y+10 Z+50 R0 FMAX M99\n"
                                            "7 END PGM RANGE MM\n");
    // Q200 = Q5 = -3 is below the range 0 ... 99999.9999: the definition, line 6 of the file.
    expectCheckFailsAsTheRun(p, p.string() + ":6:1: error: cycle 200: parameter Q200");
}

TEST_F(CheckDryRun, TheCheckWritesNoFile) {
    write("MASK.A", "\"Q1 = %f\\n\", Q1;\n");
    const fs::path p = write("OUT.H", std::string("0 BEGIN PGM OUT MM\n") + kBlank +
                                          "3 Q1 = 7\n"
                                          "4 QR1 = 5\n"
                                          "5 FN 16: F-PRINT MASK.A / RESULT.TXT\n"
                                          "6 END PGM OUT MM\n");
    const fs::path remanent = dir / "xdg" / "kerf" / "qr_parameters.txt";
    EXPECT_EQ(kerf("check", p).exitCode, 0);
    EXPECT_FALSE(fs::exists(dir / "RESULT.TXT"));
    EXPECT_FALSE(fs::exists(remanent));
    // The run writes both: the F-PRINT output and the remanent QR1.
    EXPECT_EQ(kerf("run", p).exitCode, 0);
    EXPECT_TRUE(fs::exists(dir / "RESULT.TXT"));
    EXPECT_TRUE(fs::exists(remanent));
    // The check reads the remanent parameters the run left: 10 / (QR1 - 5) divides by zero.
    const fs::path q = write("QR.H", std::string("0 BEGIN PGM QR MM\n") + kBlank +
                                         "3 Q2 = 10 / (QR1 - 5)\n"
                                         "4 END PGM QR MM\n");
    expectCheckFailsAsTheRun(q, q.string() + ":4:11: error: division by zero");
}

TEST_F(CheckDryRun, AFagorDivisionByZeroFailsAtItsOperator) {
    const fs::path p = write("P000001.PIM", "%P000001,MX,\nN10 (P1=0)\nN20 (P2=5/P1)\nN30 M30\n");
    const Result run = kerf("run", p, "lathe");
    const Result check = kerf("check", p, "lathe");
    EXPECT_EQ(check.exitCode, 1);
    EXPECT_EQ(check.errors, run.errors);
    // Line 3, column 10: the '/' of "N20 (P2=5/P1)".
    EXPECT_EQ(check.errors, p.string() + ":3:10: error: division by zero\n");
}

// EX-12.12's pattern: the program writes P9 with OPEN/WRITE and runs it with EXEC. The check
// runs P9 from memory and leaves the NC root as it was; the run writes P000009.PIM.
TEST_F(CheckDryRun, AFagorProgramThatWritesAndRunsAProgramChecksWithoutWritingIt) {
    const fs::path p = write("P000002.PIM",
                             "%P000002,MX,\nN10 (OPEN P9)\nN20 (WRITE G0 X30)\nN30 (WRITE M30)\n"
                             "N40 (EXEC P9)\nN50 M30\n");
    const Result check = kerf("check", p, "lathe");
    EXPECT_EQ(check.exitCode, 0) << check.errors;
    EXPECT_FALSE(fs::exists(dir / "P000009.PIM"));
    // What P9 holds is run: with a division by zero written into it, the check fails.
    const fs::path q = write("P000003.PIM",
                             "%P000003,MX,\nN10 (OPEN P8)\nN20 (WRITE (P1=0))\n"
                             "N30 (WRITE (P2=1/P1))\nN40 (EXEC P8)\nN50 M30\n");
    EXPECT_EQ(kerf("check", q, "lathe").exitCode, 1);
    EXPECT_FALSE(fs::exists(dir / "P000008.PIM"));
    EXPECT_EQ(kerf("run", p, "lathe").exitCode, 0);
    EXPECT_TRUE(fs::exists(dir / "P000009.PIM"));
}

}  // namespace
