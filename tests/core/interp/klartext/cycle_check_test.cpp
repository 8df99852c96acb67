// `kerf check` on CYCL DEF parameters: positions and messages worked out by hand from the text.
#include <gtest/gtest.h>

#include "core/interp/klartext/program_file.h"

namespace kerf::klartext {
namespace {

DiagnosticList check(const std::string& text) {
    ProgramFile program;
    program.source = program::SourceText::fromString(text, "P.H");
    checkProgram(program);
    return program.diagnostics;
}

// Cycle 200 with every parameter an old control writes; `q206` is the plunging feed's text.
std::string drilling(const std::string& q206, const std::string& extra = "") {
    return "0 BEGIN PGM P MM\n"
           "1 Q5 = -100\n"
           "2 CYCL DEF 200 DRILLING ~\n"
           "  Q200=2 ;SET-UP CLEARANCE ~\n"
           "  Q201=-5 ;DEPTH ~\n"
           "     Q206=" +
           q206 +
           " ;FEED ~\n"
           "  Q202=5 ~\n"
           "  Q210=0 ~\n"
           "  Q203=+0 ~\n"
           "  Q204=50" +
           extra +
           "\n"
           "3 END PGM P MM\n";
}

TEST(CycleCheck, CompleteDefinitionWithoutLaterParametersIsClean) {
    // Q211 and Q395 of cycle 200 came with later software: an older block runs without them.
    EXPECT_TRUE(check(drilling("150")).empty());
}

TEST(CycleCheck, LiteralOutsideRangeIsReportedAtItsOwnLine) {
    const DiagnosticList d = check(drilling("-100"));
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].severity, Severity::Error);
    EXPECT_EQ(d[0].code, "cycle-range");
    EXPECT_EQ(d[0].line, 6u);    // the fourth line of the program's third block
    EXPECT_EQ(d[0].column, 6u);  // after five blanks
    EXPECT_EQ(d[0].message(),
              "cycle 200: parameter Q206 (Feed rate for plunging) = -100.0000 is outside 0.0000 "
              "to 99999.9990");
}

TEST(CycleCheck, FormulaWithoutQParametersIsChecked) {
    const DiagnosticList d = check(drilling("(50-150)"));
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].line, 6u);
}

TEST(CycleCheck, ValueFromQParameterIsLeftToTheRun) {
    EXPECT_TRUE(check(drilling("Q5")).empty());
    EXPECT_TRUE(check(drilling("-Q5")).empty());
}

TEST(CycleCheck, FeedKeywordsAreNotRangeChecked) {
    EXPECT_TRUE(check(drilling("FAUTO")).empty());
}

TEST(CycleCheck, MissingParameterIsReportedAtTheCyclDef) {
    const DiagnosticList d = check(
        "0 BEGIN PGM P MM\n"
        "1 CYCL DEF 200 DRILLING\n"
        "  Q200=2\n"
        "  Q201=-5\n"
        "  Q206=150\n"
        "  Q202=5\n"
        "  Q210=0\n"
        "  Q204=50\n"
        "2 END PGM P MM\n");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].code, "cycle-parameter");
    EXPECT_EQ(d[0].line, 2u);
    EXPECT_EQ(d[0].column, 1u);
    EXPECT_EQ(d[0].message(),
              "cycle 200: parameter Q203 (Workpiece surface coordinate) is missing");
}

TEST(CycleCheck, RepeatedParameterCountsWithItsLastValue) {
    // The run takes the last Q206: the first, out of range, is overwritten.
    EXPECT_TRUE(check(drilling("-100", " ~\n  Q206=120")).empty());
    const DiagnosticList d = check(drilling("120", " ~\n  Q206=-1"));
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].line, 11u);
    EXPECT_EQ(d[0].column, 3u);
}

TEST(CycleCheck, WholeNumberParameterRefusesFractions) {
    const DiagnosticList d = check(
        "0 BEGIN PGM P MM\n"
        "1 CYCL DEF 202 BORING\n"
        "  Q200=2\n"
        "  Q201=-15\n"
        "  Q206=100\n"
        "  Q211=0\n"
        "  Q208=0\n"
        "  Q203=+0\n"
        "  Q204=50\n"
        "  Q214=2.5\n"
        "  Q336=0\n"
        "2 END PGM P MM\n");
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].line, 10u);
    EXPECT_EQ(d[0].column, 3u);
    EXPECT_NE(d[0].message().find("Q214"), std::string::npos);
    EXPECT_NE(d[0].message().find("must be a whole number from 0.0000 to 4.0000"),
              std::string::npos);
}

TEST(CycleCheck, CircularPocketFromAnOlderControlNeedsNoFeedReference) {
    // A 252 block as written before Q439 existed (software -02; corpus VESELYparametr).
    EXPECT_TRUE(check("0 BEGIN PGM P MM\n"
                      "1 CYCL DEF 252 CIRCULAR POCKET ~\n"
                      "    Q215=+0    ;MACHINING OPERATION ~\n"
                      "    Q223=+60   ;CIRCLE DIAMETER ~\n"
                      "    Q368=+0    ;ALLOWANCE FOR SIDE ~\n"
                      "    Q207=+500  ;FEED RATE FOR MILLNG ~\n"
                      "    Q351=+1    ;CLIMB OR UP-CUT ~\n"
                      "    Q201=-2    ;DEPTH ~\n"
                      "    Q202=+5    ;PLUNGING DEPTH ~\n"
                      "    Q369=+0    ;ALLOWANCE FOR FLOOR ~\n"
                      "    Q206=+150  ;FEED RATE FOR PLNGNG ~\n"
                      "    Q338=+0    ;INFEED FOR FINISHING ~\n"
                      "    Q200=+2    ;SET-UP CLEARANCE ~\n"
                      "    Q203=-2.5  ;SURFACE COORDINATE ~\n"
                      "    Q204=+50   ;2ND SET-UP CLEARANCE ~\n"
                      "    Q370=+1    ;TOOL PATH OVERLAP ~\n"
                      "    Q366=+1    ;PLUNGE ~\n"
                      "    Q385=+500  ;FINISHING FEED RATE\n"
                      "2 END PGM P MM\n")
                    .empty());
}

}  // namespace
}  // namespace kerf::klartext
