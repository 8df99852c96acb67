#include "core/program/mapped_copy.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "core/program/source_text.h"
#include "test_paths.h"

namespace kerf::program {
namespace {

namespace fs = std::filesystem;

class MappedCopyTest : public testing::Test {
protected:
    void SetUp() override { dir = test::uniqueTempDir("mapped_copy"); }
    void TearDown() override { fs::remove_all(dir); }

    fs::path write(const std::string& name, const std::string& bytes) {
        const fs::path path = dir / name;
        std::ofstream(path, std::ios::binary) << bytes;
        return path;
    }

    fs::path dir;
};

// A program of about `bytes` bytes: numbered straight lines, every one different.
std::string longProgram(size_t bytes) {
    std::string text = "BEGIN PGM LONG MM\n";
    for (int n = 1; text.size() < bytes; ++n) {
        text += std::to_string(n) + " L X+" + std::to_string(n % 997) + ".125 Y-" +
                std::to_string(n % 613) + ".5 F1000\n";
    }
    return text;
}

// Resident kilobytes of the mapping that holds `address` (/proc/self/smaps), -1 when none does.
long residentKb(const void* address) {
    std::ifstream smaps("/proc/self/smaps");
    const auto at = reinterpret_cast<uintptr_t>(address);
    bool inside = false;
    std::string line;
    while (std::getline(smaps, line)) {
        uintptr_t begin = 0;
        uintptr_t end = 0;
        if (std::sscanf(line.c_str(), "%lx-%lx ", &begin, &end) == 2 && line.find(' ') < 30) {
            inside = at >= begin && at < end;
        } else if (inside && line.rfind("Rss:", 0) == 0) {
            return std::stol(line.substr(4));
        }
    }
    return -1;
}

TEST_F(MappedCopyTest, ALongProgramKeepsItsTextWhenTheFileIsTruncatedAndRewritten) {
    const std::string text = longProgram(6u << 20);
    const fs::path path = write("LONG.H", text);
    auto source = SourceText::load(path);
    ASSERT_TRUE(source.ok());
    // Another process empties the file in place, then writes other text into it: a mapping of
    // the file itself would die with SIGBUS here or read the new text.
    fs::resize_file(path, 0);
    std::ofstream(path, std::ios::binary | std::ios::in) << std::string(text.size(), 'Z');
    EXPECT_EQ((*source)->encoding(), Encoding::Utf8);
    EXPECT_EQ((*source)->text().size(), text.size());
    EXPECT_TRUE((*source)->text() == text);
}

TEST_F(MappedCopyTest, TextReleasedBehindTheReaderIsNotResidentAndReadsTheSameAgain) {
    const std::string text = longProgram(16u << 20);
    auto source = SourceText::load(write("LONG.H", text));
    ASSERT_TRUE(source.ok());
    const std::string_view mapped = (*source)->text();
    ASSERT_GE(residentKb(mapped.data()), 0) << "the text is not a mapping of its own";

    // Read it all, as a run does, releasing every step: at most about two steps stay resident.
    uint64_t sum = 0;
    long mostResident = 0;
    for (size_t at = 0; at < mapped.size(); ++at) {
        sum += static_cast<unsigned char>(mapped[at]);
        if (at % kTextReleaseStep == kTextReleaseStep - 1) {
            releasePagesBefore(mapped, at);
            mostResident = std::max(mostResident, residentKb(mapped.data()));
        }
    }
    EXPECT_GT(sum, 0u);
    EXPECT_LE(mostResident, 2 * static_cast<long>(kTextReleaseStep / 1024) + 8);

    // A jump back reads the released text again, unchanged.
    EXPECT_TRUE(mapped == text);
    // Without releasing, the text read is resident: the measure above measures something.
    EXPECT_GT(residentKb(mapped.data()), static_cast<long>(text.size() / 2048));
}

TEST_F(MappedCopyTest, ACharacterAcrossTheCheckedPiecesStaysUtf8) {
    // "ü" (C3 BC) and "€" (E2 82 AC) placed across the first split of the UTF-8 check.
    std::string text = longProgram(6u << 20);
    text.replace(kTextReleaseStep - 1, 2, "\xC3\xBC");
    text.replace(2 * kTextReleaseStep - 2, 3, "\xE2\x82\xAC");
    auto source = SourceText::load(write("LONG.H", text));
    ASSERT_TRUE(source.ok());
    EXPECT_EQ((*source)->encoding(), Encoding::Utf8);
    EXPECT_TRUE((*source)->text() == text);
}

TEST_F(MappedCopyTest, ALongProgramInCp1252OrUtf16IsConvertedAsAShortOneIs) {
    // One byte 0xFC (cp1252 "ü") near the end: not UTF-8, so the whole text is cp1252.
    std::string latin = longProgram(6u << 20);
    latin +=
        "; Werkst\xFC"
        "ck\n";
    auto cp1252 = SourceText::load(write("LATIN.H", latin));
    ASSERT_TRUE(cp1252.ok());
    EXPECT_EQ((*cp1252)->encoding(), Encoding::Cp1252);
    std::string expected = longProgram(6u << 20) +
                           "; Werkst\xC3\xBC"
                           "ck\n";
    EXPECT_TRUE((*cp1252)->text() == expected);

    // UTF-16 little endian with its byte order mark: every ASCII byte followed by a zero.
    const std::string ascii = longProgram(3u << 20);
    std::string utf16 = "\xFF\xFE";
    for (char c : ascii) {
        utf16.push_back(c);
        utf16.push_back('\0');
    }
    auto wide = SourceText::load(write("WIDE.H", utf16));
    ASSERT_TRUE(wide.ok());
    EXPECT_EQ((*wide)->encoding(), Encoding::Utf16Le);
    EXPECT_TRUE((*wide)->text() == ascii);
}

}  // namespace
}  // namespace kerf::program
