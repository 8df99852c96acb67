// The one-pass reading of literal L blocks must give what the general parser gives. The general
// parser reads a lower-case head too ("l X+1"), which the one-pass reading leaves to it: each
// block is parsed both ways and the statements compared field by field.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "core/interp/klartext/block_parser.h"
#include "core/interp/klartext/block_reader.h"

namespace kerf::klartext {
namespace {

// Parses the first block of `text` into `out` with `parser`; false on a syntax error.
bool parseInto(BlockParser& parser, std::string_view text, ParsedBlock& out) {
    BlockReader reader(text);
    program::LogicalLine line;
    EXPECT_TRUE(reader.next(line));
    return parser.parse(line, out);
}

void expectSameLine(const LinearBlock& a, const LinearBlock& b, std::string_view text) {
    SCOPED_TRACE(std::string(text));
    EXPECT_EQ(a.coords.present, b.coords.present);
    for (size_t i = 0; i < a.coords.axes.size(); ++i) {
        EXPECT_EQ(a.coords.axes[i].present, b.coords.axes[i].present) << i;
        EXPECT_EQ(a.coords.axes[i].incremental, b.coords.axes[i].incremental) << i;
        // Bit for bit: the trace prints what the value is, so -0 and 0 differ.
        EXPECT_EQ(std::signbit(a.coords.axes[i].value), std::signbit(b.coords.axes[i].value)) << i;
        EXPECT_EQ(a.coords.axes[i].value, b.coords.axes[i].value) << i;
    }
    EXPECT_EQ(a.words.comp, b.words.comp);
    EXPECT_EQ(a.words.feed.kind, b.words.feed.kind);
    EXPECT_EQ(a.words.feed.value, b.words.feed.value);
    ASSERT_EQ(a.words.m.count, b.words.m.count);
    for (size_t i = 0; i < a.words.m.list.size(); ++i) {
        EXPECT_EQ(a.words.m.list[i].number, b.words.m.list[i].number) << i;
        EXPECT_EQ(a.words.m.list[i].parameter, b.words.m.list[i].parameter) << i;
        EXPECT_EQ(a.words.m.list[i].maxParameter, b.words.m.list[i].maxParameter) << i;
    }
}

// `rest` after "7 L" and after "7 l" (or another number and blanks before the head): the same
// block number, block skip, statement and outcome.
void expectSameAsGeneralParser(const std::string& rest, const std::string& number = "7 ") {
    BlockParser fast(nullptr), general(nullptr);
    ParsedBlock a, b;
    const std::string upperHead = number + "L" + rest, lowerHead = number + "l" + rest;
    const bool okA = parseInto(fast, upperHead, a);
    const bool okB = parseInto(general, lowerHead, b);
    ASSERT_EQ(okA, okB) << upperHead;
    if (!okA) {
        EXPECT_EQ(fast.problem().offset, general.problem().offset) << upperHead;
        EXPECT_EQ(fast.problem().messageTemplate, general.problem().messageTemplate) << upperHead;
        return;
    }
    EXPECT_EQ(a.blockNumber, b.blockNumber);
    EXPECT_EQ(a.hidden, b.hidden);
    ASSERT_EQ(a.statement.index(), b.statement.index()) << upperHead;
    if (const auto* line = std::get_if<LinearBlock>(&a.statement))
        expectSameLine(*line, std::get<LinearBlock>(b.statement), upperHead);
}

TEST(LiteralLine, ReadsTheWordsOfACamBlock) {
    BlockParser parser(nullptr);
    ParsedBlock block;
    ASSERT_TRUE(parseInto(parser, "15 L X+0.2000 Y-12.5 Z-0.9857 R0 F1500 M3 M08", block));
    EXPECT_EQ(block.blockNumber, 15);
    const auto& line = std::get<LinearBlock>(block.statement);
    EXPECT_EQ(line.coords.present, axisBit(Axis::X) | axisBit(Axis::Y) | axisBit(Axis::Z));
    EXPECT_EQ(line.coords[Axis::X].value, 0.2);
    EXPECT_EQ(line.coords[Axis::Y].value, -12.5);
    EXPECT_EQ(line.coords[Axis::Z].value, -0.9857);
    EXPECT_FALSE(line.coords[Axis::X].incremental);
    EXPECT_EQ(line.words.comp, CompWord::Off);
    EXPECT_EQ(line.words.feed.kind, FeedWord::Kind::Value);
    EXPECT_EQ(line.words.feed.value, 1500.0);
    ASSERT_EQ(line.words.m.count, 2);
    EXPECT_EQ(line.words.m.list[0].number, 3);
    EXPECT_EQ(line.words.m.list[1].number, 8);
}

TEST(LiteralLine, GivesWhatTheGeneralParserGives) {
    for (const char* rest : {
             " X+0.2000 Y+0.0000 Z-0.9857",
             " X-0.0000",
             " X+5.",
             " X+.5",
             " X5,25 Y-3,5",
             " Z+5 R0 FMAX M3",
             " X+1 RL F200",
             " X+1 RR F.5",
             " X+1 FMAX F100",
             " X+1 F100 FMAX",
             " A+90 C-45.5 U+1 V+2 W+3",
             " X+1 ;comment",
             "\tX+1\tY+2",
             " X+123456789012345",
             " X+1234567890123456",
             " X+0.1234567890123456",
             " X+1 M140",
             " X+1 M03 M00003",
             " X+1 M3 M4 M5 M6 M7 M8",
             " X+1 M3 M4 M5 M6 M7 M8 M9",
             " X+1 M10000",
             " X+1 M120 LA5",
             " X+1 M94 C",
             " X+1 M118 X+1",
             " X+1 M140 MB MAX",
             " X+1 X+2",
             " X+1Y+2",
             " X+ 1",
             " X 1",
             " X+.",
             " X+5, Y+1",
             " X+1.5.",
             " IX+1 Y+2",
             " X+Q1",
             " X+(1+2)",
             " x+1",
             " X+1 R0X",
             " X+1 RLX",
             " X+1 R",
             " X+1 F",
             " X+1 F AUTO",
             " X+1 FU0.1",
             " X+1 M",
             " PR+5 PA+30",
             " R0",
             " M3",
             " F100",
             "",
             " X+1 R0 R0",
             " X+1 RL R0",
         }) {
        expectSameAsGeneralParser(rest);
    }
}

TEST(LiteralLine, ReadsNumbersOfEveryLengthAsTheGeneralParserDoes) {
    // Numbers are read eight bytes at a time where they end within them: every split of digits
    // around the separator, at the end of the line (read from its last eight bytes) and before
    // another word, on a line shorter than eight bytes too.
    const std::string digits = "9876543210";
    for (size_t integral = 0; integral <= digits.size(); ++integral) {
        for (int decimals = -1; decimals <= 9; ++decimals) {
            for (const char* separator : {".", ","}) {
                std::string number = digits.substr(0, integral);
                if (decimals >= 0)
                    number += separator + digits.substr(0, static_cast<size_t>(decimals));
                for (const char* after : {"", " Y+1", " F1500", "\xc3\xa4", "-", "X"}) {
                    expectSameAsGeneralParser(" X+" + number + after);
                    expectSameAsGeneralParser(" X+" + number + after, "");
                    expectSameAsGeneralParser(" F" + number + after, "");
                }
            }
        }
    }
}

TEST(LiteralLine, ReadsTheBlockNumberAsTheGeneralParserDoes) {
    for (const char* number :
         {"", "0012 ", "12  ", "12\t", " 12 ", "12 /1 ", "/ ", "12/ ", "123456789012345678 ",
          "12345678901234567 ", "99999999999999999999 ", "12;", "12X "}) {
        expectSameAsGeneralParser(" X+1 Y-2", number);
    }
}

TEST(LiteralLine, ReadsBlockNumbersOfEveryLength) {
    // Fewer than eight digits are read at once, longer numbers digit by digit.
    const std::string digits = "12345678901234567";
    for (size_t length = 1; length <= digits.size(); ++length) {
        for (const char* rest : {" L X+1", " l X+1", " L", " BEGIN PGM A MM"}) {
            BlockParser parser(nullptr);
            ParsedBlock block;
            const std::string number = digits.substr(0, length);
            ASSERT_TRUE(parseInto(parser, number + rest, block)) << number + rest;
            EXPECT_EQ(block.blockNumber, std::stoll(number)) << number + rest;
        }
    }
}

TEST(LiteralLine, ABlockAfterAnotherLineKeepsNothingOfIt) {
    BlockParser parser(nullptr), general(nullptr);
    ParsedBlock reused, fresh;
    ASSERT_TRUE(parseInto(parser, "1 L X+1 Y+2 A+3 RL F100 M3 M8", reused));
    ASSERT_TRUE(parseInto(parser, "2 L Z+5", reused));
    ASSERT_TRUE(parseInto(general, "2 l Z+5", fresh));
    expectSameLine(std::get<LinearBlock>(reused.statement), std::get<LinearBlock>(fresh.statement),
                   "2 L Z+5");
    EXPECT_EQ(std::get<LinearBlock>(reused.statement).coords.present, axisBit(Axis::Z));
    EXPECT_EQ(std::get<LinearBlock>(reused.statement).words.m.count, 0);
    // A block the one pass declines after starting on it.
    ASSERT_TRUE(parseInto(parser, "3 L X+1 Y+Q1", reused));
    ASSERT_TRUE(parseInto(general, "3 l X+1 Y+Q1", fresh));
    expectSameLine(std::get<LinearBlock>(reused.statement), std::get<LinearBlock>(fresh.statement),
                   "3 L X+1 Y+Q1");
    // The same text again, as a loop runs it: given up on once, parsed by the general parser.
    const std::string loopLine = "3 L X+1 Y+Q1";
    for (int pass = 0; pass < 2; ++pass) {
        ASSERT_TRUE(parseInto(parser, loopLine, reused));
        expectSameLine(std::get<LinearBlock>(reused.statement),
                       std::get<LinearBlock>(fresh.statement), loopLine);
        EXPECT_EQ(reused.blockNumber, 3);
    }
    // Another statement after a line.
    ASSERT_TRUE(parseInto(parser, "4 LBL 1", reused));
    EXPECT_TRUE(std::holds_alternative<Label>(reused.statement));
    ASSERT_TRUE(parseInto(parser, "5 ; only a comment", reused));
    EXPECT_TRUE(std::holds_alternative<Empty>(reused.statement));
}

TEST(LiteralLine, ASyntaxErrorIsReportedWhereTheGeneralParserReportsIt) {
    BlockParser parser(nullptr);
    ParsedBlock block;
    EXPECT_FALSE(parseInto(parser, "8 L X+1 X+2", block));
    EXPECT_EQ(parser.problem().messageTemplate, "axis {1} is programmed twice");
    EXPECT_EQ(parser.problem().offset, 8u);
}

}  // namespace
}  // namespace kerf::klartext
