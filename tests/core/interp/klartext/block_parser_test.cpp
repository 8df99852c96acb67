#include "core/interp/klartext/block_parser.h"

#include <gtest/gtest.h>

#include "core/interp/klartext/block_reader.h"

namespace kerf::klartext {
namespace {

// Parses the first block of `text` (syntax only).
ParsedBlock parse(std::string_view text) {
    BlockReader reader(text);
    program::LogicalLine line;
    EXPECT_TRUE(reader.next(line));
    BlockParser parser(nullptr);
    ParsedBlock block;
    EXPECT_TRUE(parser.parse(line, block)) << text << ": " << parser.problem().messageTemplate;
    return block;
}

// The statement of the first block, as a value (the parsed block is a temporary).
template <typename T>
T first(std::string_view text) {
    return std::get<T>(parse(text).statement);
}

// The offset and message of a syntax error in a single line.
std::pair<size_t, std::string> problem(std::string_view text) {
    BlockReader reader(text);
    program::LogicalLine line;
    reader.next(line);
    BlockParser parser(nullptr);
    ParsedBlock block;
    EXPECT_FALSE(parser.parse(line, block)) << text;
    return {parser.problem().offset, parser.problem().messageTemplate};
}

TEST(BlockParser, LinearBlockWithEveryWord) {
    ParsedBlock b = parse("12 L IX+10 Y-Q3 Z+(1+2) RL F500 M3 M8 ;cut");
    EXPECT_EQ(b.blockNumber, 12);
    const auto& l = std::get<LinearBlock>(b.statement);
    EXPECT_TRUE(l.coords[Axis::X].incremental);
    EXPECT_DOUBLE_EQ(l.coords[Axis::X].value, 10);
    EXPECT_TRUE(l.coords.has(Axis::Y));
    EXPECT_DOUBLE_EQ(l.coords[Axis::Z].value, 3);
    EXPECT_EQ(l.words.comp, CompWord::Left);
    EXPECT_EQ(l.words.feed.kind, FeedWord::Kind::Value);
    EXPECT_DOUBLE_EQ(l.words.feed.value, 500);
    ASSERT_EQ(l.words.m.count, 2);
    EXPECT_EQ(l.words.m.list[1].number, 8);
}

TEST(BlockParser, FeedKeywordsAndOldListingForms) {
    EXPECT_EQ(first<LinearBlock>("L X+1 FMAX").words.feed.kind, FeedWord::Kind::Max);
    EXPECT_EQ(first<LinearBlock>("L X+1 F AUTO").words.feed.kind, FeedWord::Kind::Auto);
    EXPECT_EQ(first<LinearBlock>("L X+1 FU0.1").words.feed.kind, FeedWord::Kind::PerRevolution);
    EXPECT_EQ(first<LinearBlock>("L X+1 FZ0,05").words.feed.kind, FeedWord::Kind::PerTooth);
    // Values that were not entered are listed as bare letters by older controls.
    const auto bare = first<LinearBlock>("L X+1,000 R F M");
    EXPECT_EQ(bare.words.comp, CompWord::None);
    EXPECT_EQ(bare.words.feed.kind, FeedWord::Kind::None);
    EXPECT_EQ(bare.words.m.count, 0);
}

TEST(BlockParser, CircleRadiusAndCompensationWords) {
    const auto cr = first<CircleRadiusBlock>("CR X+10 Y+0 R-20 DR- R0 F100");
    EXPECT_DOUBLE_EQ(cr.radius, -20);
    EXPECT_EQ(cr.direction, Direction::Cw);
    EXPECT_EQ(cr.words.comp, CompWord::Off);
    EXPECT_DOUBLE_EQ(first<RoundBlock>("RND R0,5").radius, 0.5);
    const auto c = first<CircleBlock>("C DR+");
    EXPECT_EQ(c.coords.present, 0);
    EXPECT_EQ(c.direction, Direction::Ccw);
}

TEST(BlockParser, PolarAndApproachBlocks) {
    const auto lp = first<LinePolarBlock>("LP IPR+5 PA-30 RR");
    EXPECT_TRUE(lp.polar.radiusIncremental);
    EXPECT_DOUBLE_EQ(*lp.polar.angle, -30);
    const auto cp = first<CirclePolarBlock>("CP IPA+720 IZ-4 DR+");
    EXPECT_TRUE(cp.polar.angleIncremental);
    EXPECT_TRUE(cp.coords[Axis::Z].incremental);
    const auto appr = first<ApproachBlock>("APPR PCT PR+10 PA+0 CCA90 R+5 RL F100");
    EXPECT_TRUE(appr.polar);
    EXPECT_EQ(appr.kind, ApproachKind::CT);
    EXPECT_DOUBLE_EQ(*appr.angle, 90);
    EXPECT_DOUBLE_EQ(*appr.radius, 5);
    const auto dep = first<ApproachBlock>("DEP LT LEN12.5 R0");
    EXPECT_TRUE(dep.depart);
    EXPECT_DOUBLE_EQ(*dep.length, 12.5);
}

TEST(BlockParser, ToolCallForms) {
    const auto a = first<ToolCall>("TOOL CALL 5 Z S3000 F200 DL+0.1 DR-0,2 DR2+0");
    EXPECT_EQ(*a.number, 5);
    EXPECT_EQ(*a.axis, Axis::Z);
    EXPECT_DOUBLE_EQ(*a.dr, -0.2);
    EXPECT_DOUBLE_EQ(*a.dr2, 0);
    const auto b = first<ToolCall>("TOOL CALL \"MILL_D10\" Y S1000");
    EXPECT_EQ(*b.name, "MILL_D10");
    EXPECT_EQ(*b.axis, Axis::Y);
    const auto c = first<ToolCall>("TOOL CALL  DL-Q108");
    EXPECT_FALSE(c.number);
    EXPECT_TRUE(c.dl);
}

TEST(BlockParser, LabelsAndCalls) {
    EXPECT_EQ(*first<Label>("LBL1").target.number, 1);
    EXPECT_EQ(*first<Label>("LBL \"start\"").target.name, "start");
    EXPECT_EQ(first<CallLabel>("CALL LBL 1 REP 25/25").repeat, 25);
    EXPECT_EQ(first<CallLabel>("CALL LBL 1 REP2").repeat, 2);
    EXPECT_EQ(*first<CallLabel>("CALL LBL QS4").target.stringParameter, 4);
    EXPECT_EQ(std::get<CallPgm>(parse("CALL PGM TNC:\\dir\\SUB.H ;x").statement).path,
              "TNC:\\dir\\SUB.H");
}

TEST(BlockParser, FnBlocks) {
    const auto jump = first<ConditionalJump>("FN 11: IF +Q1 GT Q31 GOTO LBL \"x\"");
    EXPECT_EQ(jump.comparison, Comparison::Greater);
    EXPECT_EQ(*jump.target.name, "x");
    const auto read = first<SysRead>("FN18: SYSREAD QL28 = ID220 NR2 IDX1");
    EXPECT_EQ(read.target.kind, QKind::QL);
    EXPECT_EQ(read.id, 220);
    EXPECT_EQ(read.idx, 1);
    EXPECT_EQ(first<ErrorBlock>("FN 14: ERROR = 1010").number, 1010);
    const auto tab = first<TableAccess>("FN 27: TABWRITE 2/\"X, Y\" = Q5");
    EXPECT_TRUE(tab.write);
    EXPECT_EQ(tab.columnCount, 2u);
    EXPECT_EQ(first<PrintBlock>("FN15: PRINT Q1/Q2/Q3").values.size(), 3u);
    EXPECT_TRUE(std::holds_alternative<Deferred>(parse("FN 20: WAIT FOR xyz").statement));
}

TEST(BlockParser, CycleDefinitionsInBothLayouts) {
    const char* tilde =
        "7 CYCL DEF 200 DRILLING ~\n  Q200=2 ;SET-UP CLEARANCE ~\n  Q201=-20 ;DEPTH ~\n"
        "  Q206=FAUTO ;FEED\n8 L X+0";
    const auto a = first<CycleDefinition>(tilde);
    EXPECT_EQ(a.number, 200);
    EXPECT_EQ(a.name, "DRILLING");
    ASSERT_EQ(a.parameters.size(), 3u);
    EXPECT_DOUBLE_EQ(*a.parameters[1].value, -20);
    EXPECT_EQ(a.parameters[1].comment, "DEPTH");
    EXPECT_EQ(a.parameters[2].raw, "FAUTO");
    EXPECT_FALSE(a.parameters[2].value);
    // The manual's layout: indented parameter lines without '~'.
    const auto b = first<CycleDefinition>(
        "7 CYCL DEF 200 FURAR\n  Q200=2 ;DISTANCIA\n  Q201=-3 ;PROFUNDIDADE\n8 L");
    EXPECT_EQ(b.parameters.size(), 2u);
    const auto old = first<CycleDefinition>("CYCL DEF 7.1  X+10");
    EXPECT_EQ(old.number, 7);
    EXPECT_EQ(old.subNumber, 1);
    EXPECT_EQ(old.rest, "X+10");
}

// CAM post-processors write the parameters on the CYCL DEF line, or several on one line: the same
// block as one parameter per line (docs/klartext.md, "Program text").
TEST(BlockParser, CycleParametersOnTheHeaderLineAndSideBySide) {
    const auto a = first<CycleDefinition>(
        "7 CYCL DEF 200 DRILLING Q200=2 Q201=-20 Q206=FAUTO Q202 = 5 ;DEPTH\n8 L X+0");
    EXPECT_EQ(a.number, 200);
    EXPECT_EQ(a.name, "DRILLING");
    ASSERT_EQ(a.parameters.size(), 4u);
    EXPECT_EQ(a.parameters[0].q, 200);
    EXPECT_DOUBLE_EQ(*a.parameters[0].value, 2.0);
    EXPECT_EQ(a.parameters[0].offset, 24u);  // "Q200" after "7 CYCL DEF 200 DRILLING "
    EXPECT_DOUBLE_EQ(*a.parameters[1].value, -20.0);
    EXPECT_EQ(a.parameters[2].raw, "FAUTO");
    EXPECT_EQ(a.parameters[3].q, 202);
    EXPECT_DOUBLE_EQ(*a.parameters[3].value, 5.0);
    EXPECT_EQ(a.parameters[3].comment, "DEPTH");  // the line's comment: its last parameter's
    // Without a name, and followed by parameter lines that hold two each.
    const auto b = first<CycleDefinition>(
        "7 CYCL DEF 200 Q200=2\n  Q201=-3 Q206=150 ;PROFUNDIDADE\n  Q202=3\n8 L");
    EXPECT_EQ(b.name, "");
    ASSERT_EQ(b.parameters.size(), 4u);
    EXPECT_EQ(b.parameters[1].q, 201);
    EXPECT_EQ(b.parameters[1].comment, "");
    EXPECT_EQ(b.parameters[2].q, 206);
    EXPECT_EQ(b.parameters[2].comment, "PROFUNDIDADE");
    EXPECT_EQ(b.parameters[3].q, 202);
    // A string parameter with a blank and "Q5=" inside its quotes is one parameter.
    const auto c = first<CycleDefinition>("7 CYCL DEF 225 ENGRAVING QS500=\"A Q5=1\" Q513=10");
    ASSERT_EQ(c.parameters.size(), 2u);
    EXPECT_EQ(c.parameters[0].raw, "\"A Q5=1\"");
    EXPECT_EQ(c.parameters[1].q, 513);
    // GLOBAL DEF alike.
    const auto g = first<GlobalDefinition>("7 GLOBAL DEF 100 GENERAL Q200=2 Q204=50");
    ASSERT_EQ(g.parameters.size(), 2u);
    EXPECT_EQ(g.parameters[1].q, 204);
    // A name word that is not "Qnnn=" stays in the name.
    EXPECT_EQ(first<CycleDefinition>("7 CYCL DEF 200 Q5 DRILLING").name, "Q5 DRILLING");
}

// Real files written "CYCL DEF9 .0" with a blank before the sub-number (issue 16 item 6).
TEST(BlockParser, OldStyleSubNumberAfterABlank) {
    const auto dwell = first<CycleDefinition>("CYCL DEF9 .0 DWELL TIME");
    EXPECT_EQ(dwell.number, 9);
    EXPECT_EQ(dwell.subNumber, 0);
    EXPECT_EQ(dwell.rest, "DWELL TIME");
    const auto shift = first<CycleDefinition>("CYCL DEF7 .1 X+10");
    EXPECT_EQ(shift.number, 7);
    EXPECT_EQ(shift.subNumber, 1);
    ASSERT_EQ(shift.words.size(), 1u);
    EXPECT_EQ(shift.words[0].key, "X");
    EXPECT_DOUBLE_EQ(*shift.words[0].value, 10.0);
    const auto comma = first<CycleDefinition>("CYCL DEF 9 ,1 DWELL 1,5");
    EXPECT_EQ(comma.subNumber, 1);
    // A new-style name that starts with a number stays a name.
    const auto named = first<CycleDefinition>("CYCL DEF 200 .5MM DRILLING");
    EXPECT_EQ(named.subNumber, -1);
    EXPECT_EQ(named.number, 200);
}

TEST(BlockParser, ErrorsPointAtTheWord) {
    EXPECT_EQ(problem("L X+10 Yabc").first, 7u);
    EXPECT_EQ(problem("L X+1 X+2").second, "axis {1} is programmed twice");
    EXPECT_EQ(problem("FN 99: Q1 = 1").second, "FN {1} does not exist");
    EXPECT_EQ(problem("CR X+1 Y+1 DR+").second, "CR needs a radius R");
    EXPECT_EQ(problem("BEGIN PGM X").second, "MM or INCH expected");
    EXPECT_EQ(problem("Q1 = 2 +").second, "incomplete formula");
    EXPECT_EQ(problem("LBL 0x").first, 5u);
}

// CAM post-processors for newer TNCs open every program with FUNCTION MODE MILL; a milling
// machine is always in that mode, so the block changes nothing. Turning mode is refused at MODE's
// operand.
TEST(BlockParser, FunctionModeMillIsAcceptedAndTurnIsRefused) {
    EXPECT_TRUE(std::holds_alternative<Empty>(parse("6 FUNCTION MODE MILL ;mode").statement));
    EXPECT_EQ(problem("6 FUNCTION MODE TURN"),
              std::make_pair(size_t{16}, std::string("FUNCTION MODE TURN: this machine has no "
                                                     "turning mode")));
    EXPECT_EQ(problem("6 FUNCTION MODE DRILL").second, "FUNCTION MODE: MILL or TURN expected");
    EXPECT_EQ(problem("FUNCTION MODE MILL \"AC_TABLE\"").first, 19u);
}

// M functions with operands, as CAM output writes them: M120 LA (look-ahead blocks), M118 with
// the handwheel's travel per axis, M94 with the axes it reduces.
TEST(BlockParser, MFunctionsTakeTheirOperands) {
    const auto la = first<LinearBlock>("L X+1 RL F100 M120 LA5").words.m;
    ASSERT_EQ(la.count, 1);
    EXPECT_EQ(la.list[0].number, 120);
    EXPECT_EQ(la.list[0].parameter, 5.0);

    const auto handwheel = first<LinearBlock>("L X+0 Y+38.5 RL F125 M118 X1 Y1");
    EXPECT_DOUBLE_EQ(handwheel.coords[Axis::Y].value, 38.5);  // the block's own axes stay
    EXPECT_EQ(handwheel.words.m.list[0].number, 118);
    EXPECT_TRUE(std::holds_alternative<MFunctionBlock>(parse("M118 X+1 Y+1").statement));

    const auto reduce = first<MFunctionBlock>("L M94 C").words.m.list[0];
    EXPECT_EQ(reduce.axes, axisBit(Axis::C));
    // M94 followed by a coordinate moves that axis after reducing all of them.
    const auto move = first<LinearBlock>("L C+180 FMAX M94");
    EXPECT_EQ(move.words.m.list[0].axes, 0);
    EXPECT_DOUBLE_EQ(move.coords[Axis::C].value, 180);
}

TEST(BlockParser, SelPgmAndCallSelectedPgm) {
    EXPECT_EQ(first<SelectProgram>("SEL PGM \"TNC:\\PARTS\\P1.H\"").path, "TNC:\\PARTS\\P1.H");
    EXPECT_EQ(first<SelectProgram>("SEL PGM SUB.H ;next").path, "SUB.H");
    EXPECT_TRUE(first<SelectProgram>("SEL PGM QS3").fromParameter);
    EXPECT_TRUE(std::holds_alternative<CallSelectedProgram>(parse("CALL SELECTED PGM").statement));
    EXPECT_EQ(problem("CALL SELECTED X").second, "PGM expected");
}

TEST(BlockParser, HeadWordSkipsNumbersAndSkipMarks) {
    EXPECT_EQ(BlockParser::headWord("12 /1 CYCL DEF 200"), "CYCL");
    EXPECT_EQ(BlockParser::headWord("Q1 = 2"), "Q");
}

}  // namespace
}  // namespace kerf::klartext
