#include "core/interp/fagor/expression.h"

#include <cmath>
#include <map>
#include <string>

#include <gtest/gtest.h>

namespace kerf::fagor {
namespace {

class Context final : public ExpressionContext {
public:
    std::map<int, double> p;
    bool readParameter(int number, double& out, Problem& problem) override {
        if (number > 299) {
            problem.code = "parameter";
            return false;
        }
        out = p[number];
        return true;
    }
    bool readVariable(const VariableRef& ref, double& out, Problem&) override {
        lastVariable = ref;
        out = ref.info->id == VarId::Tox ? 12.5 : 7.0;
        return true;
    }
    VariableRef lastVariable;
};

double eval(std::string_view text, Context* context = nullptr) {
    Context local;
    Scanner s(text);
    Expression e(s, context != nullptr ? context : &local);
    ExprValue v;
    EXPECT_TRUE(e.parse(v)) << text << ": " << e.problem().messageTemplate;
    EXPECT_EQ(s.peek(), '\0') << text;
    return v.number;
}

Problem failure(std::string_view text) {
    Context context;
    Scanner s(text);
    Expression e(s, &context);
    ExprValue v;
    EXPECT_FALSE(e.parse(v)) << text;
    return e.problem();
}

// The manual's examples (spec part 2 EX-11.9).
TEST(FagorExpression, OperatorsOfTheManual) {
    EXPECT_DOUBLE_EQ(eval("3 + 4"), 7.0);
    EXPECT_DOUBLE_EQ(eval("5 - 2"), 3.0);
    EXPECT_DOUBLE_EQ(eval("-(2 * 3)"), -6.0);
    EXPECT_DOUBLE_EQ(eval("2 * 3"), 6.0);
    EXPECT_DOUBLE_EQ(eval("9 / 2"), 4.5);
    EXPECT_DOUBLE_EQ(eval("7 MOD 4"), 3.0);
    EXPECT_DOUBLE_EQ(eval("2 EXP 3"), 8.0);
}

TEST(FagorExpression, FunctionsOfTheManual) {
    EXPECT_NEAR(eval("SIN 30"), 0.5, 1e-12);
    EXPECT_NEAR(eval("COS 30"), 0.8660254, 1e-7);
    EXPECT_NEAR(eval("TAN 30"), 0.5773503, 1e-7);
    EXPECT_NEAR(eval("ASIN 1"), 90.0, 1e-12);
    EXPECT_NEAR(eval("ACOS 1"), 0.0, 1e-12);
    EXPECT_NEAR(eval("ATAN 1"), 45.0, 1e-12);
    EXPECT_NEAR(eval("ARG(-1,-2)"), 243.4349488, 1e-7);
    EXPECT_DOUBLE_EQ(eval("ABS -8"), 8.0);
    EXPECT_NEAR(eval("LOG 100"), 2.0, 1e-12);
    EXPECT_DOUBLE_EQ(eval("SQRT 16"), 4.0);
    EXPECT_DOUBLE_EQ(eval("ROUND 5.83"), 6.0);
    EXPECT_DOUBLE_EQ(eval("FIX 5.423"), 5.0);
    EXPECT_DOUBLE_EQ(eval("FUP 7"), 7.0);
    EXPECT_DOUBLE_EQ(eval("FUP 5.423"), 6.0);
    EXPECT_DOUBLE_EQ(eval("BCD 234"), 564.0);  // 0010 0011 0100
    EXPECT_DOUBLE_EQ(eval("BIN $AB"), 171.0);  // not BCD: unchanged
    EXPECT_DOUBLE_EQ(eval("BIN (BCD 156)"), 156.0);
    EXPECT_DOUBLE_EQ(eval("FUP -5.4"), -4.0);  // integer part (-5) plus one
    EXPECT_DOUBLE_EQ(eval("FIX -5.4"), -5.0);
    EXPECT_DOUBLE_EQ(eval("ROUND -2.5"), -3.0);  // half away from zero
    EXPECT_NEAR(eval("PI"), 3.14159265358979, 1e-12);
}

TEST(FagorExpression, Precedence) {
    Context c;
    c.p = {{4, 8}, {5, 2}, {6, 3}, {7, 4}, {8, 9}, {9, 3}};
    EXPECT_DOUBLE_EQ(eval("P4/P5 - P6 * P7 - P8/P9", &c), 8.0 / 2 - 12 - 3);
    EXPECT_DOUBLE_EQ(eval("-2 EXP 2"), 4.0);  // unary minus first
    EXPECT_NEAR(eval("SIN 10+5"), std::sin(10 * M_PI / 180) + 5, 1e-12);
    EXPECT_DOUBLE_EQ(eval("2 + 3 * 4 EXP 2"), 50.0);
    EXPECT_DOUBLE_EQ(eval("1 + 2 EQ 3"), 1.0);                   // arithmetic before relational
    EXPECT_DOUBLE_EQ(eval("1 EQ 1 OR 1 EQ 2 AND 0 EQ 1"), 1.0);  // AND before OR
    EXPECT_DOUBLE_EQ(eval("7 MOD 4 * 2"), 6.0);                  // MOD before *
}

TEST(FagorExpression, LogicalAndBitwise) {
    EXPECT_DOUBLE_EQ(eval("(1 EQ 1) AND (2 EQ 3)"), 0.0);
    EXPECT_DOUBLE_EQ(eval("NOT (2 EQ 3)"), 1.0);
    EXPECT_DOUBLE_EQ(eval("12 AND 10"), 8.0);  // bitwise between numbers
    EXPECT_DOUBLE_EQ(eval("12 OR 3"), 15.0);
    EXPECT_DOUBLE_EQ(eval("12 XOR 10"), 6.0);
    EXPECT_DOUBLE_EQ(eval("NOT 0"), 4294967295.0);  // 32-bit complement
    EXPECT_DOUBLE_EQ(eval("$FFFFFFFE AND 5"), 4.0);
    EXPECT_DOUBLE_EQ(eval("0.1 + 0.2 EQ 0.3"), 1.0);  // decimal values compare as written
}

TEST(FagorExpression, LocalsByLetterAndIndexedParameters) {
    Context c;
    c.p = {{0, 2}, {1, 3}, {2, 4}, {3, 8}, {4, 3}, {7, 150}, {150, 42}};
    EXPECT_DOUBLE_EQ(eval("(A+B)*C/D", &c), 2.5);
    EXPECT_DOUBLE_EQ(eval("P(P7)", &c), 42.0);
    EXPECT_DOUBLE_EQ(eval("P(P4 + 4)", &c), 150.0);
}

TEST(FagorExpression, Variables) {
    Context c;
    EXPECT_DOUBLE_EQ(eval("TOX3", &c), 12.5);
    EXPECT_EQ(c.lastVariable.index, 3);
    eval("ORGX 55", &c);
    EXPECT_EQ(c.lastVariable.info->id, VarId::OrgTable);
    EXPECT_EQ(c.lastVariable.index, 55);
    eval("ORGZ", &c);
    EXPECT_EQ(c.lastVariable.info->id, VarId::Org);
    EXPECT_EQ(c.lastVariable.axis, Axis::Z);
    eval("ORGX (12+3)", &c);
    EXPECT_EQ(c.lastVariable.index, 15);
    eval("MPY 1", &c);
    EXPECT_EQ(c.lastVariable.axis, Axis::Y);
    eval("ASINX", &c);
    EXPECT_EQ(c.lastVariable.info->id, VarId::AsinAxis);
    eval("PLCMM4", &c);
    EXPECT_EQ(c.lastVariable.info->id, VarId::PlcMm);
    eval("GPOSX N99 P100", &c);
    EXPECT_EQ(c.lastVariable.index, 99);
    EXPECT_EQ(c.lastVariable.program, 100);
    eval("FREALZ", &c);
    EXPECT_EQ(c.lastVariable.info->id, VarId::FRealAxis);
    eval("DNCSO", &c);  // chapter 11's name for DNCSSO
    EXPECT_EQ(c.lastVariable.info->id, VarId::DncSso);
}

TEST(FagorExpression, Errors) {
    EXPECT_EQ(failure("1/0").code, "math");
    EXPECT_EQ(failure("SQRT -1").code, "math");
    EXPECT_EQ(failure("LOG 0").code, "math");
    EXPECT_EQ(failure("ASIN 2").code, "math");
    EXPECT_EQ(failure("5 MOD 0").code, "math");
    EXPECT_EQ(failure("SIN P1").messageTemplate,
              "a function argument needs parentheses unless it is a number");
    EXPECT_EQ(failure("1234567").code, "format");
    EXPECT_EQ(failure("$123456789").code, "syntax");
    EXPECT_EQ(failure("FOO + 1").messageTemplate, "unknown word '{1}'");
    EXPECT_EQ(failure("TOX").messageTemplate, "{1} needs a number");
    EXPECT_EQ(failure("P300").code, "parameter");
    EXPECT_EQ(failure("LN 2").messageTemplate, "unknown word '{1}'");  // no LN on this control
    EXPECT_EQ(failure("INT 2").messageTemplate, "unknown word '{1}'");
}

TEST(FagorExpression, OverflowIsAnErrorAtItsOperator) {
    Context c;
    c.p[1] = 1e300;
    c.p[2] = 1.7e308;
    c.p[3] = 1e-300;
    auto problemOf = [&](std::string_view text) {
        Scanner s(text);
        Expression e(s, &c);
        ExprValue v;
        EXPECT_FALSE(e.parse(v)) << text;
        return e.problem();
    };
    EXPECT_EQ(problemOf("P1*P1").code, "overflow");
    EXPECT_EQ(problemOf("P1*P1").offset, 2u);
    EXPECT_EQ(problemOf("P1*10-P1*P1").offset, 8u);  // the second '*'
    EXPECT_EQ(problemOf("P2+P2").offset, 2u);
    EXPECT_EQ(problemOf("-P2-P2").offset, 3u);
    EXPECT_EQ(problemOf("P1/P3").code, "overflow");
    EXPECT_EQ(problemOf("10 EXP 400").code, "math");
    // In range stays a value.
    EXPECT_DOUBLE_EQ(eval("P1*1000", &c), 1e303);
}

TEST(FagorExpression, NestingIsLimitedWithAnErrorNotACrash) {
    const int limit = kMaxExpressionNesting;
    const std::string fits = std::string(limit - 1, '(') + "7" + std::string(limit - 1, ')');
    EXPECT_DOUBLE_EQ(eval(fits), 7);
    EXPECT_EQ(failure(std::string(limit, '(') + "7" + std::string(limit, ')')).code, "nesting");
    // The reproducers: 15000 parentheses, 10000 SIN (, 48000 signs overflowed the stack.
    std::string sines;
    for (int i = 0; i < 10000; ++i)
        sines += "SIN(";
    sines += "1" + std::string(10000, ')');
    for (const std::string& deep : {std::string(15000, '(') + "1" + std::string(15000, ')'), sines,
                                    std::string(48000, '-') + "1"}) {
        const Problem p = failure(deep);
        EXPECT_EQ(p.code, "nesting");
        EXPECT_GE(p.offset, static_cast<size_t>(limit));
        EXPECT_LT(p.offset, static_cast<size_t>(4 * limit + 1));
    }
    // Checking the syntax only is limited the same way.
    const std::string deep = std::string(15000, '(') + "1" + std::string(15000, ')');
    Scanner s(deep);
    Expression checkOnly(s, nullptr);
    ExprValue v;
    EXPECT_FALSE(checkOnly.parse(v));
}

}  // namespace
}  // namespace kerf::fagor
