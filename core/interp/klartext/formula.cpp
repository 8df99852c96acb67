#include "core/interp/klartext/formula.h"

#include <charconv>
#include <cmath>

#include "core/base/saturating.h"
#include "core/base/translate.h"
#include "core/geometry/arc_math.h"
#include "core/interp/nesting_level.h"

namespace kerf::klartext {

namespace {

const std::string kEmpty;

using UnaryFunction = double (*)(double);

struct FunctionEntry {
    std::string_view name;
    UnaryFunction apply;
};

double sq(double x) {
    return x * x;
}
double sinDeg(double x) {
    return std::sin(degToRad(x));
}
double cosDeg(double x) {
    return std::cos(degToRad(x));
}
double tanDeg(double x) {
    return std::tan(degToRad(x));
}
double asinDeg(double x) {
    return radToDeg(std::asin(x));
}
double acosDeg(double x) {
    return radToDeg(std::acos(x));
}
double atanDeg(double x) {
    return radToDeg(std::atan(x));
}
double neg(double x) {
    return -x;
}
double integer(double x) {
    return std::trunc(x);
}
double fraction(double x) {
    return x - std::trunc(x);
}
double sgn(double x) {
    return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0);
}
double absolute(double x) {
    return std::fabs(x);
}
double squareRoot(double x) {
    return std::sqrt(x);
}
double naturalLog(double x) {
    return std::log(x);
}
double log10Of(double x) {
    return std::log10(x);
}
double expOf(double x) {
    return std::exp(x);
}

// Longer names first so that "SQRT" is not read as "SQ" followed by "RT".
constexpr FunctionEntry kFunctions[] = {
    {"SQRT", squareRoot}, {"SQ", sq},        {"SIN", sinDeg},    {"COS", cosDeg},
    {"TAN", tanDeg},      {"ASIN", asinDeg}, {"ACOS", acosDeg},  {"ATAN", atanDeg},
    {"LN", naturalLog},   {"LOG", log10Of},  {"EXP", expOf},     {"NEG", neg},
    {"INT", integer},     {"ABS", absolute}, {"FRAC", fraction}, {"SGN", sgn},
};

}  // namespace

std::optional<double> FormulaParser::fail(std::string code, std::string messageTemplate,
                                          std::vector<std::string> args) {
    if (!m_problem) {
        m_problem = ParseProblem{m_cursor.position(), std::move(code), std::move(messageTemplate),
                                 std::move(args)};
    }
    return std::nullopt;
}

std::optional<double> FormulaParser::domainCheck(double value, const char* what, size_t at) {
    if (std::isfinite(value) || checkOnly()) return checkOnly() ? 0.0 : value;
    m_cursor.setPosition(at);
    return fail("math", KERF_TR_NOOP("{1} is not defined for this value"), {what});
}

std::optional<double> FormulaParser::overflowCheck(double value, size_t operatorOffset, char op) {
    if (std::isfinite(value)) return value;
    m_cursor.setPosition(operatorOffset);
    return fail("overflow", KERF_TR_NOOP("overflow: the result of '{1}' is too large"),
                {std::string(1, op)});
}

std::optional<double> FormulaParser::read(QRef ref) {
    if (m_env == nullptr) return 0.0;
    const double value = m_env->number(ref);
    // Formulas keep parameters finite; a value read from a table or the machine may not be.
    if (std::isfinite(value)) return value;
    return fail("overflow", KERF_TR_NOOP("{1}{2} holds no finite number"),
                {qPrefix(ref.kind), std::to_string(ref.index)});
}

