// The conversational blocks each DIN/ISO block means, written from the TNC's ISO manual.
#include "core/interp/tnciso/iso_translator.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace kerf::tnciso {
namespace {

// Translates the lines of `program` in order (modal G functions carry over) and returns, per
// line, its conversational blocks joined by " | " (lines of one block by " / "), or "error at
// <column>: <message>".
std::vector<std::string> translate(const std::string& program) {
    program::LineReader reader(program);
    program::LogicalLine line;
    IsoTranslator translator;
    Translation translation;
    std::vector<std::string> out;
    while (reader.next(line)) {
        if (!translator.translate(line, translation)) {
            out.push_back("error at " + std::to_string(translator.problem().offset + 1) + ": " +
                          translator.problem().messageTemplate);
            continue;
        }
        std::string text;
        if (translation.direct) text = "(deferred)";
        for (const ConversationalBlock& block : translation.blocks()) {
            if (!text.empty()) text += " | ";
            std::string joined;
            const auto& starts = block.lineStarts();
            for (size_t l = 0; l < starts.size(); ++l) {
                const size_t end = l + 1 < starts.size() ? starts[l + 1] : block.text().size();
                std::string part = block.text().substr(starts[l], end - starts[l]);
                while (!part.empty() && part.back() == ' ')
                    part.pop_back();
                joined += (l == 0 ? "" : " / ") + part;
            }
            text += joined;
        }
        out.push_back(text);
    }
    return out;
}

TEST(IsoTranslator, PathFunctionsAreModalAndTakeCompensationFeedAndM) {
    EXPECT_EQ(translate("N10 G01 G41 X+10 Y+5 F200 M3 *\n"
                        "N20 Y+20 *\n"
                        "N30 G00 G40 G91 Z+5 *\n"
                        "N40 G90 X+0 *\n"),
              (std::vector<std::string>{"L RL X+10 Y+5 F200 M3", "L Y+20", "L FMAX R0 IZ+5",
                                        "L FMAX X+0"}));
}

TEST(IsoTranslator, CirclesCentresAndPolarForms) {
    EXPECT_EQ(translate("G02 X+10 Y+0 R+5 *\n"
                        "I+5 J+5 G03 X+0 Y+10 *\n"
                        "G91 I+5 J+0 *\n"
                        "G90 G05 X+1 Y+2 *\n"
                        "G06 X+3 Y+4 *\n"
                        "G29 *\n"
                        "G10 R+10 H+30 *\n"
                        "G11 G91 H+15 Z-1 *\n"
                        "G90 G12 H+90 *\n"
                        "G13 H+180 *\n"
                        "G15 H+270 *\n"
                        "G16 R+5 H+0 *\n"),
              (std::vector<std::string>{"CR R+5 DR- X+10 Y+0", "CC X+5 Y+5 | C DR+ X+0 Y+10",
                                        "CC IX+5 IY+0", "C X+1 Y+2", "CT X+3 Y+4", "CC",
                                        "LP PR+10 PA+30 FMAX", "LP IPA+15 IZ-1", "CP PA+90 DR-",
                                        "CP PA+180 DR+", "CP PA+270", "CTP PR+5 PA+0"}));
}

TEST(IsoTranslator, CornersApproachToolsBlanksAndLabels) {
    EXPECT_EQ(translate("G24 R2 *\n"
                        "G25 R3 F100 *\n"
                        "G26 R5 *\n"
                        "G27 R5 *\n"
                        "T5 G17 S3000 DL+0.1 DR-0.2 *\n"
                        "T G18 S100 *\n"
                        "S2000 M3 *\n"
                        "G99 T3 L+50 R+4 *\n"
                        "G30 G17 X+0 Y+0 Z-40 *\n"
                        "G31 G91 X+100 Y+100 Z+40 *\n"
                        "G98 L3 *\n"
                        "L3,2 *\n"
                        "L3,0 *\n"
                        "G38 M5 *\n"
                        "M3 M8 *\n"
                        "G98 L\"EDGE\" *\n"
                        "L\"EDGE\" *\n"),
              (std::vector<std::string>{
                  "CHF 2", "RND R3 F100", "RND R5", "RND R5", "TOOL CALL 5 Z S3000 DL+0.1 DR-0.2",
                  "TOOL CALL Y S100", "TOOL CALL S2000 | M3", "TOOL DEF 3 L+50 R+4",
                  "BLK FORM 0.1 Z X+0 Y+0 Z-40", "BLK FORM 0.2 IX+100 IY+100 IZ+40", "LBL 3",
                  "CALL LBL 3 REP 2", "CALL LBL 3", "STOP M5", "M3 M8", "LBL \"EDGE\"",
                  "CALL LBL \"EDGE\""}));
}

TEST(IsoTranslator, ParameterFunctionsAndFormulas) {
    EXPECT_EQ(translate("D00 Q1 P01 +5 *\n"
                        "D01 Q1 P01 +Q2 P02 +5 *\n"
                        "D04 QL3 P01 +Q1 P02 -2 *\n"
                        "D05 Q4 P01 +16 *\n"
                        "D13 Q5 P01 +1 P02 +1 *\n"
                        "D09 P01 +Q1 P02 +10 P03 5 *\n"
                        "D12 P01 +Q1 P02 +Q2 P03 7 *\n"
                        "D14 P01 1002 *\n"
                        "D18: SYSREAD Q1 = ID20 NR1 *\n"
                        "Q7 = (Q1 + 2) * 3 *\n"),
              (std::vector<std::string>{"FN 0: Q1 = +5", "FN 1: Q1 = +Q2 + +5",
                                        "FN 4: QL3 = +Q1 DIV -2", "FN 5: Q4 = SQRT +16",
                                        "FN 13: Q5 = +1 ANG +1", "FN 9: IF +Q1 EQU +10 GOTO LBL 5",
                                        "FN 12: IF +Q1 LT +Q2 GOTO LBL 7", "FN 14: ERROR = 1002",
                                        "FN 18: SYSREAD Q1 = ID20 NR1", "Q7 = (Q1 + 2) * 3"}));
}

TEST(IsoTranslator, ProgramHeaderEndAndCalls) {
    EXPECT_EQ(translate("%PART G71 *\n"
                        "%SUB *\n"
                        "%TNC:\\dir\\OTHER.I *\n"
                        "N99999999 %PART G71 *\n"
                        "%INCHES G70 *\n"
                        "N9 %INCHES G70 *\n"),
              (std::vector<std::string>{"BEGIN PGM PART MM", "CALL PGM SUB",
                                        "CALL PGM TNC:\\dir\\OTHER.I", "END PGM PART MM",
                                        "BEGIN PGM INCHES INCH", "END PGM INCHES INCH"}));
}

TEST(IsoTranslator, ProbingCycles14xxKeepTheirActualPositions) {
    // G1493 and G1416 become TCH PROBE blocks whose "nominal@actual" the Klartext parser reads.
    EXPECT_EQ(
        translate("G1493 Q1140=+1 Q1145=+40 Q1146=+2 Q1149=+0 *\n"
                  "G1416 Q1100=+0@+1.5 Q1101=+0 *\n"),
        (std::vector<std::string>{"TCH PROBE 1493 / Q1140=+1 / Q1145=+40 / Q1146=+2 / Q1149=+0",
                                  "TCH PROBE 1416 / Q1100=+0@+1.5 / Q1101=+0"}));
    // "?" (semi-automatic mode) likewise.
    EXPECT_EQ(translate("G1416 Q1100=? Q1101=+0 Q1102=? *\n"),
              (std::vector<std::string>{"TCH PROBE 1416 / Q1100=? / Q1101=+0 / Q1102=?"}));
}

TEST(IsoTranslator, CyclesKeepTheirConversationalParameters) {
    EXPECT_EQ(translate("N10 G200 DRILLING Q200=2 Q201=-5 ;DEPTH *\n"
                        "G251 Q215=0 Q218=30 ;LENGTH *\n"
                        "G1416 Q1100=+20 *\n"
                        "G122 Q10=-5 *\n"
                        "G79 PAT M3 *\n"),
              (std::vector<std::string>{"CYCL DEF 200 DRILLING / Q200=2 / Q201=-5 ;DEPTH",
                                        "CYCL DEF 251 / Q215=0 / Q218=30 ;LENGTH",
                                        "TCH PROBE 1416 / Q1100=+20", "CYCL DEF 22 / Q10=-5",
                                        "CYCL CALL PAT M3"}));
    // Parameters written on their own lines below the cycle block (the control's layout).
    program::LineReader reader("G200 DRILLING\n  Q200=2 ;SET-UP\n  Q201=-5 ;DEPTH *\n");
    program::LogicalLine line;
    ASSERT_TRUE(reader.next(line));
    reader.appendNextLine(line);
    reader.appendNextLine(line);
    IsoTranslator translator;
    Translation translation;
    ASSERT_TRUE(translator.translate(line, translation));
    ASSERT_EQ(translation.blocks().size(), 1u);
    EXPECT_EQ(translation.blocks()[0].lineStarts().size(), 3u);
}

TEST(IsoTranslator, OldCyclesAreOneBlock) {
    EXPECT_EQ(translate("G54 X+10 Y+5 *\n"
                        "G53 P01 5 *\n"
                        "G28 X Y *\n"
                        "G73 G91 H+45 *\n"
                        "G90 G72 F0.8 *\n"
                        "G04 F1.5 *\n"
                        "G36 S90 *\n"
                        "G62 T0.05 *\n"
                        "G39 P01 \"SUB.H\" *\n"),
              (std::vector<std::string>{"CYCL DEF 7.0 DATUM SHIFT | CYCL DEF 7.1 X+10 Y+5",
                                        "CYCL DEF 7.0 DATUM SHIFT | CYCL DEF 7.1 #5",
                                        "CYCL DEF 8.0 MIRROR IMAGE | CYCL DEF 8.1 X Y",
                                        "CYCL DEF 10.0 ROTATION | CYCL DEF 10.1 IROT+45",
                                        "CYCL DEF 11.0 SCALING | CYCL DEF 11.1 SCL 0.8",
                                        "CYCL DEF 9.0 DWELL TIME | CYCL DEF 9.1 DWELL 1.5",
                                        "CYCL DEF 13.0 ORIENTATION | CYCL DEF 13.1 ANGLE 90",
                                        "CYCL DEF 32.0 TOLERANCE | CYCL DEF 32.1 T0.05",
                                        "CYCL DEF 12.0 PGM CALL | CYCL DEF 12.1 PGM SUB.H"}));
}

// G55 is touch-probe cycle 0 (spec 4): P01 the result parameter, a sign-only axis word the
// probing direction, the other axis words the pre-position.
TEST(IsoTranslator, G55IsTouchProbeCycleZero) {
    EXPECT_EQ(
        translate("G55 P01 5 X- X+5 Y+0 Z-5 *\n"),
        (std::vector<std::string>{"TCH PROBE 0.0 REF. PLANE Q5 X- | TCH PROBE 0.1 X+5 Y+0 Z-5"}));
    EXPECT_EQ(translate("G55 P01 5 X+5 *\n"),
              (std::vector<std::string>{
                  "error at 10: G55: the probing axis with its direction (X-, Y+ ...) expected"}));
    // A sign alone stays an error elsewhere.
    EXPECT_EQ(translate("G01 X- *\n"),
              (std::vector<std::string>{"error at 6: value expected after '{1}'"}));
}

// The seed gives cycle 18 the ISO code G18, the plane ZX's: its parameters make it the cycle.
TEST(IsoTranslator, G18WithItsParametersIsThreadCutting) {
    EXPECT_EQ(translate("G18 P01 -20 P02 +1.5 *\n"
                        "T1 G18 S500 *\n"
                        "G18 P01 -20 *\n"
                        "G18 *\n"),
              (std::vector<std::string>{
                  "CYCL DEF 18.0 THREAD CUTTING | CYCL DEF 18.1 DEPTH -20 | "
                  "CYCL DEF 18.2 PITCH +1.5",
                  "TOOL CALL 1 Y S500", "error at 12: P{1} expected after G18",
                  "error at 1: G17/G18/G19 belong to a tool call (T) or a blank (G30)"}));
}

// The straight line with 3D tool compensation: a G01 (or G00) with the surface normal NX NY NZ
// and the tool direction TX TY TZ is the conversational LN; LN itself is no ISO word.
TEST(IsoTranslator, StraightWithSurfaceNormalIsLn) {
    EXPECT_EQ(translate("N10 G01 X+10 Y+0 Z+0 NX+0.6 NY+0 NZ+0.8 F100 *\n"
                        "N20 X+0 Y+0 Z+50 NX+0 NY+0 NZ+1 TX+0.5 TY+0 TZ+0.866 M128 *\n"
                        "N30 X+5 *\n"
                        "N40 LN X+10 Y+0 Z+0 NX+0 NY+0 NZ+1 *\n"
                        "N50 G02 X+10 Y+0 R+5 NX+0 NY+0 NZ+1 *\n"),
              (std::vector<std::string>{
                  "LN X+10 Y+0 Z+0 NX+0.6 NY+0 NZ+0.8 F100",
                  "LN X+0 Y+0 Z+50 NX+0 NY+0 NZ+1 TX+0.5 TY+0 TZ+0.866 M128", "L X+5",
                  "error at 5: LN is the conversational straight line with 3D tool compensation; "
                  "in ISO write G01 X Y Z NX NY NZ [TX TY TZ]",
                  "error at 22: surface vectors NX NY NZ TX TY TZ belong to a straight line "
                  "G00/G01"}));
}

TEST(IsoTranslator, ErrorsPointAtTheWord) {
    EXPECT_EQ(translate("N10 X+10 *\n"
                        "N20 G01 X+1 G77 *\n"
                        "N30 G01 X+1 H+2 *\n"
                        "N40 G00 X+1 F100 *\n"
                        "N50 G01 Y+ *\n"
                        "N60 G17 *\n"
                        "N70 G01 X+1 * Y+2\n"
                        "N80 D01 Q1 P01 +2 *\n"
                        "N90 G07 X+1 *\n"),
              (std::vector<std::string>{
                  "error at 5: no path function (G00, G01, G02 ...) is active",
                  "error at 13: unknown G function G{1}",
                  "error at 13: '{1}' is not allowed in this block",
                  "error at 13: a feed rate F is not allowed with rapid G{1}",
                  "error at 10: value expected after '{1}'",
                  "error at 5: G17/G18/G19 belong to a tool call (T) or a blank (G30)",
                  "error at 15: text after the block end '*'", "error at 19: P0{1} expected",
                  "(deferred)"}));
}

}  // namespace
}  // namespace kerf::tnciso

