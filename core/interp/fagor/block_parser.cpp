#include "core/interp/fagor/block_parser.h"

#include <cmath>
#include <string>

#include "core/base/translate.h"
#include "core/interp/fagor/cycle_syntax.h"
#include "core/program/line_reader.h"

namespace kerf::fagor {

namespace {

constexpr double kPowers[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8};

// Position of a word in the order the manual prescribes: G, coordinates, F, S, T, D, M.
int rank(char letter) {
    switch (letter) {
        case 'F':
            return 2;
        case 'S':
            return 3;
        case 'T':
            return 4;
        case 'D':
            return 5;
        case 'M':
            return 6;
        default:
            return 1;
    }
}

std::string letterText(char c) {
    return std::string(1, c);
}

std::string gText(int n) {
    return "G" + std::to_string(n);
}

}  // namespace

bool BlockParser::fail(size_t offset, const char* code, const char* messageTemplate,
                       std::vector<std::string> args) {
    m_problem = Problem{offset, code, messageTemplate, std::move(args)};
    return false;
}

bool BlockParser::parse(std::string_view text, bool firstLine, ParsedBlock& out) {
    out.kind = ParsedBlock::Kind::Nothing;
    out.skipMarks = 0;
    out.label = -1;
    out.repetition = -1;
    out.endOfFile = false;
    out.outOfOrder = 0;
    out.iso.clear();
    out.highLevel = {};
    // A peripheral ends the file with ESC, EOT, SUB or ETX: nothing after it counts.
    for (size_t i = 0; i < text.size(); ++i) {
        if (isEndOfFileChar(text[i])) {
            text = text.substr(0, i);
            out.endOfFile = true;
            break;
        }
    }
    if (text.size() > program::kMaxBlockCharacters) {
        return fail(program::kMaxBlockCharacters, "syntax",
                    KERF_TR_NOOP("the block is longer than 60000 characters"));
    }
    Scanner s(text);
    const char first = s.peek();
    if (firstLine && first == '%') {
        out.kind = ParsedBlock::Kind::Header;
        return true;
    }
    if (first == ';') {
        out.kind = ParsedBlock::Kind::Comment;
        return true;
    }
    if (first == '\0') {
        if (out.endOfFile) return true;
        return fail(0, "syntax", KERF_TR_NOOP("empty block: a block needs at least a comment"));
    }
    if (!header(s, out)) return false;
    if (s.atEnd()) return true;
    return body(s, out);
}

bool BlockParser::header(Scanner& s, ParsedBlock& out) {
    int marks = 0;
    while (s.peek() == '/') {
        const size_t at = s.position();
        s.advance();
        const char c = s.peekRaw();
        int mark = 0;
        if (c >= '1' && c <= '3') {
            mark = c - '1';
            s.advance();
        }
        if (++marks > 3)
            return fail(at, "syntax", KERF_TR_NOOP("a block has at most 3 skip marks"));
        out.skipMarks = static_cast<uint8_t>(out.skipMarks | (1u << mark));
    }
    if (s.peek() == 'N') {
        const size_t at = s.position();
        s.advance();
        int64_t number = 0;
        uint8_t digits = 0;
        if (s.peek() == 'P') {
            return fail(at, "syntax", KERF_TR_NOOP("a block label cannot be a parameter"));
        }
        if (!s.unsignedInteger(number, digits)) {
            return fail(at, "syntax", KERF_TR_NOOP("label number expected after N"));
        }
        if (digits > 8) {
            return fail(at, "format", KERF_TR_NOOP("a label has at most 8 digits (N0-N99999999)"));
        }
        out.label = number;
    }
    return true;
}

bool BlockParser::body(Scanner& s, ParsedBlock& out) {
    if (s.peek() == '(') return highLevel(s, out);
    out.kind = ParsedBlock::Kind::Iso;
    return isoWords(s, out) && cycleComplete(out.iso);
}

bool BlockParser::highLevel(Scanner& s, ParsedBlock& out) {
    const std::string_view text = s.text();
    const size_t open = s.position();
    int depth = 0;
    bool inString = false;
    size_t close = std::string_view::npos;
    for (size_t i = open; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '"') inString = !inString;
        if (inString) continue;
        if (c == '(') ++depth;
        if (c == ')' && --depth == 0) {
            close = i;
            break;
        }
        if (c == ';' && depth > 0) break;  // a comment starts inside: the ')' is missing
    }
    if (close == std::string_view::npos) {
        return fail(open, "syntax", KERF_TR_NOOP("missing ')' at the end of the high-level block"));
    }
    out.kind = ParsedBlock::Kind::HighLevel;
    out.highLevel = text.substr(open + 1, close - open - 1);
    out.highLevelOffset = open + 1;
    s.setPosition(close + 1);
    return trailer(s, out);
}