std::optional<QRef> FormulaParser::parameter(bool strings) {
    size_t saved = m_cursor.position();
    if (!m_cursor.acceptPrefix("Q")) return std::nullopt;
    QRef ref;
    char c = upper(m_cursor.peekRaw());
    if (c == 'L' || c == 'R' || c == 'S') {
        m_cursor.setPosition(m_cursor.position() + 1);
        ref.kind = c == 'L' ? QKind::QL : (c == 'R' ? QKind::QR : QKind::QS);
    }
    if (!isDigit(m_cursor.peekRaw())) {
        m_cursor.setPosition(saved);
        return std::nullopt;
    }
    auto index = m_cursor.unsignedInteger();
    if (!index) {
        m_cursor.setPosition(saved);
        return std::nullopt;
    }
    if (ref.kind == QKind::QS && !strings) {
        m_cursor.setPosition(saved);
        fail("syntax", KERF_TR_NOOP("a string parameter cannot be used as a number"));
        return std::nullopt;
    }
    if (*index >= qLimit(ref.kind)) {
        m_cursor.setPosition(saved);
        fail("range", KERF_TR_NOOP("{1}{2} does not exist (0 to {3})"),
             {qPrefix(ref.kind), std::to_string(*index), std::to_string(qLimit(ref.kind) - 1)});
        return std::nullopt;
    }
    ref.index = static_cast<uint16_t>(*index);
    return ref;
}

std::optional<double> FormulaParser::signedOperand() {
    char c = m_cursor.peek();
    double sign = 1.0;
    if (c == '+' || c == '-') {
        sign = c == '-' ? -1.0 : 1.0;
        m_cursor.setPosition(m_cursor.position() + 1);
    }
    if (auto ref = parameter(false)) {
        auto value = read(*ref);
        return value ? std::optional<double>(sign * *value) : std::nullopt;
    }
    if (m_problem) return std::nullopt;
    if (auto number = m_cursor.unsignedNumber()) return sign * *number;
    return fail("syntax", KERF_TR_NOOP("number or Q parameter expected"));
}

std::optional<double> FormulaParser::wordValue() {
    char c = m_cursor.peek();
    double sign = 1.0;
    if (c == '+' || c == '-') {
        sign = c == '-' ? -1.0 : 1.0;
        m_cursor.setPosition(m_cursor.position() + 1);
        c = m_cursor.peek();
    }
    if (c == '(') {
        m_cursor.setPosition(m_cursor.position() + 1);
        auto value = additive();
        if (!value) return std::nullopt;
        if (!m_cursor.acceptChar(')')) return fail("syntax", KERF_TR_NOOP("')' expected"));
        return sign * *value;
    }
    if (isDigit(c) || c == '.') {
        if (auto number = m_cursor.unsignedNumber()) return sign * *number;
    }
    if (auto ref = parameter(false)) {
        auto value = read(*ref);
        return value ? std::optional<double>(sign * *value) : std::nullopt;
    }
    if (m_problem) return std::nullopt;
    return fail("syntax", KERF_TR_NOOP("number or Q parameter expected"));
}

std::optional<double> FormulaParser::expression() {
    if (m_cache == nullptr || m_env == nullptr) return additive();
    m_cursor.skipBlanks();
    const std::string_view text = m_cursor.rest();
    FormulaCache::Entry& entry = m_cache->entryFor(text);
    if (entry.text.empty() || entry.text != text) return recordExpression(entry, text);
    if (auto value = entry.formula.evaluate(*m_env)) {
        m_cursor.setPosition(m_cursor.position() + entry.length);
        return value;
    }
    return additive();  // the parser reports the error where it is
}

std::optional<double> FormulaParser::recordExpression(FormulaCache::Entry& entry,
                                                      std::string_view text) {
    const size_t start = m_cursor.position();
    entry.formula.clear();
    m_recording = &entry.formula;
    m_recordable = true;
    auto value = additive();
    m_recording = nullptr;
    if (value && m_recordable && entry.formula.complete()) {
        entry.text.assign(text);
        entry.length = m_cursor.position() - start;
    } else {
        entry.text.clear();
    }
    return value;
}

std::optional<double> FormulaParser::additive() {
    auto left = multiplicative();
    if (!left) return std::nullopt;
    for (;;) {
        char c = m_cursor.peek();
        if (c != '+' && c != '-') return left;
        const size_t at = m_cursor.position();
        m_cursor.setPosition(at + 1);
        auto right = multiplicative();
        if (!right) return std::nullopt;
        record(c == '+' ? CompiledFormula::Operation::Add : CompiledFormula::Operation::Subtract);
        left = overflowCheck(c == '+' ? *left + *right : *left - *right, at, c);
        if (!left) return std::nullopt;
    }
}

