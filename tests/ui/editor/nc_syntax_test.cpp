#include "ui/editor/nc_syntax.h"

#include <QString>

#include <gtest/gtest.h>

#include "ui/editor/block_numbers.h"

namespace kerf::ui {
namespace {

using program::Dialect;

// The span covering `text` exactly, found by its position in the line.
NcSpan spanOf(const QString& line, const QString& text, NcToken token, int from = 0) {
    return {static_cast<int>(line.indexOf(text, from)), static_cast<int>(text.size()), token};
}

TEST(NcSyntax, KlartextLinearBlock) {
    const QString line = QStringLiteral("12 L X+10 Y-5.5 R0 FMAX M3 ; rough");
    const std::vector<NcSpan> expected{{0, 2, NcToken::BlockNumber},
                                       spanOf(line, "L", NcToken::Keyword, 2),
                                       spanOf(line, "X", NcToken::Address),
                                       spanOf(line, "+10", NcToken::Number),
                                       spanOf(line, "Y", NcToken::Address),
                                       spanOf(line, "-5.5", NcToken::Number),
                                       spanOf(line, "R", NcToken::Address),
                                       spanOf(line, "0", NcToken::Number, 16),
                                       spanOf(line, "FMAX", NcToken::Function),
                                       spanOf(line, "M3", NcToken::Function),
                                       spanOf(line, "; rough", NcToken::Comment)};
    EXPECT_EQ(scanNcLine(line, Dialect::Klartext), expected);
}

TEST(NcSyntax, KlartextParametersAndKeywords) {
    const QString line = QStringLiteral("3 FN 0: Q12 = +QL4");
    // "3" number, "FN" keyword, "0" number, "Q12" parameter; in "+QL4" the sign is no number
    // (no digit follows) and QL4 is a parameter.
    const std::vector<NcSpan> expected{{0, 1, NcToken::BlockNumber},
                                       {2, 2, NcToken::Keyword},
                                       {5, 1, NcToken::Number},
                                       {8, 3, NcToken::Parameter},
                                       {15, 3, NcToken::Parameter}};
    EXPECT_EQ(scanNcLine(line, Dialect::Klartext), expected);
}

TEST(NcSyntax, FagorIsoBlock) {
    const QString line = QStringLiteral("N20 G01 X30 Z-2 F0.2 P100=3 ;finish");
    const auto spans = scanNcLine(line, Dialect::Fagor);
    ASSERT_EQ(spans.size(), 10u);
    EXPECT_EQ(spans[0], (NcSpan{0, 3, NcToken::BlockNumber}));
    EXPECT_EQ(spans[1], (NcSpan{4, 3, NcToken::Function}));    // G01
    EXPECT_EQ(spans[2], (NcSpan{8, 1, NcToken::Address}));     // X
    EXPECT_EQ(spans[3], (NcSpan{9, 2, NcToken::Number}));      // 30
    EXPECT_EQ(spans[4], (NcSpan{12, 1, NcToken::Address}));    // Z
    EXPECT_EQ(spans[5], (NcSpan{13, 2, NcToken::Number}));     // -2
    EXPECT_EQ(spans[6], (NcSpan{16, 4, NcToken::Function}));   // F0.2
    EXPECT_EQ(spans[7], (NcSpan{21, 4, NcToken::Parameter}));  // P100
    EXPECT_EQ(spans[8], (NcSpan{26, 1, NcToken::Number}));     // =3
    EXPECT_EQ(spans[9], (NcSpan{28, 7, NcToken::Comment}));
}

// After a canned cycle the letters are the cycle's parameters (spec part 2 §2, G81: X Z Q R C
// [D] [L] [M] [F] [H]): M is the finishing allowance along Z, F the feed of the last roughing
// pass, D the retract distance — no M function, feed or tool offset. Before the cycle, and in a
// block without one, they are.
TEST(NcSyntax, FagorCannedCycleLettersAreParameters) {
    const QString line = QStringLiteral("N3 G81 X20 Z0 Q10 R-30 C2 D1 L0.5 M0.2 F0.1 H0");
    const auto spans = scanNcLine(line, Dialect::Fagor);
    ASSERT_EQ(spans.size(), 22u);
    EXPECT_EQ(spans[1], spanOf(line, "G81", NcToken::Function));
    const char* letters = "XZQRCDLMFH";
    for (size_t i = 0; i < 10; ++i) {
        const QString word = QStringLiteral(" ") + QLatin1Char(letters[i]);
        EXPECT_EQ(spans[2 + 2 * i],
                  (NcSpan{static_cast<int>(line.indexOf(word)) + 1, 1, NcToken::Parameter}))
            << letters[i];
        EXPECT_EQ(spans[3 + 2 * i].token, NcToken::Number) << letters[i];
    }
    // G66's S and E are the profile's first and last block numbers.
    const QString g66 = QStringLiteral("G66 X60 Z0 I2 C1 S30 E40");
    EXPECT_EQ(scanNcLine(g66, Dialect::Fagor)[9], spanOf(g66, "S", NcToken::Parameter));
    // Without a cycle the same letters are functions.
    const QString plain = QStringLiteral("N4 G01 X20 F0.1 S800 M3 D1");
    const auto words = scanNcLine(plain, Dialect::Fagor);
    ASSERT_EQ(words.size(), 8u);
    EXPECT_EQ(words[4], spanOf(plain, "F0.1", NcToken::Function));
    EXPECT_EQ(words[5], spanOf(plain, "S800", NcToken::Function));
    EXPECT_EQ(words[6], spanOf(plain, "M3", NcToken::Function));
    EXPECT_EQ(words[7], spanOf(plain, "D1", NcToken::Function));
}

TEST(NcSyntax, FagorWithoutBlockNumberHasNone) {
    const auto spans = scanNcLine(QStringLiteral("G00 X0"), Dialect::Fagor);
    ASSERT_FALSE(spans.empty());
    EXPECT_EQ(spans[0], (NcSpan{0, 3, NcToken::Function}));
}

TEST(BlockNumbers, NextPrefixFollowsTheDialect) {
    EXPECT_EQ(nextBlockPrefix(u"12 L X+0", u"11 L Y+0", Dialect::Klartext), QStringLiteral("13 "));
    EXPECT_EQ(nextBlockPrefix(u"N20 G00", u"N10 G90", Dialect::Fagor), QStringLiteral("N30 "));
    EXPECT_EQ(nextBlockPrefix(u"N20 G00", u"N15 G90", Dialect::TncIso), QStringLiteral("N25 "));
    EXPECT_EQ(nextBlockPrefix(u"N20 G00", u"", Dialect::Fagor), QStringLiteral("N30 "));
    EXPECT_EQ(nextBlockPrefix(u"; comment", u"", Dialect::Klartext), QString());
}

TEST(BlockNumbers, ReplaceKeepsTheRestOfTheLine) {
    EXPECT_EQ(withBlockNumber(u"7 L Z+50", 8, Dialect::Klartext), QStringLiteral("8 L Z+50"));
    EXPECT_EQ(withBlockNumber(u"N7 G00", 40, Dialect::Fagor), QStringLiteral("N40 G00"));
    EXPECT_EQ(withBlockNumber(u"G00", 40, Dialect::Fagor), QStringLiteral("G00"));
}

}  // namespace
}  // namespace kerf::ui