bool BlockParser::trailer(Scanner& s, ParsedBlock& out) {
    if (s.peek() == 'N') {
        const size_t at = s.position();
        s.advance();
        int64_t count = 0;
        uint8_t digits = 0;
        if (!s.unsignedInteger(count, digits)) {
            return fail(at, "syntax", KERF_TR_NOOP("repetition count expected after N"));
        }
        if (digits > 4) {
            return fail(at, "format",
                        KERF_TR_NOOP("a repetition count has at most 4 digits (N0-N9999)"));
        }
        out.repetition = static_cast<int32_t>(count);
        out.repetitionOffset = static_cast<uint16_t>(at);
    }
    if (s.atEnd()) return true;
    const std::string_view rest = s.text().substr(s.position());
    return fail(s.position(), "syntax", KERF_TR_NOOP("unexpected '{1}' at the end of the block"),
                {std::string(rest.substr(0, rest.find_first_of(" \t;")))});
}

bool BlockParser::value(Scanner& s, char letter, WordValue& out) {
    out.present = true;
    out.hasValue = false;
    out.parameter = false;
    out.value = 0.0;
    m_literal = ScannedNumber{};
    m_negative = false;
    bool sign = false;
    char c = s.peek();
    if (c == '+' || c == '-') {
        m_negative = c == '-';
        sign = true;
        s.advance();
        c = s.peek();
    }
    if (c == 'P') {
        const size_t at = s.position();
        s.advance();
        if (s.peekRaw() == '(') {
            return fail(at, "syntax", KERF_TR_NOOP("expressions are not allowed in ISO blocks"));
        }
        int64_t number = 0;
        uint8_t digits = 0;
        if (!s.unsignedInteger(number, digits) || digits > 4) {
            return fail(at, "syntax", KERF_TR_NOOP("parameter number expected after P"));
        }
        double v = 0.0;
        if (m_source != nullptr && !m_source->parameter(static_cast<int>(number), v, m_problem)) {
            m_problem.offset = at;
            return false;
        }
        out.parameter = true;
        out.hasValue = true;
        out.value = m_negative ? -v : v;
        return true;
    }
    ScannedNumber number;
    if (s.unsignedNumber(number)) {
        m_literal = number;
        out.hasValue = true;
        out.value = m_negative ? -number.value : number.value;
        return true;
    }
    if (sign) {
        return fail(s.position(), "syntax", KERF_TR_NOOP("number expected after the sign of {1}"),
                    {letterText(letter)});
    }
    return true;
}