std::optional<double> FormulaParser::multiplicative() {
    auto left = power();
    if (!left) return std::nullopt;
    for (;;) {
        char c = m_cursor.peek();
        if (c != '*' && c != '/' && c != '%') return left;
        size_t at = m_cursor.position();
        m_cursor.setPosition(at + 1);
        auto right = power();
        if (!right) return std::nullopt;
        record(c == '*'   ? CompiledFormula::Operation::Multiply
               : c == '/' ? CompiledFormula::Operation::Divide
                          : CompiledFormula::Operation::Modulo);
        if (c == '*') {
            left = overflowCheck(*left * *right, at, c);
            if (!left) return std::nullopt;
            continue;
        }
        if (*right == 0.0) {
            if (checkOnly()) {
                *left = 0.0;
                continue;
            }
            m_cursor.setPosition(at);
            return fail("math", KERF_TR_NOOP("division by zero"));
        }
        left = overflowCheck(c == '/' ? *left / *right : std::fmod(*left, *right), at, c);
        if (!left) return std::nullopt;
    }
}

std::optional<double> FormulaParser::power() {
    auto left = unary();
    if (!left) return std::nullopt;
    while (m_cursor.peek() == '^') {
        const size_t operatorAt = m_cursor.position();
        m_cursor.setPosition(operatorAt + 1);
        auto right = unary();
        if (!right) return std::nullopt;
        record(CompiledFormula::Operation::Power);
        auto value = domainCheck(std::pow(*left, *right), "^", operatorAt);
        if (!value) return std::nullopt;
        left = value;
    }
    return left;
}

std::optional<double> FormulaParser::unary() {
    // Every nesting (parentheses, functions, signs) passes here: a bounded depth bounds the stack.
    const interp::NestingLevel level(m_depth);
    if (m_depth > kMaxFormulaNesting) {
        return fail("nesting", KERF_TR_NOOP("a formula may nest at most {1} levels"),
                    {std::to_string(kMaxFormulaNesting)});
    }
    char c = m_cursor.peek();
    if (c == '+' || c == '-') {
        m_cursor.setPosition(m_cursor.position() + 1);
        auto value = unary();
        if (!value) return std::nullopt;
        if (c == '+') return *value;
        record(CompiledFormula::Operation::Negate);
        return -*value;
    }
    if (isLetter(c) && upper(c) != 'Q') {
        // One look at the word decides between a function, PI and a string function.
        const size_t at = m_cursor.position();
        const std::string_view text = m_cursor.text();
        size_t end = at;
        while (end < text.size() && isLetter(text[end]))
            ++end;
        char word[8];
        const size_t length = end - at;
        if (length < sizeof word) {
            for (size_t i = 0; i < length; ++i)
                word[i] = upper(text[at + i]);
            const std::string_view name(word, length);
            for (const FunctionEntry& f : kFunctions) {
                if (f.name != name) continue;
                m_cursor.setPosition(end);
                auto argument = unary();
                if (!argument) return std::nullopt;
                if (m_recording) m_recording->pushFunction(f.apply);
                return domainCheck(f.apply(*argument), f.name.data(), at);
            }
            if (name == "PI") {
                m_cursor.setPosition(end);
                if (m_recording) m_recording->pushNumber(kPi);
                return kPi;
            }
            for (std::string_view function : {"STRLEN", "STRCOMP", "INSTR", "TONUMB"}) {
                if (name == function) {
                    m_cursor.setPosition(end);
                    m_recordable = false;  // reads strings
                    return stringFunction(function);
                }
            }
        }
    }
    return primary();
}

std::optional<double> FormulaParser::primary() {
    char c = m_cursor.peek();
    if (c == '(') {
        m_cursor.setPosition(m_cursor.position() + 1);
        auto value = additive();
        if (!value) return std::nullopt;
        if (!m_cursor.acceptChar(')')) return fail("syntax", KERF_TR_NOOP("')' expected"));
        return value;
    }
    if (isDigit(c) || c == '.') {
        if (auto number = m_cursor.unsignedNumber()) {
            if (m_recording) m_recording->pushNumber(*number);
            return number;
        }
    }
    if (auto ref = parameter(false)) {
        if (m_recording) m_recording->pushRead(*ref);
        return read(*ref);
    }
    if (m_problem) return std::nullopt;
    if (m_cursor.atEnd()) return fail("syntax", KERF_TR_NOOP("incomplete formula"));
    return fail("syntax", KERF_TR_NOOP("unexpected '{1}' in formula"),
                {std::string(1, m_cursor.peek())});
}

