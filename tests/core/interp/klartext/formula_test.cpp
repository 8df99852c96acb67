#include "core/interp/klartext/formula.h"

#include <cmath>
#include <limits>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "core/interp/klartext/formula_cache.h"

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

// The problem of a formula that must fail, with the column (1-based) it points at.
struct Failure {
    std::string code;
    size_t column = 0;
};
Failure failure(const std::string& text, FakeEnvironment* env = nullptr, bool strings = false) {
    FakeEnvironment local;
    Cursor c(text);
    FormulaParser p(c, env ? env : &local);
    const bool ok = strings ? p.stringExpression().has_value() : p.expression().has_value();
    EXPECT_FALSE(ok) << text;
    if (!p.problem()) return {};
    return {p.problem()->code, p.problem()->offset + 1};
}

TEST(Formula, OverflowIsAnErrorAtItsOperator) {
    FakeEnvironment env;
    env.values[1] = 1e300;
    // Each operator that leaves the doubles; the column is the operator's.
    EXPECT_EQ(failure("Q1 * Q1", &env).code, "overflow");
    EXPECT_EQ(failure("Q1 * Q1", &env).column, 4u);
    EXPECT_EQ(failure("Q1 * 10 - Q1 * Q1", &env).column, 14u);  // the second '*'
    env.values[5] = 1e-300;
    EXPECT_EQ(failure("Q1 / Q5", &env).code, "overflow");
    env.values[2] = 1.7e308;
    EXPECT_EQ(failure("Q2 + Q2", &env).column, 4u);
    EXPECT_EQ(failure("-Q2 - Q2", &env).column, 5u);
    EXPECT_EQ(failure("10 ^ 400").code, "math");  // the power reports its own domain error
    EXPECT_EQ(failure("EXP 1000").code, "math");
    // In range stays a value: the largest product that fits.
    EXPECT_DOUBLE_EQ(eval("Q1 * 1000", &env), 1e303);
}

TEST(Formula, AParameterWithoutAFiniteNumberCannotBeRead) {
    FakeEnvironment env;
    env.values[3] = std::numeric_limits<double>::infinity();
    env.values[4] = std::nan("");
    EXPECT_EQ(failure("Q3 + 1", &env).code, "overflow");
    EXPECT_EQ(failure("2 * Q4", &env).code, "overflow");
    Cursor c("+Q4");
    FormulaParser p(c, &env);
    EXPECT_FALSE(p.signedOperand());
    Cursor w("-Q3");
    FormulaParser q(w, &env);
    EXPECT_FALSE(q.wordValue());
}

TEST(Formula, ALiteralBeyondTheDoublesIsNoNumber) {
    const std::string huge = "1" + std::string(400, '0');
    EXPECT_FALSE(failure(huge).code.empty());
    FakeEnvironment env;
    env.strings[1] = "nan";
    env.strings[2] = "1e999";
    EXPECT_EQ(failure("TONUMB ( SRC_QS1 )", &env).code, "math");
    EXPECT_EQ(failure("TONUMB ( SRC_QS2 )", &env).code, "math");
}

TEST(Formula, NestingIsLimitedWithAnErrorNotACrash) {
    const int limit = kMaxFormulaNesting;
    // At the limit: parentheses, functions and signs each count one level, the number one more.
    const std::string fits = std::string(limit - 1, '(') + "7" + std::string(limit - 1, ')');
    EXPECT_DOUBLE_EQ(eval(fits), 7);
    EXPECT_DOUBLE_EQ(eval(std::string(limit - 2, '-') + "7"), 7);  // an even number of signs
    EXPECT_EQ(failure(std::string(limit, '(') + "7" + std::string(limit, ')')).code, "nesting");
    // The reproducers: 20000 parentheses, 10000 SIN (, 48000 signs overflowed the stack.
    for (const std::string& deep : {std::string(20000, '(') + "1" + std::string(20000, ')'),
                                    [] {
                                        std::string s;
                                        for (int i = 0; i < 10000; ++i)
                                            s += "SIN (";
                                        return s + "1" + std::string(10000, ')');
                                    }(),
                                    std::string(48000, '-') + "1"}) {
        const Failure f = failure(deep);
        EXPECT_EQ(f.code, "nesting");
        // The level beyond the limit: where the 257th opening starts.
        EXPECT_GT(f.column, static_cast<size_t>(limit - 1));
        EXPECT_LT(f.column, static_cast<size_t>(5 * limit + 2));
    }
    // A checked syntax (no environment) is limited the same way.
    Cursor c(std::string(20000, '(') + "1" + std::string(20000, ')'));
    FormulaParser checkOnly(c, nullptr);
    EXPECT_FALSE(checkOnly.expression());
}

