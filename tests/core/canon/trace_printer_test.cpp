#include "core/canon/trace_printer.h"

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace kerf::canon {
namespace {

Command lineTo(uint32_t fileId, uint32_t line, double x) {
    Pose p;
    p[Axis::X] = x;
    return Command{SourceLocation{fileId, line, 1, -1}, LinearMove{p, 100}};
}

std::vector<std::string> linesOf(std::FILE* file) {
    std::fflush(file);
    std::rewind(file);
    std::vector<std::string> lines;
    std::string current;
    for (int c = std::fgetc(file); c != EOF; c = std::fgetc(file)) {
        if (c == '\n') {
            lines.push_back(current);
            current.clear();
        } else {
            current += static_cast<char>(c);
        }
    }
    EXPECT_TRUE(current.empty()) << "a line without its newline: " << current;
    return lines;
}

TEST(TracePrinter, WritesEveryCommandInOrderAcrossManyBatches) {
    std::FILE* file = std::tmpfile();
    ASSERT_NE(file, nullptr);
    {
        TraceFormat format;
        format.fileName = [](uint32_t id) { return "SUB" + std::to_string(id) + ".H"; };
        TracePrinter printer(file, format);
        // Far more commands than one batch holds, and one from a called program.
        for (uint32_t i = 1; i <= 5000; ++i)
            printer.consume(lineTo(i == 4321 ? 2 : 0, i, i));
        EXPECT_TRUE(printer.flush());
    }
    const std::vector<std::string> lines = linesOf(file);
    ASSERT_EQ(lines.size(), 5000u);
    EXPECT_EQ(lines[0], "1:1 LINE X1.0000 Y0.0000 Z0.0000 F100.000");
    EXPECT_EQ(lines[4320], "SUB2.H:4321:1 LINE X4321.0000 Y0.0000 Z0.0000 F100.000");
    EXPECT_EQ(lines[4999], "5000:1 LINE X5000.0000 Y0.0000 Z0.0000 F100.000");
    for (uint32_t i = 1; i <= 5000; ++i) {
        const std::string start = (i == 4321 ? "SUB2.H:" : "") + std::to_string(i) + ":1 ";
        ASSERT_EQ(lines[i - 1].rfind(start, 0), 0u) << lines[i - 1];
    }
    std::fclose(file);
}

TEST(TracePrinter, FlushWritesWhatWasConsumedSoFar) {
    std::FILE* file = std::tmpfile();
    ASSERT_NE(file, nullptr);
    TracePrinter printer(file, TraceFormat{});
    for (uint32_t i = 1; i <= 3; ++i)
        printer.consume(lineTo(0, i, 0.5));
    ASSERT_TRUE(printer.flush());
    EXPECT_EQ(linesOf(file).size(), 3u);  // before the printer is destroyed
    std::fseek(file, 0, SEEK_END);
    printer.consume(lineTo(0, 4, -0.25));
    ASSERT_TRUE(printer.flush());
    const std::vector<std::string> lines = linesOf(file);
    ASSERT_EQ(lines.size(), 4u);
    EXPECT_EQ(lines[3], "4:1 LINE X-0.2500 Y0.0000 Z0.0000 F100.000");
}

TEST(TracePrinter, FlushReportsAStreamThatCannotBeWritten) {
    std::FILE* full = std::fopen("/dev/full", "wb");
    if (full == nullptr) GTEST_SKIP() << "no /dev/full";
    {
        TracePrinter printer(full, TraceFormat{});
        for (uint32_t i = 1; i <= 3000; ++i)
            printer.consume(lineTo(0, i, i));
        EXPECT_FALSE(printer.flush());
    }
    std::fclose(full);
}

}  // namespace
}  // namespace kerf::canon