std::optional<std::string> FormulaParser::stringSource(std::string_view prefix) {
    // SRC_QS1, SEA_QS3 or a quoted literal after the prefix.
    if (!prefix.empty() && !m_cursor.acceptPrefix(prefix)) {
        fail("syntax", KERF_TR_NOOP("'{1}' expected"), {std::string(prefix)});
        return std::nullopt;
    }
    if (auto literal = m_cursor.quoted()) return std::string(*literal);
    auto ref = parameter(true);
    if (!ref || ref->kind != QKind::QS) {
        fail("syntax", KERF_TR_NOOP("string parameter QS expected"));
        return std::nullopt;
    }
    return m_env ? m_env->string(ref->index) : kEmpty;
}

std::optional<double> FormulaParser::tagValue(std::string_view tag) {
    if (!m_cursor.acceptPrefix(tag)) {
        return fail("syntax", KERF_TR_NOOP("'{1}' expected"), {std::string(tag)});
    }
    return wordValue();
}

std::optional<double> FormulaParser::stringFunction(std::string_view name) {
    if (!m_cursor.acceptChar('(')) return fail("syntax", KERF_TR_NOOP("'(' expected"));
    double result = 0.0;
    if (name == "STRLEN") {
        m_cursor.acceptPrefix("SRC_");
        auto ref = parameter(true);
        if (!ref || ref->kind != QKind::QS) {
            return fail("syntax", KERF_TR_NOOP("string parameter QS expected"));
        }
        if (m_env) {
            result = m_env->stringDefined(ref->index)
                         ? static_cast<double>(m_env->string(ref->index).size())
                         : -1.0;
        }
    } else if (name == "STRCOMP") {
        auto source = stringSource("SRC_");
        if (!source) return std::nullopt;
        auto search = stringSource("SEA_");
        if (!search) return std::nullopt;
        int cmp = source->compare(*search);
        result = cmp < 0 ? -1.0 : (cmp > 0 ? 1.0 : 0.0);
    } else if (name == "INSTR") {
        auto source = stringSource("SRC_");
        if (!source) return std::nullopt;
        auto search = stringSource("SEA_");
        if (!search) return std::nullopt;
        double begin = 0.0;
        if (m_cursor.peekKeyword("BEG") || upper(m_cursor.peek()) == 'B') {
            auto value = tagValue("BEG");
            if (!value) return std::nullopt;
            begin = *value;
        }
        size_t from = saturatingCast<size_t>(begin);
        size_t found = from <= source->size() ? source->find(*search, from) : std::string::npos;
        result = static_cast<double>(found == std::string::npos ? source->size() : found);
    } else {  // TONUMB
        auto source = stringSource("SRC_");
        if (!source) return std::nullopt;
        if (m_env) {
            std::string text = *source;
            for (char& ch : text) {
                if (ch == ',') ch = '.';
            }
            size_t first = text.find_first_not_of(" \t+");
            const char* begin = text.data() + (first == std::string::npos ? text.size() : first);
            auto parsed = std::from_chars(begin, text.data() + text.size(), result);
            if (parsed.ec != std::errc() || !std::isfinite(result)) {
                return fail("math", KERF_TR_NOOP("'{1}' is not a number"), {*source});
            }
        }
    }
    if (!m_cursor.acceptChar(')')) return fail("syntax", KERF_TR_NOOP("')' expected"));
    return result;
}

