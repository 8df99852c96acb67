#include "core/interp/klartext/block_parser.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "core/base/saturating.h"
#include "core/base/translate.h"
#include "core/interp/klartext/digit_run.h"

namespace kerf::klartext {

namespace {

// Flags for the words a block may contain after its head.
enum WordFlag : uint32_t {
    kAxes = 1u << 0,
    kComp = 1u << 1,
    kFeed = 1u << 2,
    kM = 1u << 3,
    kDirection = 1u << 4,
    kRadius = 1u << 5,
    kPolar = 1u << 6,
    kLength = 1u << 7,
    kAngle = 1u << 8,
    kVectors = 1u << 9,  // LN: NX NY NZ TX TY TZ
};

struct Words {
    Coordinates* coords = nullptr;
    CommonWords* common = nullptr;
    Direction* direction = nullptr;
    std::optional<double>* radius = nullptr;
    PolarWords* polar = nullptr;
    std::optional<double>* length = nullptr;
    std::optional<double>* angle = nullptr;
    std::array<std::optional<double>, 6>* vectors = nullptr;  // NX NY NZ TX TY TZ
};

bool startsValue(char c) {
    return c == '+' || c == '-' || c == '(' || isDigit(c) || c == '.' || c == 'Q' || c == 'q';
}

std::string upperCopy(std::string_view text) {
    std::string out(text);
    for (char& c : out)
        c = upper(c);
    return out;
}

}  // namespace

struct BlockParser::Context {
    Cursor cursor;
    FormulaParser formula;
    ParseProblem& problem;
    bool failed = false;

    Context(std::string_view text, FormulaEnvironment* env, FormulaCache& formulas, ParseProblem& p)
        : cursor(text), formula(cursor, env, &formulas), problem(p), evaluating(env != nullptr) {}

    // Values computed from Q parameters are only known when the block runs: range errors are
    // reported then, not when the program is checked.
    bool evaluating;
    bool valueError(const char* messageTemplate, std::vector<std::string> args = {}) {
        if (!evaluating) return true;
        return fail("range", messageTemplate, std::move(args));
    }

    bool fail(std::string code, std::string messageTemplate, std::vector<std::string> args = {}) {
        if (!failed) {
            failed = true;
            problem = ParseProblem{cursor.position(), std::move(code), std::move(messageTemplate),
                                   std::move(args)};
        }
        return false;
    }
    // Moves a problem reported by the formula parser into ours.
    bool formulaFailed() {
        if (!failed && formula.problem()) {
            failed = true;
            problem = *formula.problem();
        }
        return false;
    }
    bool value(double& out) {
        auto v = formula.wordValue();
        if (!v) return formulaFailed();
        out = *v;
        return true;
    }
    bool unexpected() {
        std::string_view rest = cursor.rest();
        size_t end = rest.find_first_of(" \t;");
        std::string token(rest.substr(0, end == std::string_view::npos ? rest.size() : end));
        return fail("syntax", KERF_TR_NOOP("unexpected '{1}'"), {token});
    }
    bool expectEnd() {
        if (cursor.atEnd()) return true;
        return unexpected();
    }

    bool parseFeed(FeedWord& feed) {
        if (cursor.acceptKeyword("FMAX")) {
            feed.kind = FeedWord::Kind::Max;
            return true;
        }
        if (cursor.acceptKeyword("FAUTO")) {
            feed.kind = FeedWord::Kind::Auto;
            return true;
        }
        if (cursor.acceptPrefix("FU")) {
            feed.kind = FeedWord::Kind::PerRevolution;
            return value(feed.value);
        }
        if (cursor.acceptPrefix("FZ")) {
            feed.kind = FeedWord::Kind::PerTooth;
            return value(feed.value);
        }
        cursor.acceptPrefix("F");
        // Some listings separate the keyword: "F AUTO", "F MAX".
        if (cursor.acceptKeyword("AUTO")) {
            feed.kind = FeedWord::Kind::Auto;
            return true;
        }
        if (cursor.acceptKeyword("MAX")) {
            feed.kind = FeedWord::Kind::Max;
            return true;
        }
        feed.kind = FeedWord::Kind::Value;
        if (!value(feed.value)) return false;
        if (feed.value < 0.0) return valueError(KERF_TR_NOOP("the feed rate must not be negative"));
        return true;
    }

    bool parseM(MWords& m) {
        size_t at = cursor.position();
        cursor.acceptPrefix("M");
        auto number = cursor.unsignedInteger();
        if (!number || *number > 9999) {
            cursor.setPosition(at);
            return fail("syntax", KERF_TR_NOOP("M function number expected"));
        }
        if (m.count >= m.list.size()) {
            cursor.setPosition(at);
            return fail("syntax", KERF_TR_NOOP("too many M functions in one block"));
        }
        MWord& word = m.list[m.count++];
        word.number = static_cast<int>(*number);
        if (cursor.acceptKeyword("MB")) {
            if (cursor.acceptKeyword("MAX")) {
                word.maxParameter = true;
            } else {
                double v = 0.0;
                if (!value(v)) return false;
                word.parameter = v;
            }
        }
        if (word.number == 120 && cursor.acceptPrefix("LA")) return lookAhead(word);
        if (word.number == 94) return reducedAxes(word);
        if (word.number == 118) return handwheelLimits();
        return true;
    }

    // M120 LA n: how many blocks the radius compensation looks ahead (0 to 99).
    bool lookAhead(MWord& word) {
        double v = 0.0;
        if (!value(v)) return false;
        if (v < 0.0 || v > 99.0 || v != std::floor(v)) {
            return valueError(KERF_TR_NOOP("M120 LA: a whole number of blocks from 0 to 99"));
        }
        word.parameter = v;
        return true;
    }

    // M94 C: the rotary axes whose display is reduced, letters without values.
    bool reducedAxes(MWord& word) {
        for (;;) {
            cursor.skipBlanks();
            const std::string_view rest = cursor.text().substr(cursor.position());
            if (rest.size() < 1) return true;
            const auto axis = axisFromLetter(upper(rest[0]));
            const char after = rest.size() > 1 ? rest[1] : ' ';
            if (!axis || !(after == ' ' || after == '\t' || after == ';')) return true;
            word.axes |= axisBit(*axis);
            cursor.setPosition(cursor.position() + 1);
        }
    }

