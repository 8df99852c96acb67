#include "core/base/diagnostic.h"

#include <gtest/gtest.h>

namespace kerf {
namespace {

TEST(Diagnostic, FormatsLikeACompiler) {
    auto d = Diagnostic::make(Severity::Error, "syntax", "prog.H", 12, 5,
                              "unexpected '{1}' after {2}", "Q", "L");
    EXPECT_EQ(d.format(), "prog.H:12:5: error: unexpected 'Q' after L");
}

TEST(Diagnostic, OmitsMissingPosition) {
    auto d = Diagnostic::make(Severity::Warning, "io", "a.toml", 0, 0, "cannot read");
    EXPECT_EQ(d.format(), "a.toml: warning: cannot read");
}

TEST(Diagnostic, SubstitutesOnlyGivenArguments) {
    EXPECT_EQ(substituteArgs("{1}+{2}={3} {{x}", {"1", "2"}), "1+2= {x}");
}

TEST(Diagnostic, HasErrorsIgnoresWarnings) {
    DiagnosticList list{Diagnostic::make(Severity::Warning, "w", "f", 1, 1, "w")};
    EXPECT_FALSE(hasErrors(list));
    list.push_back(Diagnostic::make(Severity::Error, "e", "f", 1, 1, "e"));
    EXPECT_TRUE(hasErrors(list));
}

TEST(Diagnostic, AListKeepsAThousandThenCountsTheRest) {
    DiagnosticList list;
    for (int i = 0; i < 1000000; ++i) {
        appendDiagnostic(list, Diagnostic::make(Severity::Warning, "w", "f", 1, 1, "blank"));
    }
    ASSERT_EQ(list.size(), kMaxDiagnostics + 1);
    EXPECT_EQ(list.back().message(), "and 999000 more diagnostics");
    EXPECT_EQ(list.back().severity, Severity::Warning);
    EXPECT_FALSE(hasErrors(list));
    // An error among the left-out ones still makes the list one with errors.
    appendDiagnostic(list, Diagnostic::make(Severity::Error, "e", "f", 2, 1, "bad"));
    EXPECT_EQ(list.size(), kMaxDiagnostics + 1);
    EXPECT_EQ(list.back().message(), "and 999001 more diagnostics");
    EXPECT_TRUE(hasErrors(list));
}

TEST(Diagnostic, MergedListsAddTheirCounts) {
    DiagnosticList first;
    DiagnosticList second;
    for (int i = 0; i < 1500; ++i) {
        appendDiagnostic(first, Diagnostic::make(Severity::Warning, "w", "f", 1, 1, "w"));
        appendDiagnostic(second, Diagnostic::make(Severity::Error, "e", "f", 1, 1, "e"));
    }
    appendDiagnostics(first, second);
    ASSERT_EQ(first.size(), kMaxDiagnostics + 1);
    // 500 of the first, all 1500 of the second.
    EXPECT_EQ(first.back().message(), "and 2000 more diagnostics");
    EXPECT_TRUE(hasErrors(first));
    DiagnosticList small;
    appendDiagnostic(small, Diagnostic::make(Severity::Note, "n", "f", 1, 1, "n"));
    appendDiagnostics(small, DiagnosticList{Diagnostic::make(Severity::Note, "m", "f", 2, 1, "m")});
    EXPECT_EQ(small.size(), 2u);
}

}  // namespace
}  // namespace kerf
