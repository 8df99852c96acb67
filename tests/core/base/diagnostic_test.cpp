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

}  // namespace
}  // namespace kerf
