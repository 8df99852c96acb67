// FK blocks: every data word lands where the solver expects it; malformed blocks are refused at
// the word that is wrong.
#include <gtest/gtest.h>

#include "core/interp/klartext/block_parser.h"
#include "core/interp/klartext/block_reader.h"

namespace kerf::klartext {
namespace {

ParsedBlock parse(std::string_view text) {
    BlockReader reader(text);
    program::LogicalLine line;
    EXPECT_TRUE(reader.next(line));
    BlockParser parser(nullptr);
    ParsedBlock block;
    EXPECT_TRUE(parser.parse(line, block)) << text << ": " << parser.problem().messageTemplate;
    return block;
}

FkBlock fk(std::string_view text) {
    return std::get<FkBlock>(parse(text).statement);
}

std::pair<size_t, std::string> problem(std::string_view text) {
    BlockReader reader(text);
    program::LogicalLine line;
    reader.next(line);
    BlockParser parser(nullptr);
    ParsedBlock block;
    EXPECT_FALSE(parser.parse(line, block)) << text;
    return {parser.problem().offset, parser.problem().messageTemplate};
}

TEST(BlockParserFk, SeedBlocks) {
    const FkBlock arc = fk("17 FC DR- R30 CCX+30 CCY+30");
    EXPECT_EQ(arc.element.kind, fk::FkKind::Arc);
    EXPECT_EQ(arc.element.rotation, fk::FkRotation::Cw);
    EXPECT_DOUBLE_EQ(*arc.element.radius, 30.0);
    EXPECT_DOUBLE_EQ(arc.centre[0]->value, 30.0);
    EXPECT_FALSE(arc.centre[0]->incremental);
    EXPECT_EQ(arc.element.blockNumber, 17);
    const FkBlock line = fk("18 FL AN+60 PDX+30 PDY+30 D10");
    EXPECT_EQ(line.element.kind, fk::FkKind::Line);
    EXPECT_DOUBLE_EQ(line.element.an->value, 60.0);
    EXPECT_DOUBLE_EQ(line.pointAtDistance[1]->value, 30.0);
    EXPECT_DOUBLE_EQ(*line.element.distance, 10.0);
    const FkBlock polar = fk("21 FC DR- R20 CCPR+55 CCPA+60");
    EXPECT_DOUBLE_EQ(polar.element.ccpr->value, 55.0);
    EXPECT_DOUBLE_EQ(polar.element.ccpa->value, 60.0);
    EXPECT_EQ(std::get<FkSelect>(parse("19 FSELECT 3").statement).choice, 3);
    const FkPole pole = std::get<FkPole>(parse("20 FPOL X+30 Y+25").statement);
    EXPECT_DOUBLE_EQ(*pole.coords[1], 25.0);
    EXPECT_FALSE(pole.coords[2]);
}

TEST(BlockParserFk, RelativeDataAuxiliaryPointsAndCommonWords) {
    const FkBlock t = fk("15 FCT IX+20 DR- R20 CCA+90 RX 13 RL F200 M8");
    EXPECT_EQ(t.element.kind, fk::FkKind::TangentArc);
    ASSERT_TRUE(t.end[0]);
    EXPECT_TRUE(t.end[0]->incremental);
    EXPECT_EQ(t.end[0]->reference, 13);
    EXPECT_DOUBLE_EQ(*t.element.endAngleAboutCentre, 90.0);
    EXPECT_EQ(t.words.comp, CompWord::Left);
    EXPECT_DOUBLE_EQ(t.words.feed.value, 200.0);
    EXPECT_EQ(t.words.m.list[0].number, 8);
    const FkBlock p = fk("FLT IPR+35 PA+0 RPR 13 P2X+1 P2Y-2 LEN 5 CLSD- R0");
    EXPECT_EQ(p.element.kind, fk::FkKind::TangentLine);
    EXPECT_EQ(p.element.pr->reference, 13);
    ASSERT_TRUE(p.pointsOn[1][1]);
    EXPECT_DOUBLE_EQ(*p.pointsOn[1][1], -2.0);
    EXPECT_FALSE(p.pointsOn[0][0]);
    EXPECT_DOUBLE_EQ(*p.element.length, 5.0);
    EXPECT_TRUE(p.element.closeEnd);
    EXPECT_EQ(p.words.comp, CompWord::Off);
    EXPECT_DOUBLE_EQ(*fk("FC R0.5 DR+").element.radius, 0.5);  // a radius, not R0
    const FkBlock c = fk("FC ICCX+5 RCCX 7 ICCPA-10 RCCPA 8 IPDX+1 RPDX 9 PDY+0 D2 CLSD+");
    EXPECT_EQ(c.centre[0]->reference, 7);
    EXPECT_EQ(c.element.ccpa->reference, 8);
    EXPECT_EQ(c.pointAtDistance[0]->reference, 9);
    EXPECT_TRUE(c.element.closeStart);
}

// FK in the ZX and YZ planes: Z words are read by axis; the interpreter picks the plane's two.
TEST(BlockParserFk, CoordinatesOfEveryAxis) {
    const FkBlock b = fk("FC Z+5 IX-2 CCZ+1 ICCX+3 RCCX 4 PDZ+7 P1Z+1 P1X+2 D1 R5 DR+");
    EXPECT_DOUBLE_EQ(b.end[2]->value, 5.0);
    EXPECT_TRUE(b.end[0]->incremental);
    EXPECT_FALSE(b.end[1]);
    EXPECT_DOUBLE_EQ(b.centre[2]->value, 1.0);
    EXPECT_EQ(b.centre[0]->reference, 4);
    EXPECT_DOUBLE_EQ(b.pointAtDistance[2]->value, 7.0);
    EXPECT_DOUBLE_EQ(*b.pointsOn[0][2], 1.0);
    EXPECT_DOUBLE_EQ(*b.pointsOn[0][0], 2.0);
    const FkPole pole = std::get<FkPole>(parse("FPOL Z+3 X+4").statement);
    EXPECT_DOUBLE_EQ(*pole.coords[2], 3.0);
    EXPECT_FALSE(pole.coords[1]);
}

TEST(BlockParserFk, Errors) {
    EXPECT_EQ(problem("FL X+10 RX 12").first, 8u);  // RX without IX
    EXPECT_EQ(problem("FL P1X+10").first, 3u);      // P1Y missing
    EXPECT_EQ(problem("FL X+1 X+2").first, 7u);     // twice
    EXPECT_EQ(problem("FC DR R5").first, 6u);
    EXPECT_EQ(problem("FSELECT").first, 7u);
    EXPECT_EQ(problem("FSELECT 0").first, 8u);
    EXPECT_EQ(problem("FPOL X+1").first, 8u);
    EXPECT_EQ(problem("FPOL X+1 Y+2 Z+3").first, 16u);     // three coordinates
    EXPECT_EQ(problem("FL P2X+1 P2Y+1 P2Z+1").first, 3u);  // a point has two coordinates
    EXPECT_EQ(problem("FL CLSD").first, 7u);
}

}  // namespace
}  // namespace kerf::klartext
