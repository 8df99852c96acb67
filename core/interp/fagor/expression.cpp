#include "core/interp/fagor/expression.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "core/base/saturating.h"
#include "core/base/translate.h"
#include "core/geometry/arc_math.h"
#include "core/interp/fagor/tables/table_text.h"
#include "core/interp/nesting_level.h"

namespace kerf::fagor {

namespace {

constexpr double kEqualTolerance = 1e-9;

bool nearlyEqual(double a, double b) {
    return std::fabs(a - b) <= kEqualTolerance * std::max({1.0, std::fabs(a), std::fabs(b)});
}

uint32_t bits(double value) {
    return static_cast<uint32_t>(roundedInteger(value));
}

ExprValue number(double v) {
    return ExprValue{v, false};
}
ExprValue truth(bool t) {
    return ExprValue{t ? 1.0 : 0.0, true};
}

bool isFunctionName(std::string_view w) {
    static constexpr std::string_view kNames[] = {"SIN",  "COS", "TAN", "ASIN", "ACOS",
                                                  "ATAN", "ABS", "LOG", "SQRT", "ROUND",
                                                  "FIX",  "FUP", "BCD", "BIN"};
    for (std::string_view n : kNames) {
        if (n == w) return true;
    }
    return false;
}

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

}  // namespace

long long roundedInteger(double value) {
    return saturatingCast<long long>(std::round(value));
}

bool Expression::fail(size_t offset, const char* code, const char* messageTemplate,
                      std::vector<std::string> args) {
    m_problem = Problem{offset, code, messageTemplate, std::move(args)};
    return false;
}

bool Expression::arithmetic(double value, size_t operatorOffset, char op, ExprValue& out) {
    if (!std::isfinite(value)) {
        return fail(operatorOffset, "overflow",
                    KERF_TR_NOOP("overflow: the result of '{1}' is too large"),
                    {std::string(1, op)});
    }
    out = number(value);
    return true;
}

std::string_view Expression::peekWord() {
    m_s.skipBlanks();
    const std::string_view text = m_s.text();
    size_t end = m_s.position();
    while (end < text.size() && isUpper(text[end]))
        ++end;
    return text.substr(m_s.position(), end - m_s.position());
}

bool Expression::parse(ExprValue& out) {
    return orExpr(out);
}

bool Expression::orExpr(ExprValue& out) {
    if (!andExpr(out)) return false;
    while (peekWord() == "OR") {
        m_s.advance(2);
        ExprValue rhs;
        if (!andExpr(rhs)) return false;
        out = out.truth && rhs.truth
                  ? truth(out.number != 0.0 || rhs.number != 0.0)
                  : number(static_cast<double>(bits(out.number) | bits(rhs.number)));
    }
    return true;
}

bool Expression::andExpr(ExprValue& out) {
    if (!relation(out)) return false;
    for (;;) {
        const std::string_view w = peekWord();
        const bool isAnd = w == "AND";
        if (!isAnd && w != "XOR") return true;
        m_s.advance(3);
        ExprValue rhs;
        if (!relation(rhs)) return false;
        if (out.truth && rhs.truth) {
            const bool a = out.number != 0.0;
            const bool b = rhs.number != 0.0;
            out = truth(isAnd ? (a && b) : (a != b));
        } else {
            const uint32_t a = bits(out.number);
            const uint32_t b = bits(rhs.number);
            out = number(static_cast<double>(isAnd ? (a & b) : (a ^ b)));
        }
    }
}

bool Expression::relation(ExprValue& out) {
    if (!additive(out)) return false;
    for (;;) {
        const std::string_view w = peekWord();
        if (w != "EQ" && w != "NE" && w != "GT" && w != "GE" && w != "LT" && w != "LE") return true;
        const std::string op(w);
        m_s.advance(2);
        ExprValue rhs;
        if (!additive(rhs)) return false;
        const double a = out.number;
        const double b = rhs.number;
        const bool equal = nearlyEqual(a, b);
        bool result = false;
        if (op == "EQ") result = equal;
        if (op == "NE") result = !equal;
        if (op == "GT") result = a > b && !equal;
        if (op == "GE") result = a > b || equal;
        if (op == "LT") result = a < b && !equal;
        if (op == "LE") result = a < b || equal;
        out = truth(result);
    }
}

bool Expression::additive(ExprValue& out) {
    if (!multiplicative(out)) return false;
    for (;;) {
        const char c = m_s.peek();
        if (c != '+' && c != '-') return true;
        const size_t at = m_s.position();
        m_s.advance();
        ExprValue rhs;
        if (!multiplicative(rhs)) return false;
        const double sum = c == '+' ? out.number + rhs.number : out.number - rhs.number;
        if (!arithmetic(sum, at, c, out)) return false;
    }
}

bool Expression::multiplicative(ExprValue& out) {
    if (!power(out)) return false;
    for (;;) {
        const char c = m_s.peek();
        if (c != '*' && c != '/') return true;
        const size_t at = m_s.position();
        m_s.advance();
        ExprValue rhs;
        if (!power(rhs)) return false;
        if (c == '*') {
            if (!arithmetic(out.number * rhs.number, at, c, out)) return false;
        } else {
            if (evaluating() && rhs.number == 0.0) {
                return fail(at, "math", KERF_TR_NOOP("division by zero"));
            }
            if (!arithmetic(evaluating() ? out.number / rhs.number : 0.0, at, c, out)) {
                return false;
            }
        }
    }
}

bool Expression::power(ExprValue& out) {
    if (!unary(out)) return false;
    for (;;) {
        const std::string_view w = peekWord();
        if (w != "EXP" && w != "MOD") return true;
        const bool isExp = w == "EXP";
        const size_t at = m_s.position();
        m_s.advance(3);
        ExprValue rhs;
        if (!unary(rhs)) return false;
        if (!evaluating()) {
            out = number(0.0);
            continue;
        }
        if (isExp) {
            const double r = std::pow(out.number, rhs.number);
            if (!std::isfinite(r)) {
                return fail(at, "math", KERF_TR_NOOP("EXP: {1} to the power {2} has no value"),
                            {std::to_string(out.number), std::to_string(rhs.number)});
            }
            out = number(r);
        } else {
            if (rhs.number == 0.0) return fail(at, "math", KERF_TR_NOOP("MOD by zero"));
            out = number(std::fmod(out.number, rhs.number));
        }
    }
}

bool Expression::unary(ExprValue& out) {
    // Every nesting (parentheses, functions, signs, NOT) passes here: a bounded depth bounds the
    // stack.
    const interp::NestingLevel level(m_depth);
    if (m_depth > kMaxExpressionNesting) {
        return fail(m_s.position(), "nesting",
                    KERF_TR_NOOP("an expression may nest at most {1} levels"),
                    {std::to_string(kMaxExpressionNesting)});
    }
    const char c = m_s.peek();
    if (c == '-' || c == '+') {
        m_s.advance();
        if (!unary(out)) return false;
        if (c == '-') out = number(-out.number);
        return true;
    }
    const size_t at = m_s.position();
    const std::string_view w = peekWord();
    if (w == "NOT") {
        m_s.advance(3);
        if (!unary(out)) return false;
        out = out.truth ? truth(out.number == 0.0)
                        : number(static_cast<double>(static_cast<uint32_t>(~bits(out.number))));
        return true;
    }
    if (isFunctionName(w)) {
        // ASINX is a variable, ASIN a function: the whole letter run decides.
        m_s.advance(w.size());
        return function(w, at, out);
    }
    return primary(out);
}

bool Expression::functionArgument(ExprValue& out) {
    const char c = m_s.peek();
    if (c == '(') {
        m_s.advance();
        if (!parse(out)) return false;
        if (!m_s.accept(')')) return fail(m_s.position(), "syntax", KERF_TR_NOOP("')' expected"));
        return true;
    }
    // Without parentheses only a numeric constant: "SIN 30", "ABS -8", "BIN $AB".
    double sign = 1.0;
    if (c == '-' || c == '+') {
        sign = c == '-' ? -1.0 : 1.0;
        m_s.advance();
    }
    const char d = m_s.peek();
    if (d == '$' || isDigit(d) || d == '.') {
        if (!constant(out)) return false;
        out.number *= sign;
        return true;
    }
    return fail(m_s.position(), "syntax",
                KERF_TR_NOOP("a function argument needs parentheses unless it is a number"));
}

bool Expression::function(std::string_view name, size_t offset, ExprValue& out) {
    ExprValue arg;
    if (!functionArgument(arg)) return false;
    const double x = arg.number;
    if (!evaluating()) {
        out = number(0.0);
        return true;
    }
    auto domain = [&](const char* what) {
        return fail(offset, "math", KERF_TR_NOOP("{1}: {2} is outside its domain"),
                    {std::string(what), formatTableNumber(x, 5)});
    };
    double r = 0.0;
    if (name == "SIN") {
        r = std::sin(degToRad(x));
    } else if (name == "COS") {
        r = std::cos(degToRad(x));
    } else if (name == "TAN") {
        if (std::fabs(std::cos(degToRad(x))) < 1e-12) return domain("TAN");
        r = std::tan(degToRad(x));
    } else if (name == "ASIN" || name == "ACOS") {
        if (std::fabs(x) > 1.0 + 1e-12) return domain(name == "ASIN" ? "ASIN" : "ACOS");
        const double clamped = std::max(-1.0, std::min(1.0, x));
        r = radToDeg(name == "ASIN" ? std::asin(clamped) : std::acos(clamped));
    } else if (name == "ATAN") {
        r = radToDeg(std::atan(x));
    } else if (name == "ABS") {
        r = std::fabs(x);
    } else if (name == "LOG") {
        if (x <= 0.0) return domain("LOG");
        r = std::log10(x);
    } else if (name == "SQRT") {
        if (x < 0.0) return domain("SQRT");
        r = std::sqrt(x);
    } else if (name == "ROUND") {
        r = std::round(x);
    } else if (name == "FIX") {
        r = std::trunc(x);
    } else if (name == "FUP") {
        // The manual: an integer stays, otherwise its integer part plus one (FUP -5.4 = -4).
        r = x == std::trunc(x) ? x : std::trunc(x) + 1.0;
    } else if (name == "BCD") {
        long long v = roundedInteger(x);
        if (v < 0 || v > 99999999) return domain("BCD");
        uint32_t packed = 0;
        for (int shift = 0; v > 0; shift += 4, v /= 10) {
            packed |= static_cast<uint32_t>(v % 10) << shift;
        }
        r = static_cast<double>(packed);
    } else {  // BIN: BCD back to binary; a value with a non-decimal nibble stays as it is
        const uint32_t packed = bits(x);
        uint32_t value = 0;
        uint32_t scale = 1;
        bool decimal = true;
        for (uint32_t p = packed; p != 0; p >>= 4, scale *= 10) {
            if ((p & 0xF) > 9) decimal = false;
            value += (p & 0xF) * scale;
        }
        r = static_cast<double>(decimal ? value : packed);
    }
    out = number(r);
    return true;
}

bool Expression::constant(ExprValue& out) {
    const size_t at = m_s.position();
    if (m_s.peek() == '$') {
        m_s.advance();
        uint64_t value = 0;
        int digits = 0;
        while (hexDigit(m_s.peekRaw()) >= 0) {
            value = value * 16 + static_cast<uint64_t>(hexDigit(m_s.peekRaw()));
            m_s.advance();
            ++digits;
        }
        if (digits == 0 || digits > 8) {
            return fail(at, "syntax", KERF_TR_NOOP("a hexadecimal constant has 1 to 8 digits"));
        }
        out = number(static_cast<double>(value));
        return true;
    }
    double v = 0.0;
    if (!parseNumber(v)) return false;
    out = number(v);
    return true;
}

bool Expression::parseNumber(double& out) {
    const size_t at = m_s.position();
    ScannedNumber n;
    if (!m_s.unsignedNumber(n)) return fail(at, "syntax", KERF_TR_NOOP("number expected"));
    if (n.intDigits > 6 || n.decDigits > 5) {
        return fail(at, "format",
                    KERF_TR_NOOP("a constant has at most 6 integer and 5 decimal digits"));
    }
    out = n.value;
    return true;
}

bool Expression::index(int& out) {
    const size_t at = m_s.position();
    if (m_s.peek() == '(') {
        m_s.advance();
        ExprValue v;
        if (!parse(v)) return false;
        if (!m_s.accept(')')) return fail(m_s.position(), "syntax", KERF_TR_NOOP("')' expected"));
        if (evaluating() &&
            (v.number != std::floor(v.number) || v.number < 0.0 || v.number > 1e9)) {
            return fail(at, "syntax", KERF_TR_NOOP("an index must be a whole number, not {1}"),
                        {std::to_string(v.number)});
        }
        out = static_cast<int>(evaluating() ? v.number : 0.0);
        return true;
    }
    int64_t value = 0;
    uint8_t digits = 0;
    if (!m_s.unsignedInteger(value, digits) || digits > 9) {
        return fail(at, "syntax", KERF_TR_NOOP("number or (expression) expected"));
    }
    out = static_cast<int>(value);
    return true;
}

bool Expression::parameterIndex(int& out) {
    return index(out);
}

bool Expression::variableRef(std::string_view name, size_t offset, VariableRef& out) {
    out = VariableRef{};
    auto startsIndex = [&] {
        const char c = m_s.peek();
        return isDigit(c) || c == '(';
    };
    if (const VariableInfo* v = findVariable(name, VarShape::Simple)) {
        out.info = v;
        return true;
    }
    if (const VariableInfo* v = findVariable(name, VarShape::Table); v && startsIndex()) {
        out.info = v;
        return index(out.index);
    }
    const auto axis = name.size() >= 2 ? axisFromLetter(name.back()) : std::nullopt;
    if (axis) {
        const std::string_view root = name.substr(0, name.size() - 1);
        out.axis = *axis;
        if (root == "GPOS") {
            out.info = findVariable(root, VarShape::Gpos);
            if (!m_s.accept('N'))
                return fail(m_s.position(), "syntax", KERF_TR_NOOP("GPOS needs N<block>"));
            if (!index(out.index)) return false;
            if (!m_s.accept('P'))
                return fail(m_s.position(), "syntax", KERF_TR_NOOP("GPOS needs P<program>"));
            return index(out.program);
        }
        if (const VariableInfo* v = findVariable(root, VarShape::AxisTable); v && startsIndex()) {
            out.info = v;
            return index(out.index);
        }
        if (const VariableInfo* v = findVariable(root, VarShape::Axis)) {
            out.info = v;
            return true;
        }
        if (findVariable(root, VarShape::AxisTable) != nullptr) {
            return fail(m_s.position(), "syntax", KERF_TR_NOOP("{1} needs a number"),
                        {std::string(name)});
        }
    }
    if (findVariable(name, VarShape::Table) != nullptr) {
        return fail(m_s.position(), "syntax", KERF_TR_NOOP("{1} needs a number"),
                    {std::string(name)});
    }
    return fail(offset, "syntax", KERF_TR_NOOP("unknown word '{1}'"), {std::string(name)});
}

bool Expression::primary(ExprValue& out) {
    const size_t at = m_s.position();
    const char c = m_s.peek();
    if (c == '(') {
        m_s.advance();
        if (!parse(out)) return false;
        if (!m_s.accept(')')) return fail(m_s.position(), "syntax", KERF_TR_NOOP("')' expected"));
        return true;
    }
    if (c == '$' || isDigit(c) || c == '.') return constant(out);
    if (isLower(c)) {
        return fail(at, "syntax", KERF_TR_NOOP("'{1}': words are written in upper case"),
                    {std::string(1, c)});
    }
    if (!isUpper(c)) {
        if (c == '\0' || c == ')' || c == ',') {
            return fail(at, "syntax", KERF_TR_NOOP("value expected"));
        }
        return fail(at, "syntax", KERF_TR_NOOP("unexpected '{1}'"), {std::string(1, c)});
    }
    const std::string_view name = m_s.letters();
    if (name == "PI") {
        out = number(kPi);
        return true;
    }
    if (name == "ARG") {
        if (!m_s.accept('(')) return fail(m_s.position(), "syntax", KERF_TR_NOOP("'(' expected"));
        ExprValue x, y;
        if (!parse(x)) return false;
        if (!m_s.accept(',')) return fail(m_s.position(), "syntax", KERF_TR_NOOP("',' expected"));
        if (!parse(y)) return false;
        if (!m_s.accept(')')) return fail(m_s.position(), "syntax", KERF_TR_NOOP("')' expected"));
        double a = radToDeg(std::atan2(y.number, x.number));
        if (a < 0.0) a += 360.0;
        out = number(evaluating() ? a : 0.0);
        return true;
    }
    int parameter = -1;
    if (name == "P" && (isDigit(m_s.peekRaw()) || m_s.peek() == '(')) {
        if (!index(parameter)) return false;
    } else if (name.size() == 1) {
        parameter = name[0] - 'A';  // A = P0 ... Z = P25
    }
    if (parameter >= 0) {
        double v = 0.0;
        if (evaluating() && !m_context->readParameter(parameter, v, m_problem)) {
            m_problem.offset = at;
            return false;
        }
        out = number(v);
        return true;
    }
    VariableRef ref;
    if (!variableRef(name, at, ref)) return false;
    double v = 0.0;
    if (evaluating() && !m_context->readVariable(ref, v, m_problem)) {
        m_problem.offset = at;
        return false;
    }
    out = number(v);
    return true;
}

}  // namespace kerf::fagor