bool BlockParser::format(const WordValue& w, char letter, int intDigits, int decDigits, bool sign) {
    if (!w.hasValue) return true;
    if (!sign && w.value < 0.0) {
        return fail(w.offset, "format", KERF_TR_NOOP("{1} cannot be negative"),
                    {letterText(letter)});
    }
    if (w.parameter) {
        if (m_source != nullptr && !(std::fabs(w.value) < kPowers[intDigits])) {
            return fail(w.offset, "format",
                        KERF_TR_NOOP("{1} value {2} is outside the format {3}.{4}"),
                        {letterText(letter), std::to_string(w.value), std::to_string(intDigits),
                         std::to_string(decDigits)});
        }
        return true;
    }
    if (m_literal.intDigits > intDigits || m_literal.decDigits > decDigits) {
        return fail(w.offset, "format", KERF_TR_NOOP("{1} is outside the format {2}.{3}"),
                    {letterText(letter), std::to_string(intDigits), std::to_string(decDigits)});
    }
    return true;
}

bool BlockParser::integer(const WordValue& w, char letter, double lo, double hi) {
    if (w.parameter && m_source == nullptr) return true;  // known at execution
    const double v = w.value;
    if (v != std::floor(v) || v < lo || v > hi) {
        return fail(w.offset, "format", KERF_TR_NOOP("{1} must be a whole number from {2} to {3}"),
                    {letterText(letter), std::to_string(static_cast<long long>(lo)),
                     std::to_string(static_cast<long long>(hi))});
    }
    return true;
}

bool BlockParser::gArguments(Scanner& s, int g, IsoBlock& iso) {
    auto take = [&](char letter, WordValue& into) -> bool {
        const size_t at = s.position();
        s.advance();
        if (into.present) {
            return fail(at, "syntax", KERF_TR_NOOP("{1} is programmed twice"),
                        {letterText(letter)});
        }
        into.offset = static_cast<uint16_t>(at);
        return value(s, letter, into);
    };
    const char c = s.peek();
    switch (g) {
        case 4:
            if (c == 'K') return take('K', iso.gK) && format(iso.gK, 'K', 5, 0, false);
            return true;
        case 20:
        case 21:
        case 22:
            if (c == 'K') return take('K', iso.gK) && integer(iso.gK, 'K', 1, 4);
            return true;
        case 36:
        case 37:
        case 38:
        case 39:
            if (c == 'R') return take('R', iso.cornerR) && format(iso.cornerR, 'R', 5, 5, false);
            return true;
        case 41:
        case 42:
            if (c == 'N') return take('N', iso.gN) && integer(iso.gN, 'N', 0, 50);
            return true;
        case 159:
            if (c == 'N') return take('N', iso.gN) && integer(iso.gN, 'N', 1, 20);
            return true;
        case 93:
            while (s.peek() == 'I' || s.peek() == 'J') {
                const char l = s.peek();
                WordValue& w = l == 'I' ? iso.i1 : iso.j;
                if (!take(l, w) || !format(w, l, 5, 5, true)) return false;
            }
            return true;
        case 51:
            while (s.peek() == 'A' || s.peek() == 'E' || s.peek() == 'B') {
                const char l = s.peek();
                if (l == 'A' && !(take('A', iso.a51) && integer(iso.a51, 'A', 0, 255)))
                    return false;
                if (l == 'E' && !(take('E', iso.e51) && format(iso.e51, 'E', 5, 5, false)))
                    return false;
                if (l == 'B' && !(take('B', iso.b51) && integer(iso.b51, 'B', 0, 180)))
                    return false;
            }
            return true;
        default:
            return true;
    }
}

