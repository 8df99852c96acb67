#include "core/program/line_reader.h"

#include <chrono>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/program/source_text.h"

namespace kerf::program {
namespace {

std::vector<std::string> readAll(std::string_view text, bool join = true) {
    LineReader reader(text);
    LogicalLine line;
    std::vector<std::string> out;
    while (reader.next(line, join))
        out.emplace_back(line.text);
    return out;
}

TEST(LineReader, AllLineEndings) {
    EXPECT_EQ(readAll("a\nb\r\nc\rd"), (std::vector<std::string>{"a", "b", "c", "d"}));
    EXPECT_EQ(readAll("a\n\nb\n"), (std::vector<std::string>{"a", "", "b"}));
    EXPECT_EQ(readAll("x\r"), (std::vector<std::string>{"x"}));
}

TEST(LineReader, JoinsTildeContinuations) {
    auto lines = readAll("1 Q1 = 1 + ~\r\n  2 ~\n  * 3\n4 END");
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "1 Q1 = 1 +  2  * 3");
    EXPECT_EQ(lines[1], "4 END");
}

TEST(LineReader, MapsJoinedOffsetsBackToLinesAndColumns) {
    LineReader reader("1 Q1 = 1 + ~\n  2 / x\nnext");
    LogicalLine line;
    ASSERT_TRUE(reader.next(line));
    size_t x = line.text.find('x');
    EXPECT_EQ(line.lineAt(x), 2u);
    EXPECT_EQ(line.columnAt(x), 7u);
    EXPECT_EQ(line.lineAt(0), 1u);
    EXPECT_EQ(reader.line(), 3u);  // the next line to read
}

TEST(LineReader, SeekAndAppend) {
    LineReader reader("a\nb\nc\n");
    LogicalLine line;
    reader.next(line);
    const size_t afterA = reader.offset();
    reader.next(line);
    reader.seek(afterA, 2);
    ASSERT_TRUE(reader.next(line));
    EXPECT_EQ(line.text, "b");
    ASSERT_TRUE(reader.appendNextLine(line));
    EXPECT_EQ(line.segments.size(), 2u);
    EXPECT_EQ(line.text, "b c");
}

TEST(Columns, CountCharactersNotBytes) {
    EXPECT_EQ(columnOf("\xC3\xA4x", 2), 2u);  // after one two-byte character
    EXPECT_EQ(columnOf("abc", 0), 1u);
}

// CR-only line ends: every line used to search the rest of the file for an LF (200k lines: 13 s).
TEST(LineReader, CrOnlyLineEndsReadInLinearTime) {
    std::string text;
    for (int i = 0; i < 200000; ++i)
        text += "G01 X" + std::to_string(i) + "\r";
    const auto start = std::chrono::steady_clock::now();
    LineReader reader(text);
    LogicalLine line;
    size_t count = 0;
    std::string_view last;
    while (reader.next(line)) {
        ++count;
        last = line.text;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(count, 200000u);
    EXPECT_EQ(last, "G01 X199999");
    EXPECT_EQ(reader.line(), 200001u);
    // Linear: a few milliseconds; quadratic: about 4 GB of scanning.
    EXPECT_LT(seconds, 1.0);
}

TEST(LineReader, MixedEndsAfterASeekBack) {
    const std::string text = "a\rb\nc\rd\r\ne";
    LineReader reader(text);
    LogicalLine line;
    ASSERT_TRUE(reader.next(line));
    ASSERT_TRUE(reader.next(line));
    ASSERT_TRUE(reader.next(line));
    EXPECT_EQ(line.text, "c");
    reader.seek(0, 1);  // the remembered LF is past where reading continues
    std::vector<std::string> again;
    while (reader.next(line))
        again.emplace_back(line.text);
    EXPECT_EQ(again, (std::vector<std::string>{"a", "b", "c", "d", "e"}));
}

}  // namespace
}  // namespace kerf::program
