#include "core/program/encoding.h"

#include <gtest/gtest.h>

#include "core/program/source_text.h"

namespace kerf::program {
namespace {

TEST(Encoding, DetectsUtf8Cp1252AndGbk) {
    EXPECT_EQ(detectEncoding("L X+1 ; Werkst\xC3\xBC"
                             "ck"),
              Encoding::Utf8);
    EXPECT_EQ(detectEncoding("; Werkst\xFC"
                             "ck \xE4"
                             "ndern"),
              Encoding::Cp1252);
    // "加工" (machining) in GBK: two pairs of high bytes.
    EXPECT_EQ(detectEncoding("; \xBC\xD3\xB9\xA4 L X+1"), Encoding::Gbk);
}

TEST(Encoding, ConvertsToUtf8) {
    EXPECT_EQ(toUtf8("\xFC", Encoding::Cp1252), "\xC3\xBC");  // ü
    EXPECT_EQ(toUtf8("\xBC\xD3\xB9\xA4", Encoding::Gbk), "\xE5\x8A\xA0\xE5\xB7\xA5");
    EXPECT_EQ(fromUtf8("\xC3\xBC", Encoding::Cp1252), "\xFC");
}

TEST(Encoding, RejectsBrokenUtf8) {
    EXPECT_FALSE(isValidUtf8("\xC3"));
    EXPECT_FALSE(isValidUtf8("\xE0\x80\x80"));  // overlong
    EXPECT_FALSE(isValidUtf8("\xED\xA0\x80"));  // surrogate
    EXPECT_TRUE(isValidUtf8("plain ascii text that is longer than eight bytes"));
}

// Windows editors save "Unicode" text as UTF-16 with a byte order mark. It was read byte by
// byte: every other byte a NUL, and an error "unexpected '\0'" on every line.
TEST(Encoding, Utf16WithAByteOrderMarkIsReadAndSavedAsIt) {
    using namespace std::string_literals;
    const std::string little =
        "\xFF\xFE"
        "L\0 \0X\0+\0"
        "1\0\xFC\0\n\0"s;  // "L X+1ü\n"
    const std::string big =
        "\xFE\xFF"
        "\0L\0 \0X\0+\0"
        "1\0\xFC\0\n"s;
    EXPECT_EQ(detectEncoding(little), Encoding::Utf16Le);
    EXPECT_EQ(detectEncoding(big), Encoding::Utf16Be);
    EXPECT_EQ(toUtf8(little, Encoding::Utf16Le), "L X+1\xC3\xBC\n");
    EXPECT_EQ(toUtf8(big, Encoding::Utf16Be), "L X+1\xC3\xBC\n");
    EXPECT_EQ(fromUtf8("L X+1\xC3\xBC\n", Encoding::Utf16Le), little);
    EXPECT_EQ(fromUtf8("L X+1\xC3\xBC\n", Encoding::Utf16Be), big);
    auto source = SourceText::fromString(little, "u.H");
    EXPECT_EQ(source->encoding(), Encoding::Utf16Le);
    EXPECT_EQ(source->text(), "L X+1\xC3\xBC\n");
}

TEST(SourceText, ConvertsOnLoadAndStripsBom) {
    auto cp = SourceText::fromString("; \xFC\n", "a.H");
    EXPECT_EQ(cp->encoding(), Encoding::Cp1252);
    EXPECT_EQ(cp->text(), "; \xC3\xBC\n");
    auto bom = SourceText::fromString("\xEF\xBB\xBFL X+1", "b.H");
    EXPECT_EQ(bom->text(), "L X+1");
}

}  // namespace
}  // namespace kerf::program
