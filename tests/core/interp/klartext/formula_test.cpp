#include "core/interp/klartext/formula.h"

#include <cmath>
#include <map>

#include <gtest/gtest.h>

namespace kerf::klartext {
namespace {

class FakeEnvironment : public FormulaEnvironment {
public:
    double number(QRef ref) override { return values[ref.index]; }
    const std::string& string(uint16_t index) override { return strings[index]; }
    bool stringDefined(uint16_t index) override { return strings.count(index) > 0; }
    std::optional<std::string> systemString(int, int) override { return std::nullopt; }
    std::map<int, double> values;
    std::map<uint16_t, std::string> strings;
};

double eval(const std::string& text, FakeEnvironment* env = nullptr) {
    FakeEnvironment local;
    Cursor c(text);
    FormulaParser p(c, env ? env : &local);
    auto v = p.expression();
    EXPECT_TRUE(v.has_value()) << text << ": " << (p.problem() ? p.problem()->messageTemplate : "");
    EXPECT_TRUE(c.atEnd()) << text;
    return v.value_or(NAN);
}

TEST(Formula, PrecedenceAsTheTncManualDescribes) {
    EXPECT_DOUBLE_EQ(eval("5 * 3 + 2 * 10"), 35);
    EXPECT_DOUBLE_EQ(eval("SQ 10 ^ 3"), 1e6);  // function first, then power
    EXPECT_NEAR(eval("SIN 30 ^ 2"), 0.25, 1e-15);
    EXPECT_DOUBLE_EQ(eval("2 ^ 3 ^ 2"), 64);  // same priority: left to right
    EXPECT_DOUBLE_EQ(eval("10 - 4 - 3"), 3);
    EXPECT_DOUBLE_EQ(eval("( 1 + 2 ) * 3"), 9);
    EXPECT_DOUBLE_EQ(eval("-2 ^ 2"), 4);  // a sign binds like a function
    EXPECT_DOUBLE_EQ(eval("7 % 3"), 1);
}

TEST(Formula, EveryFunction) {
    EXPECT_NEAR(eval("COS 60"), 0.5, 1e-15);
    EXPECT_NEAR(eval("TAN 45"), 1, 1e-15);
    EXPECT_NEAR(eval("ASIN 0.5"), 30, 1e-12);
    EXPECT_NEAR(eval("ACOS 0.5"), 60, 1e-12);
    EXPECT_NEAR(eval("ATAN 1"), 45, 1e-12);
    EXPECT_DOUBLE_EQ(eval("SQRT 16"), 4);
    EXPECT_NEAR(eval("LN EXP 3"), 3, 1e-15);
    EXPECT_NEAR(eval("LOG 1000"), 3, 1e-15);
    EXPECT_DOUBLE_EQ(eval("NEG 4"), -4);
    EXPECT_DOUBLE_EQ(eval("INT -3.7"), -3);
    EXPECT_DOUBLE_EQ(eval("FRAC 3.75"), 0.75);
    EXPECT_DOUBLE_EQ(eval("ABS -2"), 2);
    EXPECT_DOUBLE_EQ(eval("SGN -0.1 + SGN 0 + SGN 5"), 0);
    EXPECT_NEAR(eval("PI"), 3.14159265358979323846, 1e-15);
}

TEST(Formula, ParametersAndDecimalCommas) {
    FakeEnvironment env;
    env.values[5] = 2.5;
    EXPECT_DOUBLE_EQ(eval("Q5 * 2", &env), 5);
    EXPECT_DOUBLE_EQ(eval("QL5 + QR5", &env), 5);
    EXPECT_DOUBLE_EQ(eval("0,5 + 1,25"), 1.75);
}

TEST(Formula, StringFunctions) {
    FakeEnvironment env;
    env.strings[1] = "ABCDEF";
    env.strings[2] = "CD";
    EXPECT_DOUBLE_EQ(eval("STRLEN ( SRC_QS1 )", &env), 6);
    EXPECT_DOUBLE_EQ(eval("STRLEN ( SRC_QS9 )", &env), -1);  // undefined string
    EXPECT_DOUBLE_EQ(eval("INSTR ( SRC_QS1 SEA_QS2 BEG0 )", &env), 2);
    EXPECT_DOUBLE_EQ(eval("INSTR ( SRC_QS1 SEA_QS2 BEG3 )", &env), 6);  // not found: length
    EXPECT_DOUBLE_EQ(eval("STRCOMP ( SRC_QS2 SEA_QS1 )", &env), 1);
    Cursor c("QS1 || \"-\" || SUBSTR ( SRC_QS1 BEG1 LEN2 ) || TOCHAR ( DAT+1.5 DECIMALS2 )");
    FormulaParser p(c, &env);
    auto s = p.stringExpression();
    ASSERT_TRUE(s);
    EXPECT_EQ(*s, "ABCDEF-BC1.50");
}

TEST(Formula, Errors) {
    FakeEnvironment env;
    for (const char* bad :
         {"1 / 0", "SQRT -1", "ACOS 2", "LN 0", "(1 + 2", "1 +", "Q2000", "QS1 + 1", "FOO 2"}) {
        Cursor c(bad);
        FormulaParser p(c, &env);
        auto v = p.expression();
        EXPECT_FALSE(v && c.atEnd()) << bad;
    }
    // Checking only the syntax never reports value errors.
    Cursor c("1 / Q3");
    FormulaParser checkOnly(c, nullptr);
    EXPECT_TRUE(checkOnly.expression());
}

}  // namespace
}  // namespace kerf::klartext