bool BlockParser::cycleWord(Scanner& s, char letter, size_t offset, CycleWords& cycle) {
    const CycleParameter* p = cycleSyntax(cycle.g)->find(letter);
    if (p == nullptr) {
        return fail(offset, "cycle-parameter", KERF_TR_NOOP("{1} is not a parameter of {2}"),
                    {letterText(letter), gText(cycle.g)});
    }
    WordValue& w = cycle[letter];
    if (w.present) {
        return fail(offset, "syntax", KERF_TR_NOOP("{1} is programmed twice"),
                    {letterText(letter)});
    }
    w.offset = static_cast<uint16_t>(offset);
    if (!value(s, letter, w)) return false;
    if (!w.hasValue) {
        return fail(offset, "syntax", KERF_TR_NOOP("{1} of {2} needs a value"),
                    {letterText(letter), gText(cycle.g)});
    }
    if (!format(w, letter, p->intDigits, p->decDigits, p->sign)) return false;
    if (p->decDigits == 0) {
        const double hi = p->maxValue != 0 ? p->maxValue : kPowers[p->intDigits] - 1.0;
        if (!integer(w, letter, 0.0, hi)) return false;
    }
    if (p->nonZero && known(w) && w.value == 0.0) {
        return fail(offset, "cycle-parameter", KERF_TR_NOOP("{1} of {2} cannot be 0"),
                    {letterText(letter), gText(cycle.g)});
    }
    return true;
}

bool BlockParser::cycleComplete(const IsoBlock& iso) {
    const CycleWords& cycle = iso.cycle;
    if (cycle.g < 0) return true;
    for (const CycleParameter& p : cycleSyntax(cycle.g)->parameters) {
        if (p.required && !cycle.has(p.letter)) {
            return fail(cycle.offset, "cycle-parameter",
                        KERF_TR_NOOP("{1} needs its parameter {2}"),
                        {gText(cycle.g), letterText(p.letter)});
        }
    }
    if ((cycle.g == 86 || cycle.g == 87) && cycle.has('K') && cycle.has('M')) {
        // K (thread repass) and M (variable pitch) exclude each other (spec part 2, G86).
        return fail(cycle['M'].offset, "cycle-parameter",
                    KERF_TR_NOOP("{1}: M (pitch change) cannot be programmed with K (repass)"),
                    {gText(cycle.g)});
    }
    return true;
}