    // M118 X.. Y..: how far the handwheel may move each axis during the run. The simulated
    // machine has no handwheel, so the values are only read.
    bool handwheelLimits() {
        for (;;) {
            cursor.skipBlanks();
            const std::string_view rest = cursor.text().substr(cursor.position());
            if (rest.size() < 2 || !axisFromLetter(upper(rest[0])) || !startsValue(rest[1]))
                return true;
            cursor.setPosition(cursor.position() + 1);
            double v = 0.0;
            if (!value(v)) return false;
        }
    }

    bool parseAxis(Coordinates& coords, bool incremental) {
        char letter = upper(cursor.peekRaw());
        auto axis = axisFromLetter(letter);
        size_t at = cursor.position();
        cursor.setPosition(at + 1);
        if (coords.has(*axis)) {
            cursor.setPosition(at);
            return fail("syntax", KERF_TR_NOOP("axis {1} is programmed twice"),
                        {std::string(1, letter)});
        }
        AxisWord& word = coords.axes[static_cast<size_t>(*axis)];
        word.present = true;
        word.incremental = incremental;
        coords.present |= axisBit(*axis);
        return value(word.value);
    }

    bool parseWords(uint32_t allowed, Words w) {
        bool radiusRead = false;
        while (!cursor.atEnd()) {
            char c = upper(cursor.peek());
            char next = upper(cursor.text().size() > cursor.position() + 1
                                  ? cursor.text()[cursor.position() + 1]
                                  : '\0');
            // Axis words are by far the most common: try them first.
            if ((allowed & kAxes) != 0 && axisFromLetter(c) &&
                !(c == 'C' && next == 'C' && (allowed & kAngle) != 0) &&
                (startsValue(next) || next == ' ')) {
                if (!parseAxis(*w.coords, false)) return false;
                continue;
            }
            // Older controls list a word that was not entered as its bare letter ("R F M").
            bool bare = next == '\0' || next == ' ' || next == '\t' || next == ';';
            if (bare && c == 'F') {
                Cursor ahead(cursor.text(), cursor.position() + 1);
                bare = !ahead.peekKeyword("AUTO") && !ahead.peekKeyword("MAX");
            }
            if (bare &&
                ((c == 'R' && (allowed & kComp) != 0) || (c == 'F' && (allowed & kFeed) != 0) ||
                 (c == 'M' && (allowed & kM) != 0))) {
                cursor.setPosition(cursor.position() + 1);
                continue;
            }
            if ((allowed & kPolar) != 0) {
                bool inc = c == 'I' && (next == 'P');
                size_t at = cursor.position();
                if (inc) cursor.setPosition(at + 1);
                if (cursor.acceptPrefix("PR")) {
                    double v = 0.0;
                    if (!value(v)) return false;
                    w.polar->radius = v;
                    w.polar->radiusIncremental = inc;
                    continue;
                }
                if (cursor.acceptPrefix("PA")) {
                    double v = 0.0;
                    if (!value(v)) return false;
                    w.polar->angle = v;
                    w.polar->angleIncremental = inc;
                    continue;
                }
                cursor.setPosition(at);
            }
            if ((allowed & kVectors) != 0 && (c == 'N' || c == 'T') &&
                (next == 'X' || next == 'Y' || next == 'Z')) {
                const size_t index = (c == 'T' ? 3u : 0u) + static_cast<size_t>(next - 'X');
                cursor.setPosition(cursor.position() + 2);
                double v = 0.0;
                if (!value(v)) return false;
                (*w.vectors)[index] = v;
                continue;
            }
            if ((allowed & kLength) != 0 && cursor.acceptPrefix("LEN")) {
                double v = 0.0;
                if (!value(v)) return false;
                *w.length = v;
                continue;
            }
            if ((allowed & kAngle) != 0 && cursor.acceptPrefix("CCA")) {
                double v = 0.0;
                if (!value(v)) return false;
                *w.angle = v;
                continue;
            }
            if ((allowed & kDirection) != 0 && c == 'D' && next == 'R') {
                size_t at = cursor.position();
                cursor.setPosition(at + 2);
                char sign = cursor.peek();
                if (sign == '+' || sign == '-') {
                    cursor.setPosition(cursor.position() + 1);
                    *w.direction = sign == '+' ? Direction::Ccw : Direction::Cw;
                    continue;
                }
                cursor.setPosition(at);
                return fail("syntax", KERF_TR_NOOP("DR+ or DR- expected"));
            }
            if (c == 'R' && (allowed & kComp) != 0) {
                if (cursor.acceptKeyword("RL")) {
                    w.common->comp = CompWord::Left;
                    continue;
                }
                if (cursor.acceptKeyword("RR")) {
                    w.common->comp = CompWord::Right;
                    continue;
                }
                bool radiusExpected = (allowed & kRadius) != 0 && !radiusRead;
                if (next == '0' && !radiusExpected) {
                    size_t at = cursor.position();
                    cursor.setPosition(at + 2);
                    char after = cursor.peekRaw();
                    if (!isDigit(after) && after != '.' && after != ',') {
                        w.common->comp = CompWord::Off;
                        continue;
                    }
                    cursor.setPosition(at);
                }
            }
            if (c == 'R' && (allowed & kRadius) != 0 && !radiusRead) {
                cursor.setPosition(cursor.position() + 1);
                double v = 0.0;
                if (!value(v)) return false;
                *w.radius = v;
                radiusRead = true;
                continue;
            }
            if (c == 'F' && (allowed & kFeed) != 0) {
                if (!parseFeed(w.common->feed)) return false;
                continue;
            }
            if (c == 'M' && isDigit(next) && (allowed & kM) != 0) {
                if (!parseM(w.common->m)) return false;
                continue;
            }
            if ((allowed & kAxes) != 0) {
                bool inc = c == 'I' && axisFromLetter(next).has_value();
                size_t at = cursor.position();
                if (inc) cursor.setPosition(at + 1);
                char letter = upper(cursor.peekRaw());
                if (axisFromLetter(letter)) {
                    char after = cursor.text().size() > cursor.position() + 1
                                     ? cursor.text()[cursor.position() + 1]
                                     : '\0';
                    if (startsValue(after) || after == ' ') {
                        if (!parseAxis(*w.coords, inc)) return false;
                        continue;
                    }
                }
                cursor.setPosition(at);
            }
            return unexpected();
        }
        return true;
    }
};

std::string_view BlockParser::headWord(std::string_view text) {
    Cursor c(text);
    c.skipBlanks();
    if (isDigit(c.peekRaw())) {
        c.unsignedInteger();
    }
    c.skipBlanks();
    if (c.peekRaw() == '/') {
        c.setPosition(c.position() + 1);
        c.unsignedInteger();
    }
    c.skipBlanks();
    size_t start = c.position();
    size_t end = start;
    while (end < text.size() && isLetter(text[end]))
        ++end;
    return text.substr(start, end - start);
}

bool BlockParser::parse(const program::LogicalLine& line, ParsedBlock& out) {
    out.hidden = false;
    if (line.text.size() > program::kMaxBlockCharacters) {
        return failAt(program::kMaxBlockCharacters, "syntax",
                      KERF_TR_NOOP("the block is longer than 60000 characters"));
    }
    // "123 L ...", most blocks of a CAM program: the number read here, the line in one pass.
    const std::string_view text = line.text;
    size_t digits = 0;
    int64_t leadingNumber = 0;
    uint64_t chunk = 0;
    const uint64_t stops = eightCharacters(text, 0, chunk) ? notDigits(chunk) : 0;
    if (stops != 0) {
        // Fewer than eight digits: all of them at once.
        digits = static_cast<size_t>(std::countr_zero(stops) >> 3);
        if (digits > 0)
            leadingNumber = static_cast<int64_t>(digitsValue(chunk, static_cast<int>(digits)));
    } else {
        while (digits < text.size() && digits < 18 && isDigit(text[digits]))
            leadingNumber = leadingNumber * 10 + (text[digits++] - '0');
    }
    const bool numbered = digits > 0 && digits < 18 && digits < text.size() &&
                          (text[digits] == ' ' || text[digits] == '\t');
    // A loop runs the same text again: a line the one pass gave up on is not tried again.
    const bool general = text.data() == m_generalLine.data() && text.size() == m_generalLine.size();
    const bool literalLine = numbered && !general && digits + 2 < text.size() &&
                             text[digits] == ' ' && text[digits + 1] == 'L' &&
                             (text[digits + 2] == ' ' || text[digits + 2] == '\t');
    if (literalLine) {
        if (parseLiteralLine(text, digits + 2, out)) {
            out.blockNumber = leadingNumber;
            return true;
        }
        m_generalLine = text;
    }
    out.blockNumber = -1;
    Context c(line.text, m_env, m_formulas, m_problem);
    Cursor& cur = c.cursor;
    if (numbered) {
        out.blockNumber = leadingNumber;
        cur.setPosition(digits);
    }
    cur.skipBlanks();
    if (!numbered && isDigit(cur.peekRaw())) {
        size_t at = cur.position();
        auto number = cur.unsignedInteger();
        char after = cur.peekRaw();
        if (!number || (after != ' ' && after != '\t' && after != '\0' && after != ';')) {
            cur.setPosition(at);
            out.statement = Empty{};
            return c.unexpected();
        }
        out.blockNumber = *number;
    }
    if (cur.peek() == '/') {
        cur.setPosition(cur.position() + 1);
        cur.unsignedInteger();
        out.hidden = true;
    }
    cur.skipBlanks();
    const size_t head = cur.position();
    if (!literalLine && !general && head + 1 < line.text.size() && line.text[head] == 'L' &&
        (line.text[head + 1] == ' ' || line.text[head + 1] == '\t') &&
        parseLiteralLine(line.text, head + 1, out)) {
        return true;
    }
    out.statement = Empty{};
    if (cur.atEnd() || cur.peek() == '*') return true;
    return parseStatement(c, line, out);
}

namespace {

bool parseLabelTarget(BlockParser::Context& c, LabelTarget& target, bool allowZero);

std::optional<Axis> parseToolAxis(Cursor& cur) {
    size_t at = cur.position();
    char letter = upper(cur.peek());
    auto axis = axisFromLetter(letter);
    if (!axis) return std::nullopt;
    cur.setPosition(cur.position() + 1);
    char after = cur.peekRaw();
    if (after != ' ' && after != '\t' && after != '\0' && after != ';') {
        cur.setPosition(at);
        return std::nullopt;
    }
    return axis;
}

}  // namespace

// Splits out the head word and dispatches; one branch per kind of block.
bool BlockParser::parseStatement(Context& c, const program::LogicalLine& line, ParsedBlock& out) {
    Cursor& cur = c.cursor;
    const size_t headAt = cur.position();
    size_t end = headAt;
    const std::string_view text = cur.text();
    while (end < text.size() && isLetter(text[end]))
        ++end;
    // Heads are short keywords: compare an upper-case copy kept on the stack.
    char headBuffer[16];
    const size_t headLength = std::min(end - headAt, sizeof headBuffer);
    for (size_t i = 0; i < headLength; ++i)
        headBuffer[i] = upper(text[headAt + i]);
    const std::string_view head(headBuffer, end - headAt <= sizeof headBuffer ? headLength : 0);
    cur.setPosition(end);

    auto deferred = [&](std::string feature) {
        out.statement = Deferred{std::move(feature), std::string(line.text)};
        return true;
    };

    if (head.size() == 1 && head[0] == 'L') {
        // Parsed in place: this is the block CAM programs consist of.
        LinearBlock& b = out.statement.emplace<LinearBlock>();
        PolarWords polar;
        Words w{&b.coords, &b.words};
        w.polar = &polar;
        if (!c.parseWords(kAxes | kComp | kFeed | kM | kPolar, w)) return false;
        if (polar.radius || polar.angle) {
            // The manual's own examples write "L PR+25 PA+0" for LP (spec §8.1, manual error).
            LinePolarBlock lp{polar, b.coords, b.words};
            out.statement = lp;
            return true;
        }
        if (b.coords.present == 0 && b.words.comp == CompWord::None) {
            CommonWords words = b.words;
            out.statement = MFunctionBlock{words};
        }
        return true;
    }
    if (head == "LN") {
        LineNormalBlock b;
        std::array<std::optional<double>, 6> vectors;
        Words w{&b.coords, &b.words};
        w.vectors = &vectors;
        if (!c.parseWords(kAxes | kComp | kFeed | kM | kVectors, w)) return false;
        auto vector = [&](size_t first) -> std::optional<Vec3> {
            if (!vectors[first] || !vectors[first + 1] || !vectors[first + 2]) return std::nullopt;
            return Vec3(*vectors[first], *vectors[first + 1], *vectors[first + 2]);
        };
        const auto normal = vector(0);
        b.tool = vector(3);
        const bool someTool = vectors[3] || vectors[4] || vectors[5];
        if (!normal || (someTool && !b.tool)) {
            return c.fail("syntax",
                          KERF_TR_NOOP("LN needs all of NX NY NZ, and TX TY TZ all or none"));
        }
        b.normal = *normal;
        out.statement = b;
        return true;
    }
    // Q parameters and jumps are what loops consist of: before the long list of other heads.
    if (head == "Q" || head == "QL" || head == "QR" || head == "QS" ||
        (head == "DECLARE" && !cur.peekKeyword("CONTOUR"))) {
        if (head == "DECLARE") {
            if (!cur.acceptKeyword("STRING")) return deferred("DECLARE");
        } else {
            cur.setPosition(headAt);
        }
        size_t targetAt = cur.position();
        auto ref = c.formula.parameter(true);
        if (!ref) {
            if (c.formula.problem()) return c.formulaFailed();
            return c.fail("syntax", KERF_TR_NOOP("Q parameter expected"));
        }
        if (!cur.acceptChar('=')) return c.fail("syntax", KERF_TR_NOOP("'=' expected"));
        if (ref->kind == QKind::QS) {
            auto value = c.formula.stringExpression();
            if (!value) return c.formulaFailed();
            if (!c.expectEnd()) return false;
            out.statement = QStringAssign{ref->index, std::move(*value)};
            return true;
        }
        if (head == "DECLARE") {
            cur.setPosition(targetAt);
            return c.fail("syntax", KERF_TR_NOOP("DECLARE STRING needs a QS parameter"));
        }
        auto value = c.formula.expression();
        if (!value) return c.formulaFailed();
        if (!c.expectEnd()) return false;
        out.statement = QAssign{*ref, *value};
        return true;
    }
    if (head == "FN") {
        auto fn = cur.unsignedInteger();
        if (!fn) return c.fail("syntax", KERF_TR_NOOP("FN number expected"));
        if (!cur.acceptChar(':'))
            return c.fail("syntax", KERF_TR_NOOP("':' expected after FN {1}"),
                          {std::to_string(*fn)});
        auto target = [&]() -> std::optional<QRef> {
            auto ref = c.formula.parameter(false);
            if (!ref) {
                if (c.formula.problem()) {
                    c.formulaFailed();
                } else {
                    c.fail("syntax", KERF_TR_NOOP("Q parameter expected"));
                }
                return std::nullopt;
            }
            if (!cur.acceptChar('=')) {
                c.fail("syntax", KERF_TR_NOOP("'=' expected"));
                return std::nullopt;
            }
            return ref;
        };
        auto operand = [&](double& v) {
            auto value = c.formula.signedOperand();
            if (!value) return c.formulaFailed();
            v = *value;
            return true;
        };
        switch (*fn) {
            case 0:
            case 1:
            case 2:
            case 3:
            case 4:
            case 8:
            case 13: {
                auto ref = target();
                if (!ref) return false;
                double a = 0.0, b = 0.0;
                if (!operand(a)) return false;
                size_t opAt = cur.position();
                if (*fn != 0) {
                    static const char* const kOps[] = {"", "+", "-", "*", "DIV", "", "", "", "LEN"};
                    const char* op = *fn == 13 ? "ANG" : kOps[*fn];
                    bool symbol = *fn >= 1 && *fn <= 3;
                    bool ok = symbol ? cur.acceptChar(op[0]) : cur.acceptPrefix(op);
                    if (!ok) return c.fail("syntax", KERF_TR_NOOP("'{1}' expected"), {op});
                    if (!operand(b)) return false;
                }
                double result = a;
                switch (*fn) {
                    case 1:
                        result = a + b;
                        break;
                    case 2:
                        result = a - b;
                        break;
                    case 3:
                        result = a * b;
                        break;
                    case 4:
                        if (b == 0.0 && m_env) {
                            cur.setPosition(opAt);
                            return c.fail("math", KERF_TR_NOOP("division by zero"));
                        }
                        result = b == 0.0 ? 0.0 : a / b;
                        break;
                    case 8:
                        result = std::hypot(a, b);
                        break;
                    case 13: {
                        result = std::atan2(b, a) * 180.0 / 3.14159265358979323846;
                        if (result < 0.0) result += 360.0;
                        break;
                    }
                    default:
                        break;
                }
                if (!c.expectEnd()) return false;
                out.statement = QAssign{*ref, result};
                return true;
            }
            case 5:
            case 6:
            case 7: {
                auto ref = target();
                if (!ref) return false;
                const char* op = *fn == 5 ? "SQRT" : (*fn == 6 ? "SIN" : "COS");
                if (!cur.acceptKeyword(op))
                    return c.fail("syntax", KERF_TR_NOOP("'{1}' expected"), {op});
                double a = 0.0;
                if (!operand(a)) return false;
                double result;
                if (*fn == 5) {
                    if (a < 0.0 && m_env)
                        return c.fail("math", KERF_TR_NOOP("square root of a negative number"));
                    result = a < 0.0 ? 0.0 : std::sqrt(a);
                } else {
                    double rad = a * 3.14159265358979323846 / 180.0;
                    result = *fn == 6 ? std::sin(rad) : std::cos(rad);
                }
                if (!c.expectEnd()) return false;
                out.statement = QAssign{*ref, result};
                return true;
            }
            case 9:
            case 10:
            case 11:
            case 12: {
                if (!cur.acceptKeyword("IF"))
                    return c.fail("syntax", KERF_TR_NOOP("'IF' expected"));
                ConditionalJump b;
                if (!operand(b.left)) return false;
                static const char* const kWords[] = {"EQU", "NE", "GT", "LT"};
                const char* word = kWords[*fn - 9];
                if (!cur.acceptKeyword(word))
                    return c.fail("syntax", KERF_TR_NOOP("'{1}' expected"), {word});
                b.comparison = static_cast<Comparison>(*fn - 9);
                if (!operand(b.right)) return false;
                if (!cur.acceptKeyword("GOTO"))
                    return c.fail("syntax", KERF_TR_NOOP("'GOTO' expected"));
                if (!cur.acceptKeyword("LBL") && !cur.acceptPrefix("LBL")) {
                    return c.fail("syntax", KERF_TR_NOOP("'LBL' expected"));
                }
                if (!parseLabelTarget(c, b.target, false)) return false;
                if (!c.expectEnd()) return false;
                out.statement = b;
                return true;
            }
            case 14: {
                if (!cur.acceptKeyword("ERROR"))
                    return c.fail("syntax", KERF_TR_NOOP("'ERROR' expected"));
                if (!cur.acceptChar('=')) return c.fail("syntax", KERF_TR_NOOP("'=' expected"));
                double number = 0.0;
                if (!c.value(number)) return false;
                if (!c.expectEnd()) return false;
                out.statement = ErrorBlock{saturatingInt(number)};
                return true;
            }
            case 15: {
                if (!cur.acceptKeyword("PRINT"))
                    return c.fail("syntax", KERF_TR_NOOP("'PRINT' expected"));
                PrintBlock b;
                if (auto textValue = cur.quoted()) {
                    b.text = std::string(*textValue);
                } else {
                    do {
                        double v = 0.0;
                        if (!operand(v)) return false;
                        b.values.push_back(v);
                    } while (cur.acceptChar('/'));
                }
                if (!c.expectEnd()) return false;
                out.statement = b;
                return true;
            }
            case 16: {
                if (!cur.acceptKeyword("F-PRINT") && !cur.acceptPrefix("F-PRINT")) {
                    return c.fail("syntax", KERF_TR_NOOP("'F-PRINT' expected"));
                }
                std::string_view rest = cur.restUntilComment();
                // "mask / output": the separator is a slash between blanks (TNC names may
                // contain forward slashes too).
                size_t slash = rest.find(" / ");
                if (slash != std::string_view::npos) {
                    ++slash;
                } else {
                    slash = rest.find('/');
                }
                PrintBlock b;
                b.formatted = true;
                if (slash == std::string_view::npos) {
                    return c.fail("syntax", KERF_TR_NOOP("'mask file / output file' expected"));
                }
                auto trim = [](std::string_view s) {
                    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
                        s.remove_prefix(1);
                    while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
                        s.remove_suffix(1);
                    return std::string(s);
                };
                b.maskFile = trim(rest.substr(0, slash));
                b.outputFile = trim(rest.substr(slash + 1));
                if (b.maskFile.empty() || b.outputFile.empty()) {
                    return c.fail("syntax", KERF_TR_NOOP("'mask file / output file' expected"));
                }
                out.statement = b;
                return true;
            }
            case 18: {
                if (!cur.acceptKeyword("SYSREAD"))
                    return c.fail("syntax", KERF_TR_NOOP("'SYSREAD' expected"));
                SysRead b;
                auto ref = target();
                if (!ref) return false;
                b.target = *ref;
                double v = 0.0;
                if (!cur.acceptPrefix("ID")) return c.fail("syntax", KERF_TR_NOOP("'ID' expected"));
                if (!c.value(v)) return false;
                b.id = saturatingInt(v);
                if (cur.acceptPrefix("NR")) {
                    if (!c.value(v)) return false;
                    b.nr = saturatingInt(v);
                }
                if (cur.acceptPrefix("IDX")) {
                    if (!c.value(v)) return false;
                    b.idx = saturatingInt(v);
                    b.hasIdx = true;
                }
                if (!c.expectEnd()) return false;
                out.statement = b;
                return true;
            }
            case 23:
            case 24: {
                if (!cur.acceptKeyword("CDATA"))
                    return c.fail("syntax", KERF_TR_NOOP("'CDATA' expected"));
                CircleData b;
                b.points = *fn == 23 ? 3 : 4;
                auto ref = target();
                if (!ref) return false;
                b.target = *ref;
                auto source = c.formula.parameter(false);
                if (!source) return c.fail("syntax", KERF_TR_NOOP("Q parameter expected"));
                b.source = *source;
                if (b.target.index + 2 >= qLimit(b.target.kind) ||
                    b.source.index + 2 * b.points - 1 >= qLimit(b.source.kind)) {
                    return c.fail(
                        "range",
                        KERF_TR_NOOP("the parameter range runs past the last Q parameter"));
                }
                if (!c.expectEnd()) return false;
                out.statement = b;
                return true;
            }
            case 26: {
                if (!cur.acceptKeyword("TABOPEN"))
                    return c.fail("syntax", KERF_TR_NOOP("'TABOPEN' expected"));
                std::string_view path = cur.restUntilComment();
                if (path.empty()) return c.fail("syntax", KERF_TR_NOOP("table name expected"));
                out.statement = TableOpen{std::string(path)};
                return true;
            }
            case 27:
            case 28: {
                TableAccess b;
                b.write = *fn == 27;
                if (!cur.acceptKeyword(b.write ? "TABWRITE" : "TABREAD")) {
                    return c.fail("syntax", KERF_TR_NOOP("'{1}' expected"),
                                  {b.write ? "TABWRITE" : "TABREAD"});
                }
                if (!b.write) {
                    auto ref = target();
                    if (!ref) return false;
                    b.parameter = *ref;
                }
                double row = 0.0;
                if (!c.value(row)) return false;
                b.row = saturatingInt(row);
                if (!cur.acceptChar('/')) return c.fail("syntax", KERF_TR_NOOP("'/' expected"));
                auto columns = cur.quoted();
                if (!columns)
                    return c.fail("syntax", KERF_TR_NOOP("column names in quotes expected"));
                b.columns = std::string(*columns);
                for (size_t start = 0; start <= columns->size();) {
                    size_t comma = columns->find(',', start);
                    if (comma == std::string_view::npos) comma = columns->size();
                    if (columns->substr(start, comma - start).find_first_not_of(' ') !=
                        std::string_view::npos) {
                        ++b.columnCount;
                    }
                    start = comma + 1;
                }
                if (b.columnCount == 0)
                    return c.fail("syntax", KERF_TR_NOOP("column names in quotes expected"));
                if (b.write) {
                    if (!cur.acceptChar('=')) return c.fail("syntax", KERF_TR_NOOP("'=' expected"));
                    auto ref = c.formula.parameter(false);
                    if (!ref) return c.fail("syntax", KERF_TR_NOOP("Q parameter expected"));
                    b.parameter = *ref;
                }
                if (b.parameter.index + b.columnCount >
                    static_cast<size_t>(qLimit(b.parameter.kind))) {
                    return c.fail(
                        "range",
                        KERF_TR_NOOP("the parameter range runs past the last Q parameter"));
                }
                if (!c.expectEnd()) return false;
                out.statement = b;
                return true;
            }
            case 20:
                // WAIT FOR SYNC: the read-ahead stops here until the machine has reached
                // this block. Waiting for PLC conditions needs a PLC Kerf does not have.
                if (cur.acceptKeyword("WAIT") && cur.acceptKeyword("FOR") &&
                    cur.acceptKeyword("SYNC")) {
                    if (!c.expectEnd()) return false;
                    out.statement = WaitForSync{};
                    return true;
                }
                return deferred("FN 20");
            case 17:
            case 19:
            case 29:
            case 31:
            case 37:
            case 38:
                return deferred("FN " + std::to_string(*fn));
            default:
                return c.fail("syntax", KERF_TR_NOOP("FN {1} does not exist"),
                              {std::to_string(*fn)});
        }
    }
    if (head == "CC") {
        CircleCenter b;
        if (!c.parseWords(kAxes, {&b.coords})) return false;
        out.statement = b;
        return true;
    }
    if (head == "C") {
        CircleBlock b;
        Words w{&b.coords, &b.words, &b.direction};
        if (!c.parseWords(kAxes | kComp | kFeed | kM | kDirection, w)) return false;
        out.statement = b;
        return true;
    }
    if (head == "CR") {
        CircleRadiusBlock b;
        std::optional<double> radius;
        Words w{&b.coords, &b.words, &b.direction, &radius};
        if (!c.parseWords(kAxes | kComp | kFeed | kM | kDirection | kRadius, w)) return false;
        if (!radius) return c.fail("syntax", KERF_TR_NOOP("CR needs a radius R"));
        b.radius = *radius;
        out.statement = b;
        return true;
    }
    if (head == "CT") {
        CircleTangentBlock b;
        if (!c.parseWords(kAxes | kComp | kFeed | kM, {&b.coords, &b.words})) return false;
        out.statement = b;
        return true;
    }
    if (head == "LP") {
        LinePolarBlock b;
        Words w{&b.coords, &b.words};
        w.polar = &b.polar;
        if (!c.parseWords(kAxes | kComp | kFeed | kM | kPolar, w)) return false;
        out.statement = b;
        return true;
    }
    if (head == "CP") {
        CirclePolarBlock b;
        Words w{&b.coords, &b.words, &b.direction};
        w.polar = &b.polar;
        if (!c.parseWords(kAxes | kComp | kFeed | kM | kPolar | kDirection, w)) return false;
        out.statement = b;
        return true;
    }
    if (head == "CTP") {
        CircleTangentPolarBlock b;
        Words w{&b.coords, &b.words};
        w.polar = &b.polar;
        if (!c.parseWords(kAxes | kComp | kFeed | kM | kPolar, w)) return false;
        out.statement = b;
        return true;
    }
    if (head == "RND" || head == "CHF") {
        bool round = head == "RND";
        if (round) cur.acceptPrefix("R");
        double value = 0.0;
        if (!c.value(value)) return false;
        FeedWord feed;
        if (upper(cur.peek()) == 'F' && !c.parseFeed(feed)) return false;
        if (!c.expectEnd()) return false;
        if (value <= 0.0 &&
            !c.valueError(round ? KERF_TR_NOOP("the rounding radius must be positive")
                                : KERF_TR_NOOP("the chamfer length must be positive"))) {
            return false;
        }
        if (feed.kind == FeedWord::Kind::Max) {
            return c.fail("syntax", KERF_TR_NOOP("FMAX is not allowed here"));
        }
        if (round) {
            out.statement = RoundBlock{value, feed};
        } else {
            out.statement = ChamferBlock{value, feed};
        }
        return true;
    }
    if (head == "APPR" || head == "DEP") {
        ApproachBlock b;
        b.depart = head == "DEP";
        std::string_view kind = cur.word();
        std::string k = upperCopy(kind);
        if (!k.empty() && k[0] == 'P') {
            b.polar = true;
            k.erase(0, 1);
        }
        if (k == "LT") {
            b.kind = ApproachKind::LT;
        } else if (k == "LN") {
            b.kind = ApproachKind::LN;
        } else if (k == "CT") {
            b.kind = ApproachKind::CT;
        } else if (k == "LCT") {
            b.kind = ApproachKind::LCT;
        } else {
            cur.setPosition(static_cast<size_t>(kind.data() - text.data()));
            return c.fail("syntax", KERF_TR_NOOP("LT, LN, CT or LCT expected after {1}"),
                          {std::string(head)});
        }
        Words w{&b.coords, &b.words};
        w.polar = &b.polarWords;
        w.length = &b.length;
        w.angle = &b.angle;
        w.radius = &b.radius;
        uint32_t flags = kAxes | kComp | kFeed | kM | kPolar | kLength | kAngle | kRadius;
        if (b.kind == ApproachKind::LT || b.kind == ApproachKind::LN) flags &= ~kRadius;
        if (!c.parseWords(flags, w)) return false;
        out.statement = b;
        return true;
    }
    if (head == "LBL") {
        Label b;
        if (!parseLabelTarget(c, b.target, true)) return false;
        if (!c.expectEnd()) return false;
        out.statement = b;
        return true;
    }
    if (head == "CALL") {
        if (cur.acceptKeyword("LBL")) {
            CallLabel b;
            if (!parseLabelTarget(c, b.target, false)) return false;
            if ((cur.acceptKeyword("REP") || cur.acceptPrefix("REP")) && !cur.atEnd()) {
                double rep = 0.0;
                if (!c.value(rep)) return false;
                if (cur.acceptChar('/')) {  // "REP 2/2": the control shows repeats left/total
                    double total = 0.0;
                    if (!c.value(total)) return false;
                    rep = total;
                }
                // Written so that NaN is out of range too.
                const bool inRange = rep >= 0.0 && rep <= 65534.0;
                if (!inRange && !c.valueError(KERF_TR_NOOP("REP must be between 0 and 65534"))) {
                    return false;
                }
                b.repeat = inRange ? static_cast<int>(rep) : 0;
            }
            if (!c.expectEnd()) return false;
            out.statement = b;
            return true;
        }
        if (cur.acceptKeyword("PGM")) {
            std::string_view path = cur.restUntilComment();
            if (path.empty()) return c.fail("syntax", KERF_TR_NOOP("program name expected"));
            out.statement = CallPgm{std::string(path)};
            return true;
        }
        if (cur.acceptKeyword("SELECTED")) {
            if (!cur.acceptKeyword("PGM")) return c.fail("syntax", KERF_TR_NOOP("PGM expected"));
            if (!c.expectEnd()) return false;
            out.statement = CallSelectedProgram{};
            return true;
        }
        return c.fail("syntax", KERF_TR_NOOP("LBL or PGM expected after CALL"));
    }
    if (head == "STOP") {
        StopBlock b;
        CommonWords words;
        if (!c.parseWords(kM, {nullptr, &words})) return false;
        b.m = words.m;
        out.statement = b;
        return true;
    }
    if (head == "M") {
        cur.setPosition(headAt);
        MFunctionBlock b;
        if (!c.parseWords(kM | kFeed, {nullptr, &b.words})) return false;
        out.statement = b;
        return true;
    }
    if (head == "TOOL") {
        if (cur.acceptKeyword("CALL")) {
            ToolCall b;
            if (auto name = cur.quoted()) {
                b.name = std::string(*name);
            } else if (isDigit(cur.peek())) {
                auto number = cur.unsignedNumber();  // "5.1": tool 5, index 1
                if (!number || *number > 32767) {
                    return c.fail("range", KERF_TR_NOOP("tool number out of range"));
                }
                b.number = static_cast<int>(*number);
            } else if (upper(cur.peek()) == 'Q') {
                size_t at = cur.position();
                auto ref = c.formula.parameter(true);
                if (!ref) {
                    cur.setPosition(at);
                } else if (ref->kind == QKind::QS) {
                    b.name = m_env ? m_env->string(ref->index) : std::string();
                } else {
                    double v = m_env ? m_env->number(*ref) : 0.0;
                    b.number = saturatingInt(std::round(v));
                }
            }
            if (auto axis = parseToolAxis(cur)) b.axis = axis;
            while (!cur.atEnd()) {
                double v = 0.0;
                if (cur.acceptPrefix("DR2")) {
                    if (!c.value(v)) return false;
                    b.dr2 = v;
                } else if (cur.acceptPrefix("DL")) {
                    if (!c.value(v)) return false;
                    b.dl = v;
                } else if (cur.acceptPrefix("DR")) {
                    if (!c.value(v)) return false;
                    b.dr = v;
                } else if (cur.acceptPrefix("S")) {
                    if (!c.value(v)) return false;
                    if (v < 0.0 &&
                        !c.valueError(KERF_TR_NOOP("the spindle speed must not be negative"))) {
                        return false;
                    }
                    b.speed = v;
                } else if (upper(cur.peek()) == 'F') {
                    FeedWord feed;
                    if (!c.parseFeed(feed)) return false;
                    b.feed = feed.value;
                } else {
                    return c.unexpected();
                }
            }
            out.statement = b;
            return true;
        }
        if (cur.acceptKeyword("DEF")) {
            ToolDef b;
            if (auto name = cur.quoted()) {
                b.name = std::string(*name);
            } else if (isDigit(cur.peek())) {
                auto number = cur.unsignedNumber();
                b.number = saturatingInt(number.value_or(0.0));
            }
            while (!cur.atEnd()) {
                double v = 0.0;
                if (cur.acceptPrefix("L")) {
                    if (!c.value(v)) return false;
                    b.length = v;
                } else if (cur.acceptPrefix("R")) {
                    if (!c.value(v)) return false;
                    b.radius = v;
                } else {
                    return c.unexpected();
                }
            }
            out.statement = b;
            return true;
        }
        return c.fail("syntax", KERF_TR_NOOP("CALL or DEF expected after TOOL"));
    }
    if (head == "BEGIN" || head == "END") {
        if (!cur.acceptKeyword("PGM")) return c.fail("syntax", KERF_TR_NOOP("PGM expected"));
        std::string_view name = cur.word();
        if (name.empty()) return c.fail("syntax", KERF_TR_NOOP("program name expected"));
        bool inch = false;
        if (cur.acceptKeyword("INCH")) {
            inch = true;
        } else if (!cur.acceptKeyword("MM")) {
            return c.fail("syntax", KERF_TR_NOOP("MM or INCH expected"));
        }
        if (!c.expectEnd()) return false;
        if (head == "BEGIN") {
            out.statement = BeginPgm{std::string(name), inch};
        } else {
            out.statement = EndPgm{std::string(name), inch};
        }
        return true;
    }
    if (head == "BLK") {
        if (!cur.acceptKeyword("FORM")) return c.fail("syntax", KERF_TR_NOOP("FORM expected"));
        BlkForm b;
        if (cur.acceptKeyword("CYLINDER")) {
            b.kind = BlkForm::Kind::Cylinder;
            auto axis = parseToolAxis(cur);
            if (!axis) return c.fail("syntax", KERF_TR_NOOP("axis expected"));
            b.toolAxis = *axis;
            while (!cur.atEnd()) {
                double v = 0.0;
                if (cur.acceptPrefix("RI")) {
                    if (!c.value(v)) return false;
                    b.innerRadius = v;
                } else if (cur.acceptPrefix("DIST")) {
                    if (!c.value(v)) return false;
                    b.distance = v;
                } else if (cur.acceptPrefix("D")) {
                    if (!c.value(v)) return false;
                    b.radius = v / 2.0;
                } else if (cur.acceptPrefix("R")) {
                    if (!c.value(v)) return false;
                    b.radius = v;
                } else if (cur.acceptPrefix("L")) {
                    if (!c.value(v)) return false;
                    b.length = v;
                } else {
                    return c.unexpected();
                }
            }
            out.statement = b;
            return true;
        }
        if (cur.peekKeyword("ROTATION")) return deferred("BLK FORM ROTATION");
        auto kind = cur.unsignedNumber();
        if (!kind || (*kind != 0.1 && *kind != 0.2)) {
            return c.fail("syntax", KERF_TR_NOOP("0.1, 0.2 or CYLINDER expected"));
        }
        if (*kind == 0.1) {
            b.kind = BlkForm::Kind::MinPoint;
            auto axis = parseToolAxis(cur);
            if (!axis) return c.fail("syntax", KERF_TR_NOOP("tool axis expected"));
            b.toolAxis = *axis;
        } else {
            b.kind = BlkForm::Kind::MaxPoint;
        }
        if (!c.parseWords(kAxes, {&b.point})) return false;
        out.statement = b;
        return true;
    }
    if (head == "QC" || ((head == "SEL" || head == "DECLARE") && cur.peekKeyword("CONTOUR")) ||
        (head == "CONTOUR" && cur.peekKeyword("DEF"))) {
        return parseContourFormula(head, line, head == "QC" ? headAt : cur.position(), out);
    }
    if (head == "TCH") {
        if (!cur.acceptKeyword("PROBE"))
            return c.fail("syntax", KERF_TR_NOOP("PROBE expected after TCH"));
        if (!parseCycleDef(line, cur.position(), out, true)) return false;
        std::get<CycleDefinition>(out.statement).probe = true;
        return true;
    }
    if (head == "CYCL") {
        if (cur.acceptKeyword("DEF")) return parseCycleDef(line, cur.position(), out);
        if (cur.acceptKeyword("CALL")) {
            CycleCall b;
            uint32_t flags = kFeed | kM;
            if (cur.acceptKeyword("PAT")) {
                b.kind = CycleCall::Kind::Pattern;
            } else if (cur.acceptKeyword("POS")) {
                b.kind = CycleCall::Kind::Position;
                flags |= kAxes;
            }
            if (!c.parseWords(flags, {&b.coords, &b.words})) return false;
            out.statement = b;
            return true;
        }
        return c.fail("syntax", KERF_TR_NOOP("DEF or CALL expected after CYCL"));
    }
    if (head == "GLOBAL" && cur.acceptKeyword("DEF"))
        return parseGlobalDef(line, cur.position(), out);
    if (head == "PATTERN" && cur.acceptKeyword("DEF")) {
        return parsePatternDef(line, cur.position(), out);
    }
    if (head == "SEL" && cur.acceptKeyword("PGM")) {
        // The name is quoted, a string parameter (known when the block runs) or written plain.
        SelectProgram b;
        const size_t at = cur.position();
        if (auto quoted = cur.quoted()) {
            b.path = std::string(*quoted);
        } else if (auto ref = c.formula.parameter(true); ref && ref->kind == QKind::QS) {
            b.path = m_env ? m_env->string(ref->index) : std::string();
            b.fromParameter = true;
            if (!c.expectEnd()) return false;
            out.statement = std::move(b);
            return true;
        } else {
            cur.setPosition(at);
            b.path = std::string(cur.restUntilComment());
        }
        if (b.path.empty()) return c.fail("syntax", KERF_TR_NOOP("program name expected"));
        if (!c.expectEnd()) return false;
        out.statement = std::move(b);
        return true;
    }
    if (head == "SEL" && (cur.peekKeyword("TABLE") || cur.peekKeyword("PATTERN"))) {
        const bool table = cur.acceptKeyword("TABLE");
        if (!table) cur.acceptKeyword("PATTERN");
        std::string path;
        if (auto quoted = cur.quoted()) {
            path = std::string(*quoted);
        } else {
            path = std::string(cur.restUntilComment());
        }
        if (path.empty()) return c.fail("syntax", KERF_TR_NOOP("file name expected"));
        if (!c.expectEnd()) return false;
        if (table) {
            out.statement = SelectTable{std::move(path)};
        } else {
            out.statement = SelectPattern{std::move(path)};
        }
        return true;
    }
    if (head == "FPOL" || head == "FL" || head == "FLT" || head == "FC" || head == "FCT" ||
        head == "FSELECT" || head == "FSELCT") {
        return parseFk(head, line, cur.position(), out);
    }
    if (head == "PLANE") return parsePlane(line, cur.position(), out);
    if (head == "FUNCTION" && cur.acceptKeyword("MODE")) return parseFunctionMode(cur, out);
    if (head == "FUNCTION") {
        bool handled = false;
        const bool ok = parseTcpm(line, cur.position(), out, handled);
        if (handled) return ok;
    }
    static const char* const kDeferredHeads[] = {
        "PATTERN", "SEL",     "GLOBAL",   "FUNCTION",   "TRANS",     "CONTOUR",
        "SPEC",    "PRESET",  "POLARKIN", "FACING",     "TABDATA",   "OPEN",
        "LIFTOFF", "WAIT",    "ERROR",    "MONITORING", "PARAXCOMP", "PARAXMODE",
        "RESET",   "SYSREAD", "CFGWRITE", "CFGREAD"};
    for (const char* candidate : kDeferredHeads) {
        if (head == candidate) {
            std::string feature(head);
            if (head == "PATTERN") feature = "PATTERN DEF";
            if (head == "GLOBAL") feature = "GLOBAL DEF";
            if (head == "SEL") {
                std::string_view what = cur.word();
                feature = "SEL " + upperCopy(what);
            }
            return deferred(feature);
        }
    }
    cur.setPosition(headAt);
    if (head.empty()) return c.unexpected();
    if (head == "CYCLE") {
        return c.fail("syntax", KERF_TR_NOOP("unknown block 'CYCLE' (the keyword is CYCL)"));
    }
    return c.fail("syntax", KERF_TR_NOOP("unknown block '{1}'"), {std::string(head)});
}

namespace {

bool parseLabelTarget(BlockParser::Context& c, LabelTarget& target, bool allowZero) {
    Cursor& cur = c.cursor;
    if (auto name = cur.quoted()) {
        if (name->empty()) return c.fail("syntax", KERF_TR_NOOP("label name must not be empty"));
        target.name = std::string(*name);
        return true;
    }
    char first = upper(cur.peek());
    if (first == 'Q') {
        auto ref = c.formula.parameter(true);
        if (!ref) return c.formulaFailed() || c.fail("syntax", KERF_TR_NOOP("label expected"));
        if (ref->kind == QKind::QS) {
            target.stringParameter = ref->index;
            return true;
        }
        return c.fail("syntax", KERF_TR_NOOP("label number or name expected"));
    }
    auto number = cur.unsignedInteger();
    if (!number) return c.fail("syntax", KERF_TR_NOOP("label number or name expected"));
    if (*number > 65535 || (*number == 0 && !allowZero)) {
        return c.fail("range", KERF_TR_NOOP("label number must be between {1} and 65535"),
                      {allowZero ? "0" : "1"});
    }
    target.number = static_cast<int>(*number);
    return true;
}

}  // namespace

}  // namespace kerf::klartext
