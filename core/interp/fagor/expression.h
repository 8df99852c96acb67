#pragma once

#include <string_view>

#include "core/interp/fagor/problem.h"
#include "core/interp/fagor/scanner.h"
#include "core/interp/fagor/variables.h"

namespace kerf::fagor {

// A value of the high-level language: a number, and whether it is a truth value (the result of a
// relational or logical operation). AND, OR, XOR and NOT act logically on two truth values and
// bitwise (32 bits) otherwise.
struct ExprValue {
    double number = 0.0;
    bool truth = false;
};

// Deepest nesting of parentheses, functions and signs in one expression (the parser recurses).
inline constexpr int kMaxExpressionNesting = 256;

// What expressions read.
class ExpressionContext {
public:
    virtual ~ExpressionContext() = default;
    // P<number> (locals 0-25, globals 100-299, 1000-1255, 2000-2255).
    virtual bool readParameter(int number, double& out, Problem& problem) = 0;
    virtual bool readVariable(const VariableRef& ref, double& out, Problem& problem) = 0;
};

// Parses and evaluates one expression of the high-level language (spec part 2 §4.3-4.6) in one
// pass. Precedence, highest first: NOT, functions and unary minus (right to left); EXP and MOD;
// * and /; + and -; EQ NE GT GE LT LE; AND and XOR; OR. Angles are degrees. Without a context the
// syntax is checked and every operand reads as 0.
class Expression {
public:
    Expression(Scanner& scanner, ExpressionContext* context) : m_s(scanner), m_context(context) {}

    bool parse(ExprValue& out);
    bool parseNumber(double& out);
    // The parameter number after 'P' ("P12", "P(P7)"); the scanner is after the P.
    bool parameterIndex(int& out);
    // Completes a variable name whose letters were just read (`name` starting at `offset`).
    bool variableRef(std::string_view name, size_t offset, VariableRef& out);

    const Problem& problem() const { return m_problem; }
    bool fail(size_t offset, const char* code, const char* messageTemplate,
              std::vector<std::string> args = {});

private:
    bool orExpr(ExprValue& out);
    bool andExpr(ExprValue& out);
    bool relation(ExprValue& out);
    bool additive(ExprValue& out);
    bool multiplicative(ExprValue& out);
    bool power(ExprValue& out);
    bool unary(ExprValue& out);
    bool primary(ExprValue& out);
    // Stores an arithmetic result; one that is not finite is an overflow at its operator.
    bool arithmetic(double value, size_t operatorOffset, char op, ExprValue& out);
    bool function(std::string_view name, size_t offset, ExprValue& out);
    bool functionArgument(ExprValue& out);
    bool constant(ExprValue& out);
    bool index(int& out);
    // The operator word at the cursor (without consuming it), or empty.
    std::string_view peekWord();
    bool evaluating() const { return m_context != nullptr; }

    Scanner& m_s;
    ExpressionContext* m_context;
    Problem m_problem;
    int m_depth = 0;
};

// Integer of a value for bitwise operations and indexes: rounds to the nearest integer, saturating.
long long roundedInteger(double value);

}  // namespace kerf::fagor