bool BlockParser::isoWords(Scanner& s, ParsedBlock& out) {
    IsoBlock& iso = out.iso;
    bool gPhase = true;
    bool selectors = false;
    int maxRank = 0;
    char previous = '\0';
    while (!s.atEnd()) {
        const size_t at = s.position();
        const char c = s.peekRaw();
        if (isLower(c)) {
            return fail(at, "syntax", KERF_TR_NOOP("'{1}': words are written in upper case"),
                        {letterText(c)});
        }
        if (!isUpper(c))
            return fail(at, "syntax", KERF_TR_NOOP("unexpected '{1}'"), {letterText(c)});
        s.advance();
        const auto offset = static_cast<uint16_t>(at);
        auto single = [&](WordValue& w) -> bool {
            if (w.present) {
                return fail(at, "syntax", KERF_TR_NOOP("{1} is programmed twice"), {letterText(c)});
            }
            w.offset = offset;
            return value(s, c, w);
        };
        if (c == 'G') {
            if (!gPhase) {
                return fail(at, "syntax",
                            KERF_TR_NOOP("G functions are written at the start of the block"));
            }
            if (iso.gCount >= IsoBlock::kMaxG) {
                return fail(at, "syntax", KERF_TR_NOOP("too many G functions in one block"));
            }
            WordValue& g = iso.g[iso.gCount++];
            g.offset = offset;
            if (!value(s, 'G', g) || !format(g, 'G', 3, 0, false) || !integer(g, 'G', 0, 319)) {
                return false;
            }
            const int number = static_cast<int>(g.value);
            if (cycleSyntax(number) != nullptr) {
                if (iso.cycle.g >= 0) {
                    return fail(at, "syntax",
                                KERF_TR_NOOP("{1} and {2}: one canned cycle per block"),
                                {gText(iso.cycle.g), gText(number)});
                }
                iso.cycle.g = static_cast<int16_t>(number);
                iso.cycle.offset = offset;
            }
            if (number == 14 || number == 16 || number == 74) selectors = true;
            if (!gArguments(s, number, iso)) return false;
            previous = 'G';
            continue;
        }
        gPhase = false;
        if (iso.cycle.g >= 0 && c != 'N') {
            if (!cycleWord(s, c, at, iso.cycle)) return false;
            continue;
        }
        const int r = rank(c);
        const bool m19Angle = c == 'S' && previous == 'M' && iso.mCount > 0 &&
                              iso.m[iso.mCount - 1].number.value == 19;
        if (r < maxRank && !m19Angle && out.outOfOrder == 0 && c != 'N') out.outOfOrder = offset;
        if (r > maxRank) maxRank = r;
        previous = c;
        if (auto axis = axisFromLetter(c)) {
            WordValue& w = iso.axes[static_cast<size_t>(axisIndex(*axis))];
            if (iso.has(*axis)) {
                return fail(at, "syntax", KERF_TR_NOOP("{1} is programmed twice"), {letterText(c)});
            }
            w = WordValue{};
            w.offset = offset;
            if (!value(s, c, w) || !format(w, c, 5, 5, true)) return false;
            if (selectors && w.hasValue) {
                return fail(at, "syntax",
                            KERF_TR_NOOP("axis letters after G14, G16 or G74 take no value"));
            }
            iso.axisMask = static_cast<AxisMask>(iso.axisMask | axisBit(*axis));
            iso.axisOrder[iso.axisCount++] = *axis;
            continue;
        }
        switch (c) {
            case 'I': {
                if (iso.i2.present) {
                    return fail(at, "syntax", KERF_TR_NOOP("I is programmed more than twice"));
                }
                WordValue& w = iso.i1.present ? iso.i2 : iso.i1;
                w.offset = offset;
                if (!value(s, c, w) || !format(w, c, 6, 5, true)) return false;
                continue;
            }
            case 'J':
            case 'K':
            case 'R': {
                WordValue& w = c == 'J' ? iso.j : c == 'K' ? iso.k : iso.r;
                if (!single(w) || !format(w, c, 6, 5, true)) return false;
                continue;
            }
            case 'Q':
                if (!single(iso.q) || !format(iso.q, c, 5, 5, true)) return false;
                continue;
            case 'L':
                if (!single(iso.l) || !format(iso.l, c, 5, 5, false)) return false;
                continue;
            case 'F':
                if (!single(iso.f) || !format(iso.f, c, 5, 5, false)) return false;
                continue;
            case 'S':
                if (m19Angle) {
                    MWord& m = iso.m[iso.mCount - 1];
                    m.s.offset = offset;
                    if (!value(s, c, m.s) || !format(m.s, c, 5, 5, true)) return false;
                    continue;
                }
                if (!single(iso.s) || !format(iso.s, c, 5, 5, true)) return false;
                continue;
            case 'T':
                if (!single(iso.t) || !format(iso.t, c, 4, 0, false) ||
                    !integer(iso.t, c, 0, 9999)) {
                    return false;
                }
                continue;
            case 'D':
                if (!single(iso.d) || !format(iso.d, c, 3, 0, false) ||
                    !integer(iso.d, c, 0, 255)) {
                    return false;
                }
                continue;
            case 'M': {
                if (iso.mCount >= IsoBlock::kMaxM) {
                    return fail(at, "syntax", KERF_TR_NOOP("at most 7 M functions in one block"));
                }
                MWord& m = iso.m[iso.mCount++];
                m = MWord{};
                m.number.offset = offset;
                if (!value(s, c, m.number) || !format(m.number, c, 4, 0, false) ||
                    !integer(m.number, c, 0, 9999)) {
                    return false;
                }
                continue;
            }
            case 'N': {
                s.setPosition(at);
                if (!trailer(s, out)) return false;
                return true;
            }
            case 'E':
                return fail(at, "syntax", KERF_TR_NOOP("E belongs to G51"));
            default:
                return fail(at, "syntax", KERF_TR_NOOP("unknown word '{1}'"), {letterText(c)});
        }
    }
    return true;
}

}  // namespace kerf::fagor
