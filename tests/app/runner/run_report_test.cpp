#include "app/runner/run_report.h"

#include <gtest/gtest.h>

namespace kerf::app {
namespace {

// The report used to abort (nlohmann type_error 316) on a byte that is not UTF-8 in a message or
// a file name; JSON must be UTF-8, so each invalid sequence becomes U+FFFD.
TEST(RunReport, BytesThatAreNotUtf8BecomeReplacementCharacters) {
    DiagnosticList diagnostics{Diagnostic::make(Severity::Error, "syntax", "bad\xffname.H", 1, 4,
                                                "unexpected '{1}'", std::string("\xc3"))};
    nlohmann::json report;
    report["diagnostics"] = diagnosticsJson(diagnostics);
    const std::string text = reportText(report);
    const nlohmann::json back = nlohmann::json::parse(text);
    EXPECT_EQ(back["diagnostics"][0]["file"], "bad\xef\xbf\xbdname.H");
    EXPECT_EQ(back["diagnostics"][0]["message"], "unexpected '\xef\xbf\xbd'");
    // Valid UTF-8 passes unchanged.
    report["text"] =
        "Z\xc3\xbc"
        "rich";
    EXPECT_EQ(nlohmann::json::parse(reportText(report))["text"],
              "Z\xc3\xbc"
              "rich");
}

}  // namespace
}  // namespace kerf::app
