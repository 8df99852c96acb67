#include "core/interp/fagor/block_parser.h"

#include <gtest/gtest.h>

namespace kerf::fagor {
namespace {

ParsedBlock parse(std::string_view text, bool firstLine = false) {
    BlockParser parser(nullptr);
    ParsedBlock block;
    EXPECT_TRUE(parser.parse(text, firstLine, block))
        << text << ": " << parser.problem().messageTemplate;
    return block;
}

Problem problem(std::string_view text) {
    BlockParser parser(nullptr);
    ParsedBlock block;
    EXPECT_FALSE(parser.parse(text, false, block)) << text;
    return parser.problem();
}

class Values final : public ParameterSource {
public:
    bool parameter(int number, double& out, Problem& p) override {
        if (number == 99) {
            p.code = "parameter";
            p.messageTemplate = "no P99";
            return false;
        }
        out = number == 3 ? 20.567 : number == 1 ? -12.5 : 1.0;
        return true;
    }
};

TEST(FagorBlockParser, HeaderLabelBodyRepetitionComment) {
    const ParsedBlock b = parse("/1 /3 N20 G90 G01 X100 Z200 F2000 ; cut");
    EXPECT_EQ(b.skipMarks, 0b101);
    EXPECT_EQ(b.label, 20);
    ASSERT_EQ(b.kind, ParsedBlock::Kind::Iso);
    ASSERT_EQ(b.iso.gCount, 2);
    EXPECT_EQ(b.iso.g[1].value, 1.0);
    EXPECT_TRUE(b.iso.has(Axis::X));
    EXPECT_DOUBLE_EQ(b.iso.axes[0].value, 100.0);
    EXPECT_DOUBLE_EQ(b.iso.f.value, 2000.0);
    const ParsedBlock rpt = parse("(RPT N10, N20) N3");
    ASSERT_EQ(rpt.kind, ParsedBlock::Kind::HighLevel);
    EXPECT_EQ(rpt.highLevel, "RPT N10, N20");
    EXPECT_EQ(rpt.repetition, 3);
    EXPECT_EQ(parse("X10 N3").repetition, 3);
    EXPECT_EQ(parse("; only a comment").kind, ParsedBlock::Kind::Comment);
    EXPECT_EQ(parse("N12345678").label, 12345678);
    EXPECT_EQ(parse("/ X1").skipMarks, 1);  // '/' is '/1'
}

TEST(FagorBlockParser, TransferHeaderAndEndOfFileCharacter) {
    EXPECT_EQ(parse("%Fagor Automation, MX,", true).kind, ParsedBlock::Kind::Header);
    const ParsedBlock end = parse("N10 M30\x1A garbage");
    EXPECT_TRUE(end.endOfFile);
    EXPECT_EQ(end.iso.mCount, 1);
    EXPECT_TRUE(parse("\x04").endOfFile);
}

TEST(FagorBlockParser, WordsBoundToTheirFunction) {
    const ParsedBlock a = parse("G02 G36 R10 X60 Z50 R28");
    EXPECT_DOUBLE_EQ(a.iso.cornerR.value, 10.0);
    EXPECT_DOUBLE_EQ(a.iso.r.value, 28.0);
    const ParsedBlock b = parse("G42 N10 G01 X1");
    EXPECT_DOUBLE_EQ(b.iso.gN.value, 10.0);
    EXPECT_EQ(b.repetition, -1);
    EXPECT_DOUBLE_EQ(parse("G159 N6").iso.gN.value, 6.0);
    EXPECT_FALSE(parse("G04 K").iso.gK.hasValue);
    EXPECT_DOUBLE_EQ(parse("G04 K50").iso.gK.value, 50.0);
    const ParsedBlock c = parse("G51 A80 E0.02 B30");
    EXPECT_DOUBLE_EQ(c.iso.e51.value, 0.02);
    EXPECT_DOUBLE_EQ(c.iso.b51.value, 30.0);
    const ParsedBlock m19 = parse("M19 S-30");
    EXPECT_DOUBLE_EQ(m19.iso.m[0].s.value, -30.0);
    EXPECT_FALSE(m19.iso.s.present);
    const ParsedBlock g16 = parse("G16 ZC");
    ASSERT_EQ(g16.iso.axisCount, 2);
    EXPECT_EQ(g16.iso.axisOrder[0], Axis::Z);
    EXPECT_EQ(g16.iso.axisOrder[1], Axis::C);
    EXPECT_FALSE(g16.iso.axes[static_cast<size_t>(axisIndex(Axis::C))].hasValue);
}

TEST(FagorBlockParser, SpacesBareLettersAndSigns) {
    const ParsedBlock b = parse("G 1 X - 20.5 Z");
    EXPECT_EQ(b.iso.g[0].value, 1.0);
    EXPECT_DOUBLE_EQ(b.iso.axes[0].value, -20.5);
    EXPECT_TRUE(b.iso.has(Axis::Z));
    EXPECT_FALSE(b.iso.axes[2].hasValue);          // Z alone is Z0
    EXPECT_EQ(problem("X20 . 5").code, "syntax");  // no blanks inside a number
    const ParsedBlock g = parse("G X.5");
    EXPECT_FALSE(g.iso.g[0].hasValue);  // bare G is G00
    EXPECT_DOUBLE_EQ(g.iso.axes[0].value, 0.5);
}

TEST(FagorBlockParser, ParametersInWords) {
    Values values;
    BlockParser parser(&values);
    ParsedBlock b;
    ASSERT_TRUE(parser.parse("GP0 XP1 Z-P3", false, b));
    EXPECT_DOUBLE_EQ(b.iso.g[0].value, 1.0);
    EXPECT_DOUBLE_EQ(b.iso.axes[0].value, -12.5);
    EXPECT_DOUBLE_EQ(b.iso.axes[2].value, -20.567);
    EXPECT_TRUE(b.iso.axes[0].parameter);
    EXPECT_FALSE(parser.parse("X10 ZP99", false, b));
    EXPECT_EQ(parser.problem().offset, 5u);
    EXPECT_FALSE(parser.parse("GP3", false, b));  // G20.567 is not a whole number
}

TEST(FagorBlockParser, OrderOfWords) {
    EXPECT_EQ(parse("G01 X1 F100 S200 T1 D1 M3").outOfOrder, 0);
    EXPECT_EQ(parse("G01 F100 X1").outOfOrder, 9);
    EXPECT_EQ(parse("M19 S100").outOfOrder, 0);
    EXPECT_EQ(parse("Q90 X30").outOfOrder, 0);
}

TEST(FagorBlockParser, Errors) {
    EXPECT_EQ(problem("").messageTemplate, "empty block: a block needs at least a comment");
    EXPECT_EQ(problem("G01 x10").offset, 4u);
    EXPECT_EQ(problem("X10 X20").offset, 4u);
    EXPECT_EQ(problem("X10 G01").offset, 4u);
    EXPECT_EQ(problem("X123456").code, "format");
    EXPECT_EQ(problem("X1.123456").code, "format");
    EXPECT_EQ(problem("N123456789").code, "format");
    EXPECT_EQ(problem("X1 N3 F2").offset, 6u);
    EXPECT_EQ(problem("(P1=2").code, "syntax");
    EXPECT_EQ(problem("D256").code, "format");
    EXPECT_EQ(problem("G320").code, "format");
    EXPECT_EQ(problem("M1 M2 M3 M4 M5 M6 M7 M8").offset, 21u);
    EXPECT_EQ(problem("NP1 X1").offset, 0u);
    EXPECT_EQ(problem("XP(1)").code, "syntax");
    EXPECT_EQ(problem("H5").messageTemplate, "unknown word '{1}'");
    EXPECT_EQ(problem("G14 X10").code, "syntax");
    EXPECT_EQ(problem("F-5").code, "format");
}

}  // namespace
}  // namespace kerf::fagor