namespace kerf::tnciso {
namespace {

// Special functions keep their conversational words inside the ISO block; the block end '*' and
// comments go, a '*' inside a Q formula stays, continuation lines stay lines of the block.
TEST(IsoTranslator, SpecialFunctionsAreWrittenWithTheirConversationalWords) {
    EXPECT_EQ(translate("N30 SEL TABLE \"TNC:\\DATUMS.D\" *\n"
                        "N40 GLOBAL DEF 125 POSITIONING ~\n"
                        "  Q345=+1 ;SELECT POS. HEIGHT *\n"
                        "N50 PATTERN DEF POS1 (X+10 Y+10 Z+0) *\n"
                        "N60 FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS * ;tcpm\n"
                        "N70 CONTOUR DEF P1 = \"POCK\" I2 = \"ISLE\" DEPTH5 *\n"
                        "N80 QC10 = (QC1 | QC2) \\ QC3 *\n"
                        "N90 PLANE RESET STAY *\n"),
              (std::vector<std::string>{
                  "SEL TABLE \"TNC:\\DATUMS.D\"", "GLOBAL DEF 125 POSITIONING / Q345=+1",
                  "PATTERN DEF POS1 (X+10 Y+10 Z+0)", "FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS",
                  "CONTOUR DEF P1 = \"POCK\" I2 = \"ISLE\" DEPTH5", "QC10 = (QC1 | QC2) \\ QC3",
                  "PLANE RESET STAY"}));
}

// SEL PGM and CALL SELECTED PGM, the pair the HMI's SPEC FCT writes, are conversational words
// too; "CALL" without SELECTED stays an error (the ISO call is "%NAME").
TEST(IsoTranslator, SelectedProgramCallsKeepTheirConversationalWords) {
    EXPECT_EQ(translate("N10 SEL PGM \"SUB\" *\n"
                        "N20 CALL SELECTED PGM *\n"
                        "N30 %SUB *\n"),
              (std::vector<std::string>{"SEL PGM \"SUB\"", "CALL SELECTED PGM", "CALL PGM SUB"}));
    EXPECT_EQ(translate("N40 CALL LBL 1 *\n").front().substr(0, 9), "error at ");
}

}  // namespace
}  // namespace kerf::tnciso
