#include "core/interp/klartext/fprint_formatter.h"

#include <map>

#include <gtest/gtest.h>

namespace kerf::klartext {
namespace {

class Env : public FormulaEnvironment {
public:
    double number(QRef ref) override { return ref.index == 1 ? 12.3456 : -2.0; }
    const std::string& string(uint16_t) override { return text; }
    bool stringDefined(uint16_t) override { return true; }
    std::optional<std::string> systemString(int, int) override { return std::nullopt; }
    std::string text = "PART-7";
};

TEST(FPrint, FormatsValuesDatesAndLanguages) {
    Env env;
    std::tm now{};
    now.tm_year = 2026 - 1900;
    now.tm_mon = 10;
    now.tm_mday = 22;
    const char* mask =
        "\"MEASURING LOG %S\", QS1;\n"
        "\"X1 = %9.3LF\", Q1;\n"
        "\"N = %D\", Q2;\n"
        "\"DATE %02D.%02D.%4D\", DAY, MONTH, YEAR4;\n"
        "L_GERMAN;\n"
        "\"nur deutsch\";\n"
        "L_ALL;\n"
        "M_APPEND;\n";
    auto out = formatFPrint(mask, "m.a", env, now);
    ASSERT_TRUE(out.ok()) << out.error().message();
    EXPECT_EQ(out->text, "MEASURING LOG PART-7\nX1 =    12.346\nN = -2\nDATE 22.11.2026\n");
    EXPECT_TRUE(out->append);
}

TEST(FPrint, ReportsBadMasks) {
    Env env;
    std::tm now{};
    EXPECT_FALSE(formatFPrint("\"%F %F\", Q1;\n", "m.a", env, now).ok());
    EXPECT_FALSE(formatFPrint("\"unterminated\n", "m.a", env, now).ok());
    auto unknown = formatFPrint("\n\"%F\", BOGUS;\n", "m.a", env, now);
    ASSERT_FALSE(unknown.ok());
    EXPECT_EQ(unknown.error().line, 2u);
}

}  // namespace
}  // namespace kerf::klartext