std::optional<std::string> FormulaParser::stringExpression() {
    m_cursor.skipBlanks();
    size_t at = m_cursor.position();
    auto left = stringTerm();
    if (!left) return std::nullopt;
    for (;;) {
        if (left->size() > kMaxStringLength) {
            m_cursor.setPosition(at);
            fail("string-length", KERF_TR_NOOP("a string may hold at most {1} characters, not {2}"),
                 {std::to_string(kMaxStringLength), std::to_string(left->size())});
            return std::nullopt;
        }
        if (m_cursor.peek() != '|') return left;
        at = m_cursor.position();
        if (m_cursor.text().substr(at, 2) != "||") {
            fail("syntax", KERF_TR_NOOP("'||' expected"));
            return std::nullopt;
        }
        m_cursor.setPosition(at + 2);
        auto right = stringTerm();
        if (!right) return std::nullopt;
        *left += *right;
    }
}

std::optional<std::string> FormulaParser::stringTerm() {
    if (auto literal = m_cursor.quoted()) return std::string(*literal);
    if (m_cursor.acceptKeyword("TOCHAR")) {
        if (!m_cursor.acceptChar('(')) {
            fail("syntax", KERF_TR_NOOP("'(' expected"));
            return std::nullopt;
        }
        auto value = tagValue("DAT");
        if (!value) return std::nullopt;
        int decimals = 3;
        if (m_cursor.peekKeyword("DECIMALS") || upper(m_cursor.peek()) == 'D') {
            auto d = tagValue("DECIMALS");
            if (!d) return std::nullopt;
            decimals = static_cast<int>(std::clamp(*d, 0.0, 9.0));
        }
        if (!m_cursor.acceptChar(')')) {
            fail("syntax", KERF_TR_NOOP("')' expected"));
            return std::nullopt;
        }
        // Sign, the 309 integral digits of the largest double, point and 9 decimals.
        char buffer[1 + 309 + 1 + 9];
        auto r = std::to_chars(buffer, buffer + sizeof buffer, *value, std::chars_format::fixed,
                               decimals);
        return std::string(buffer, r.ptr);
    }
    if (m_cursor.acceptKeyword("SUBSTR")) {
        if (!m_cursor.acceptChar('(')) {
            fail("syntax", KERF_TR_NOOP("'(' expected"));
            return std::nullopt;
        }
        auto source = stringSource("SRC_");
        if (!source) return std::nullopt;
        auto begin = tagValue("BEG");
        if (!begin) return std::nullopt;
        auto length = tagValue("LEN");
        if (!length) return std::nullopt;
        if (!m_cursor.acceptChar(')')) {
            fail("syntax", KERF_TR_NOOP("')' expected"));
            return std::nullopt;
        }
        if (*begin < 0.0 || *length < 0.0) {
            if (checkOnly()) return std::string();
            fail("math", KERF_TR_NOOP("SUBSTR needs BEG and LEN of at least 0"));
            return std::nullopt;
        }
        auto from = saturatingCast<size_t>(*begin);
        if (from > source->size()) return std::string();
        return source->substr(from, saturatingCast<size_t>(*length));
    }
    if (m_cursor.acceptKeyword("SYSSTR")) {
        if (!m_cursor.acceptChar('(')) {
            fail("syntax", KERF_TR_NOOP("'(' expected"));
            return std::nullopt;
        }
        auto id = tagValue("ID");
        if (!id) return std::nullopt;
        double nr = 0.0;
        if (upper(m_cursor.peek()) == 'N') {
            auto value = tagValue("NR");
            if (!value) return std::nullopt;
            nr = *value;
        }
        if (!m_cursor.acceptChar(')')) {
            fail("syntax", KERF_TR_NOOP("')' expected"));
            return std::nullopt;
        }
        if (!m_env) return std::string();
        auto text = m_env->systemString(saturatingInt(*id), saturatingInt(nr));
        if (!text) {
            fail("not-supported", KERF_TR_NOOP("SYSSTR ID{1} NR{2} is not available"),
                 {std::to_string(saturatingInt(*id)), std::to_string(saturatingInt(nr))});
            return std::nullopt;
        }
        return text;
    }
    auto ref = parameter(true);
    if (!ref || ref->kind != QKind::QS) {
        if (!m_problem) fail("syntax", KERF_TR_NOOP("string expected"));
        return std::nullopt;
    }
    return m_env ? m_env->string(ref->index) : kEmpty;
}

}  // namespace kerf::klartext