TEST(Formula, AStringHoldsAtMost255Characters) {
    FakeEnvironment env;
    env.strings[1] = std::string(200, 'A');
    // The concatenation that passes 255 fails at its '||' (column 5).
    const Failure f = failure("QS1 || QS1", &env, true);
    EXPECT_EQ(f.code, "string-length");
    EXPECT_EQ(f.column, 5u);
    env.strings[2] = std::string(55, 'B');
    Cursor c("QS1 || QS2");
    FormulaParser p(c, &env);
    auto s = p.stringExpression();
    ASSERT_TRUE(s);
    EXPECT_EQ(s->size(), 255u);
    // TOCHAR of a huge number: its 305 characters are too long, not a crash.
    env.values[1] = 1e300;
    EXPECT_EQ(failure("TOCHAR ( DAT+Q1 DECIMALS3 )", &env, true).code, "string-length");
    EXPECT_EQ(failure(std::string("\"") + std::string(256, 'x') + "\"", nullptr, true).code,
              "string-length");
}

// A formula evaluated again through the cache, with `values` as the parameters now.
struct CachedRun {
    std::optional<double> value;
    size_t end = 0;  // where the cursor stops
    std::optional<ParseProblem> problem;
};
CachedRun runCached(const std::string& text, FormulaCache& cache, FakeEnvironment& env) {
    Cursor c(text);
    FormulaParser p(c, &env, &cache);
    CachedRun run{p.expression(), c.position(), p.problem()};
    return run;
}

TEST(FormulaCache, ARepeatedFormulaGivesTheParsersBitsWithNewParameterValues) {
    const std::string text =
        "( 1 + Q14 ) / 2 * Q13 * Q12 - SIN ( Q13 * 8.185 ) ^ 2 % 0.7 + -PI ; x";
    FakeEnvironment env;
    FormulaCache cache;
    for (int i = 1; i <= 5; ++i) {
        env.values[12] = 0.2;
        env.values[13] = i;
        env.values[14] = i % 2 == 0 ? 1.0 : -1.0;
        CachedRun cached = runCached(text, cache, env);
        ASSERT_TRUE(cached.value) << i;
        // Worked out by hand in the parser's order of operations.
        const double sine = std::sin(i * 8.185 * (3.14159265358979323846 / 180.0));
        const double expected = (1 + env.values[14]) / 2 * i * 0.2 -
                                std::fmod(std::pow(sine, 2), 0.7) + -3.14159265358979323846;
        EXPECT_EQ(*cached.value, expected) << i;     // the same bits, not just close
        EXPECT_EQ(cached.end, text.find(';')) << i;  // stops at the comment
    }
}

TEST(FormulaCache, AnErrorInACachedFormulaIsReportedWhereTheParserFindsIt) {
    FakeEnvironment env;
    FormulaCache cache;
    env.values[1] = 4;
    env.values[2] = 2;
    ASSERT_TRUE(runCached("Q1 / ( Q2 - 2 ) + 1", cache, env).value == std::nullopt);
    env.values[2] = 1;
    EXPECT_EQ(runCached("Q1 / ( Q2 - 2 ) + 1", cache, env).value, -3.0);
    env.values[2] = 2;  // recorded now: the division by zero comes from the evaluation
    CachedRun run = runCached("Q1 / ( Q2 - 2 ) + 1", cache, env);
    EXPECT_FALSE(run.value);
    ASSERT_TRUE(run.problem);
    EXPECT_EQ(run.problem->code, "math");
    EXPECT_EQ(run.problem->offset, 3u);  // at the '/'
    env.values[2] = std::numeric_limits<double>::infinity();
    run = runCached("Q1 / ( Q2 - 2 ) + 1", cache, env);
    ASSERT_TRUE(run.problem);
    EXPECT_EQ(run.problem->code, "overflow");
}

TEST(FormulaCache, FormulasSharingAnEntryAreToldApartByTheirText) {
    FakeEnvironment env;
    FormulaCache cache;
    // More formulas than entries: each is evaluated from its own text however they collide.
    for (int round = 0; round < 2; ++round) {
        for (int i = 0; i < 1000; ++i) {
            const std::string text = std::to_string(i) + " * 2 + 1";
            EXPECT_EQ(runCached(text, cache, env).value, i * 2.0 + 1.0) << text;
        }
    }
}

}  // namespace
}  // namespace kerf::klartext
